"""Figures for Section 5.1: the eigenvalues of ``M_j`` and the invariant ratio (Eq. 34, 39; Fig. 6).

The numbers behind the figures come from :mod:`symdecomp.analysis.tangent`:

>>> from symdecomp.schemes.scheme import catmull_clark
>>> invariant_ratios(catmull_clark(), [4])
[(1+1j)]
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
import sympy as sp

from symdecomp.algebra.circulant import fourier_matrix
from symdecomp.analysis.evolution import one_ring, subdivide_ring
from symdecomp.analysis.frequency import per_frequency_matrix_at
from symdecomp.analysis.tangent import invariant_ratio, invariant_ratio_at, invariant_ratio_limit, tangent_eigenvalues
from symdecomp.errors import NotApplicableError
from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_valence

__all__ = [
    "tangent_eigenvalues_figure",
    "invariant_ring_figure",
    "invariant_ratio_sweep_figure",
    "invariant_ratios",
    "component_rings",
    "component_decay",
    "component_decay_figure",
]


def _closed_form_curves(scheme: Scheme, samples: int = 401):
    """The two closed-form eigenvalues of Eq. 34 sampled over ``x = j/n`` in ``[0, 1]``."""
    ev = tangent_eigenvalues(scheme)
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {list(scheme.parameters)}; substitute them first")
    x = np.linspace(0.0, 1.0, samples)
    curves = []
    for expr in (ev.dominant, ev.subdominant):
        f = sp.lambdify((cos_jtheta, sin_jtheta), expr, modules="numpy")
        values = np.asarray(f(np.cos(np.pi * x), np.sin(np.pi * x)), dtype=complex) * np.ones_like(x)
        curves.append(values)
    return x, curves


def _matrix_eigenvalues(scheme: Scheme, n: int, j: int) -> np.ndarray:
    """Eigenvalues of the exact ``M_j`` at ``(n, j)``, computed numerically from the matrix itself."""
    matrix = np.array(per_frequency_matrix_at(scheme, n, j).evalf(30), dtype=complex)
    return np.linalg.eigvals(matrix)


def _real_or_modulus(values: np.ndarray) -> tuple[np.ndarray, bool]:
    values = np.asarray(values, dtype=complex)
    if np.max(np.abs(values.imag), initial=0.0) > 1e-12:
        return np.abs(values), True
    return values.real, False


def tangent_eigenvalues_figure(scheme: Scheme, valences: Iterable[int] = (3, 4, 5, 6, 8, 12), *, sweep: Iterable[int] = range(3, 25)):
    """The eigenvalues of ``M_j`` over ``j`` and ``n`` (Eq. 33-34, Proposition 5.1).

    Left: the two closed-form eigenvalues of Eq. 34 as curves in ``j/n`` (``c = cos(j pi/n)``),
    and, as markers, the eigenvalues of the exact matrices ``M_j`` for each valence in
    ``valences`` and ``j = 1..n-1``, computed from the matrices without the closed form.
    Right: for each ``n`` in ``sweep``, all eigenvalues of ``M_1..M_{n-1}`` (grey), the largest,
    ``lambda_1`` of ``M_1`` (Proposition 5.1), and ``lambda_1^2`` (the rate the elliptic and
    hyperbolic components must match, Sections 5.2-5.3).
    """
    valences = [check_valence(v) for v in valences]
    sweep = [check_valence(v) for v in sweep]
    fig = new_figure(12, 4.6)
    left, right = fig.subplots(1, 2)

    x, (dominant, subdominant) = _closed_form_curves(scheme)
    dom, modulus = _real_or_modulus(dominant)
    sub, modulus2 = _real_or_modulus(subdominant)
    modulus = modulus or modulus2
    left.plot(x, dom, color="black", lw=1.5, label=r"Eq. 34, $+$ root")
    left.plot(x, sub, color="black", lw=1.0, ls="--", label=r"Eq. 34, $-$ root")
    markers = "osD^v<>ph*"
    for k, n in enumerate(valences):
        js = np.arange(1, n)
        vals = np.array([_matrix_eigenvalues(scheme, n, int(j)) for j in js])
        shown, _ = _real_or_modulus(vals)
        left.scatter(np.repeat(js / n, 2), shown.ravel(), marker=markers[k % len(markers)], s=28, zorder=3,
                     label=f"$M_j$, n = {n}", facecolors="none", edgecolors=f"C{k}")
    label_axes(left, r"$j/n$   ($c = \cos(j\pi/n)$)", "|eigenvalue|" if modulus else "eigenvalue",
               r"Eigenvalues of $M_j$: closed form (lines) and exact matrices (markers)", ncol=2)

    lam1 = []
    for n in sweep:
        vals = np.array([_matrix_eigenvalues(scheme, n, j) for j in range(1, n)]).ravel()
        shown, _ = _real_or_modulus(vals)
        right.scatter(np.full(shown.shape, n), shown, color="0.6", s=10)
        lam1.append(max(np.abs(_matrix_eigenvalues(scheme, n, 1))))
    right.scatter([], [], color="0.6", s=10, label=r"eigenvalues of $M_1, \dots, M_{n-1}$")
    right.plot(sweep, lam1, color="C3", marker="o", ms=4, label=r"$\lambda_1$ (largest, of $M_1$)")
    right.plot(sweep, np.square(lam1), color="C0", ls="--", label=r"$\lambda_1^2$")
    label_axes(right, "valence n", "|eigenvalue|", r"All eigenvalues of $M_j$, $j = 1..n-1$, by valence")
    fig.suptitle(f"{scheme.name}: the per-frequency matrices $M_j$ (Eq. 33)")
    return fig


def invariant_ratios(scheme: Scheme, valences: Iterable[int], j: int = 1, *, exact: bool = True) -> list[complex]:
    """``B^j/A^j`` on the dominant eigenvector (Eq. 39) for each valence, as Python complex numbers.

    With ``exact=True`` each value is :func:`symdecomp.analysis.tangent.invariant_ratio_at` (exact,
    simplified; slow beyond ``n ~ 20``) evaluated to double precision; with ``exact=False`` the
    closed form :func:`symdecomp.analysis.tangent.invariant_ratio` is evaluated at 20 digits directly
    (the same expression, without the exact simplification; for long sweeps).
    """
    if exact:
        return [complex(sp.N(invariant_ratio_at(scheme, check_valence(n), j), 20)) for n in valences]
    closed_form = invariant_ratio(scheme)
    values = []
    for n in valences:
        n = check_valence(n)
        angle = sp.pi * sp.Rational(j, n)
        point = {OMEGA: sp.exp(2 * sp.I * angle), cos_jtheta: sp.cos(angle), sin_jtheta: sp.sin(angle)}
        values.append(complex(sp.N(closed_form.subs(point), 20)))
    return values


def _draw_invariant_ring(ax, n: int, ratio: complex) -> None:
    """The 1-ring with ``A^1 = v_1`` and ``B^1 = ratio * v_1``: its quads, O, and the two n-gons."""
    w = np.exp(2j * np.pi * np.arange(n) / n)
    a = w
    b = ratio * w
    for i in range(n):
        ax.plot([0, a[i].real], [0, a[i].imag], color="0.5", lw=0.8)
        quad = np.array([a[i], b[i], a[(i + 1) % n]])
        ax.plot(quad.real, quad.imag, color="0.5", lw=0.8)
    closed_a = np.append(a, a[0])
    closed_b = np.append(b, b[0])
    ax.plot(closed_a.real, closed_a.imag, color="C0", ls="--", lw=1.2, label=r"$A^1$ (the $a_i$)")
    ax.plot(closed_b.real, closed_b.imag, color="C3", ls=":", lw=1.5, label=r"$B^1$ (the $b_i$)")
    ax.scatter(a.real, a.imag, color="C0", s=25, zorder=3)
    ax.scatter(b.real, b.imag, color="C3", marker="s", s=25, zorder=3)
    ax.scatter([0], [0], color="black", s=30, zorder=3)
    ax.annotate("O", (0, 0), textcoords="offset points", xytext=(4, 4))
    ax.annotate(r"$a_0$", (a[0].real, a[0].imag), textcoords="offset points", xytext=(4, -10))
    ax.annotate(r"$b_0$", (b[0].real, b[0].imag), textcoords="offset points", xytext=(4, 2))
    ax.set_aspect("equal")
    ax.margins(0.08)
    ax.set_xlabel("x (tangent plane)")
    ax.set_ylabel("y (tangent plane)")


def invariant_ring_figure(scheme: Scheme, valences: Iterable[int] = (4, 12), j: int = 1):
    """Fig. 6: the 1-ring invariant under the scheme, ``B^1 = r A^1`` with ``r`` from Eq. 39.

    ``A^1`` is the regular convex n-gon ``v_1`` (the ``a_i``), ``B^1 = r v_1`` (the ``b_i``);
    the quads ``(O, a_i, b_i, a_{i+1})`` are drawn in grey. For ``n = 4`` the ring is the regular
    grid (``r = 1 + i``).
    """
    valences = [check_valence(v) for v in valences]
    ratios = invariant_ratios(scheme, valences, j)
    fig = new_figure(5.2 * len(valences), 5.2)
    axes = np.atleast_1d(fig.subplots(1, len(valences)))
    for ax, n, r in zip(axes, valences, ratios):
        _draw_invariant_ring(ax, n, r)
        ax.set_title(f"n = {n}:  $B^{j}/A^{j}$ = {abs(r):.4f} at {np.degrees(np.angle(r)):.2f}°")
        ax.legend(fontsize=8, loc="lower left")
    fig.suptitle(f"{scheme.name}: the invariant ratio between $A^{j}$ and $B^{j}$ (Eq. 39, Fig. 6)")
    return fig


def invariant_ratio_sweep_figure(scheme: Scheme, valences: Iterable[int] = range(3, 33), j: int = 1):
    """``|B^j/A^j|`` and ``arg(B^j/A^j)`` (Eq. 39) over a sweep of ``n``, with the limit ``n -> oo``.

    The values are the closed form of Eq. 39 evaluated at each ``n`` (``invariant_ratios(...,
    exact=False)``); the limit is :func:`symdecomp.analysis.tangent.invariant_ratio_limit` (``sympy.limit``).
    """
    valences = [check_valence(v) for v in valences]
    ratios = np.array(invariant_ratios(scheme, valences, j, exact=False))
    limit = invariant_ratio_limit(scheme, j)
    fig = new_figure(12, 4.4)
    left, right = fig.subplots(1, 2)
    left.plot(valences, np.abs(ratios), marker="o", ms=4, ls="none", label=r"$|B^%d/A^%d|$ (Eq. 39)" % (j, j))
    left.axhline(float(abs(sp.N(limit))), color="C3", ls="--", label=f"limit $n\\to\\infty$: ${sp.latex(limit)}$")
    left.set_xlabel("valence n")
    left.set_ylabel(r"$|B^%d| / |A^%d|$ (scale ratio)" % (j, j))
    left.set_title("Scale between the two invariant n-gons")
    left.legend()
    left.grid(alpha=0.3)
    right.plot(valences, np.degrees(np.angle(ratios)), marker="o", ms=4, ls="none", label=r"$\arg(B^%d/A^%d)$" % (j, j))
    right.plot(valences, [180.0 * j / n for n in valences], color="0.4", ls=":", label=r"$180° \cdot j/n$ (the angle of $\omega_{2n}^j$)")
    right.set_xlabel("valence n")
    right.set_ylabel("rotation (degrees)")
    right.set_title(r"Rotation from $A^%d$ to $B^%d$" % (j, j))
    right.legend()
    right.grid(alpha=0.3)
    fig.suptitle(f"{scheme.name}: the invariant ratio of Eq. 39 over the valence")
    return fig


def component_rings(n: int) -> list[np.ndarray]:
    """For ``j = 0..2n-1``, the planar 1-ring whose 2n-gon is the regular ``v_j`` (Eq. 11-12), ``O = 0``.

    Row ``j`` of the Fourier matrix ``F_{2n}`` split as in Eq. 12: ``a_i = v_j[2i]``,
    ``b_i = v_j[2i+1]``. Each ring is a ``(2n+1, 1)`` complex array (:mod:`symdecomp.analysis.evolution`).
    """
    n = check_valence(n)
    F = np.array(fourier_matrix(2 * n).evalf(20), dtype=complex)
    return [one_ring([0j], F[j, 0::2], F[j, 1::2]) for j in range(2 * n)]


def component_decay(scheme: Scheme, n: int, steps: int) -> np.ndarray:
    """``|P_k - O_k| / (|P_0 - O_0| lambda_1^k)`` for each 2n-gon component ``j`` (rows) and step ``k``.

    ``P_k`` is the 1-ring of :func:`component_rings` after ``k`` exact subdivision steps and
    ``lambda_1`` the largest eigenvalue of ``M_1`` (Eq. 34). A component that the scheme filters
    out relative to the tangent plane goes to 0; one that shrinks at the rate ``lambda_1`` stays
    bounded away from 0.
    """
    lam1 = max(abs(complex(sp.N(v, 20))) for v in tangent_eigenvalues(scheme).at(check_valence(n), 1))
    table = []
    for ring in component_rings(n):
        history = subdivide_ring(scheme, ring, steps)
        size = np.array([np.linalg.norm(r - r[0]) for r in history])
        table.append(size / size[0] / lam1 ** np.arange(steps + 1))
    return np.array(table)


def component_decay_figure(scheme: Scheme, n: int, steps: int = 12):
    """Each 2n-gon component's size relative to ``lambda_1^k`` over subdivision steps (Prop. 5.1, Remark 5.1)."""
    n = check_valence(n)
    table = component_decay(scheme, n, steps)
    fig = new_figure(8.5, 5)
    ax = fig.add_subplot()
    tangent = {1, n - 1, n + 1, 2 * n - 1}
    k = np.arange(steps + 1)
    for j, row in enumerate(table):
        style = {"lw": 2.0, "marker": "o", "ms": 3} if j in tangent else {"lw": 0.9, "ls": "--"}
        ax.plot(k, row, label=f"j = {j}", **style)
    ax.set_yscale("log")
    ax.set_xlabel("subdivision step k")
    ax.set_ylabel(r"$|P_k - O_k| \,/\, (|P_0 - O_0|\, \lambda_1^k)$")
    ax.set_title(f"{scheme.name}, n = {n}: the 1-ring of each 2n-gon component $v_j$, relative to $\\lambda_1^k$\n"
                 f"(thick: j = 1, n-1, n+1, 2n-1)", fontsize=10)
    ax.legend(fontsize=7, ncol=2, loc="lower left")
    ax.grid(alpha=0.3, which="both")
    return fig
