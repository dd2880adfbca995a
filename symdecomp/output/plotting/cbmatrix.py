"""Figures for Section 6: which eigenvalues constant blocks move (Proposition 6.3).

The numbers are computed from exact matrices (converted to floating point only to find
eigenvalues for the picture):

>>> import sympy as sp
>>> numeric_eigenvalues(sp.Matrix([[2, 1], [0, sp.Rational(1, 2)]]))
array([2. +0.j, 0.5+0.j])
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import numpy as np
import sympy as sp

from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.errors import NotApplicableError
from symdecomp.output.plotting._mpl import new_figure
from symdecomp.schemes.scheme import Scheme, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = ["numeric_eigenvalues", "unmatched_eigenvalues", "eigenvalue_shift_figure", "vertex_weight_sweep_figure"]


def numeric_eigenvalues(matrix) -> np.ndarray:
    """The eigenvalues of an exact (sympy) matrix, in double precision, largest modulus first."""
    values = np.linalg.eigvals(np.array(sp.Matrix(matrix).evalf(30), dtype=complex))
    # Round-off leaves imaginary parts of order 1e-16 on real eigenvalues; drop them.
    values = np.where(np.abs(values.imag) < 1e-9 * np.maximum(1.0, np.abs(values)), values.real + 0j, values)
    order = np.lexsort((-values.imag, -values.real, -np.abs(values)))
    return values[order]


def unmatched_eigenvalues(before: np.ndarray, after: np.ndarray, *, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """The eigenvalues of ``after`` not found among ``before`` (each match used once), and vice versa."""
    left = list(np.asarray(before, dtype=complex))
    extra = []
    for value in np.asarray(after, dtype=complex):
        distances = [abs(value - x) for x in left]
        k = int(np.argmin(distances)) if left else -1
        if left and distances[k] <= tol * max(1.0, abs(value)):
            left.pop(k)
        else:
            extra.append(value)
    return np.array(extra, dtype=complex), np.array(left, dtype=complex)


def eigenvalue_shift_figure(before, after, predicted, *, title: str, labels: Sequence[str] = ("B", "C = B + A", r"$E_0 + mT$")):
    """Eigenvalues of ``before`` and ``after`` in the complex plane, and the ``predicted`` moved ones.

    Proposition 6.3: adding constant blocks to a CB-matrix changes only the eigenvalues of the
    block-eigenvalue matrix ``E_0``; ``predicted`` are the eigenvalues the proposition gives for them.
    """
    ev_before = numeric_eigenvalues(before)
    ev_after = numeric_eigenvalues(after)
    ev_pred = numeric_eigenvalues(predicted)
    moved_to, moved_from = unmatched_eigenvalues(ev_before, ev_after)
    fig = new_figure(11, 4.8)
    plane, bars = fig.subplots(1, 2, width_ratios=(1.2, 1))
    if np.all(ev_after.imag == 0) and np.all(ev_before.imag == 0) and np.all(ev_pred.imag == 0):
        # All real: three rows on the real line, the unchanged ones joined.
        rows = {labels[0]: (2, ev_before, "o", "C0"), labels[1]: (1, ev_after, "x", "C3"), labels[2] + " (predicted)": (0, ev_pred, "s", "C2")}
        for label, (y, ev, marker, color) in rows.items():
            kwargs = {"facecolors": "none", "edgecolors": color} if marker != "x" else {"color": color}
            plane.scatter(ev.real, np.full(ev.shape, y), marker=marker, s=70, label=label, **kwargs)
        for value in ev_after:
            if not np.any(np.isclose(value, moved_to)):
                plane.plot([value.real, value.real], [1, 2], color="0.75", lw=0.8, zorder=0)
        for value in moved_to:
            plane.plot([value.real, value.real], [0, 1], color="C2", lw=0.8, ls="--", zorder=0)
        plane.set_yticks([0, 1, 2], [labels[2], labels[1], labels[0]])
        plane.set_ylim(-0.6, 2.8)
        plane.set_xlabel("eigenvalue (all real)")
        plane.set_ylabel("matrix")
    else:
        plane.scatter(ev_before.real, ev_before.imag, s=90, facecolors="none", edgecolors="C0", label=f"eigenvalues of {labels[0]}")
        plane.scatter(ev_after.real, ev_after.imag, s=30, marker="x", color="C3", label=f"eigenvalues of {labels[1]}")
        plane.scatter(ev_pred.real, ev_pred.imag, s=160, marker="s", facecolors="none", edgecolors="C2", lw=1.5,
                      label=f"eigenvalues of {labels[2]} (predicted)")
        plane.axhline(0, color="0.8", lw=0.8)
        plane.axvline(0, color="0.8", lw=0.8)
        plane.set_xlabel("Re(eigenvalue)")
        plane.set_ylabel("Im(eigenvalue)")
    plane.set_title(f"{len(moved_to)} of {len(ev_after)} eigenvalues moved")
    plane.legend(fontsize=8)
    plane.grid(alpha=0.3)

    width = 0.38
    index = np.arange(len(ev_after))
    bars.bar(index - width / 2, np.abs(ev_before), width, color="C0", label=f"|eigenvalue| of {labels[0]}")
    bars.bar(index + width / 2, np.abs(ev_after), width, color="C3", label=f"|eigenvalue| of {labels[1]}")
    bars.set_xlabel("eigenvalue index (by decreasing modulus)")
    bars.set_ylabel("|eigenvalue|")
    bars.set_title("Moduli, sorted: all but the moved ones pair up")
    bars.legend(fontsize=8)
    fig.suptitle(title)
    return fig


def vertex_weight_sweep_figure(scheme: Scheme, n: int, parameter: sp.Symbol, values: Iterable, *, fixed: Mapping | None = None, standard=None):
    """Every eigenvalue of the subdivision matrix while one vertex-rule weight is swept (Section 6).

    ``scheme`` has the vertex-rule weights free (``catmull_clark(alpha, beta)``); ``parameter``
    is swept over ``values`` with the others set by ``fixed``. Dots: the eigenvalues of the exact
    ``(2n+1) x (2n+1)`` matrix (:func:`symdecomp.schemes.scheme.subdivision_matrix`) at each value; the
    ones the weight does not move form horizontal rows. Curves: the two eigenvalues of the
    recursion matrix of Eq. 43 other than 1, from their closed forms
    (:func:`symdecomp.analysis.spectrum.recursion_eigenvalues`): Proposition 6.3 says these are the
    only ones that move. Real parts are shown; eigenvalues of a complex pair are marked.
    """
    n = check_valence(n)
    fixed = {k: sp.sympify(v, strict=True) for k, v in (fixed or {}).items()}
    values = [sp.sympify(t, strict=True) for t in values]
    missing = set(scheme.parameters) - set(fixed) - {parameter}
    if missing:
        raise NotApplicableError(f"give values for the scheme's other free parameters {sorted(map(str, missing))} in fixed=")
    S = subdivision_matrix(scheme, n)
    moving = [e.subs({N: n, **fixed}) for e in recursion_eigenvalues(scheme)[1:]]
    fig = new_figure(11, 5.4)
    ax = fig.add_subplot()
    curves = []
    for t in values:
        ev = numeric_eigenvalues(S.subs({parameter: t, **fixed}))
        real = ev.imag == 0
        ax.scatter(np.full(real.sum(), float(t)), ev.real[real], s=9, color="0.45", zorder=2)
        if (~real).any():
            ax.scatter(np.full((~real).sum(), float(t)), ev.real[~real], s=16, marker="^", color="0.45", zorder=2)
        curves.append([complex(sp.N(e.subs(parameter, t), 20)) for e in moving])
    curves = np.array(curves)
    ts = [float(t) for t in values]
    for k in range(curves.shape[1]):
        ax.plot(ts, curves[:, k].real, color=f"C{k + 1}", lw=1.5, label=f"closed form: eigenvalue {k + 2} of the Eq. 43 matrix")
    ax.scatter([], [], s=9, color="0.45", label=f"eigenvalues of the {2 * n + 1}x{2 * n + 1} subdivision matrix")
    ax.scatter([], [], s=16, marker="^", color="0.45", label="(complex pair: real part)")
    if standard is not None:
        ax.axvline(float(standard), color="0.3", ls=":", label=f"standard {parameter} = {standard}")
    ax.set_xlabel(f"vertex-rule weight {parameter}" + (f"   ({', '.join(f'{k} = {v}' for k, v in fixed.items())})" if fixed else ""))
    ax.set_ylabel("Re(eigenvalue)")
    ax.set_title(f"{scheme.name}, n = {n}: the eigenvalues that the vertex weight moves")
    fig.legend(fontsize=8, loc="outside lower center", ncol=3)
    ax.grid(alpha=0.3)
    return fig
