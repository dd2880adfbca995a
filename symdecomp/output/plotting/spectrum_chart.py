"""The figure of ``symdecomp spectrum --plot``: the eigenvalues by the frequency (or block) they come from.

At an interior vertex each distinct eigenvalue is drawn at every frequency ``k`` whose block (``M_k``
of Eq. 34, the 3x3 matrix of Eq. 43 for ``k = 0``; ``E(omega^k)`` of a K-ring matrix) contributes it,
as in the paper's figures of the eigenvalues of ``M_j``; at a boundary, crease, corner or dart vertex
at every block of the mirror decomposition it comes from. Real eigenvalues are drawn by value, complex
ones by modulus (hollow markers). The numbers are the results the command prints
(:class:`~symdecomp.analysis.spectrum.Spectrum`, :class:`~symdecomp.analysis.spectrum.RingSpectrum`,
:class:`~symdecomp.analysis.spectrum.SharpSpectrum`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from symdecomp.output.plotting._mpl import new_figure

__all__ = ["as_complex", "spectrum_figure", "sharp_spectrum_figure"]


def as_complex(value: Any) -> complex:
    """An eigenvalue as a Python complex: an Arb ball by its midpoint, an mpmath or sympy number as it is.

    >>> import flint
    >>> as_complex(flint.acb(0.5, -0.25)), as_complex(flint.arb(3))
    ((0.5-0.25j), (3+0j))
    """
    import flint

    if isinstance(value, flint.acb):
        return complex(float(value.real.mid()), float(value.imag.mid()))
    if isinstance(value, flint.arb):
        return complex(float(value.mid()))
    return complex(value)


def _scatter(ax, points: Sequence[tuple[float, complex, int]]) -> None:
    """Points ``(x, eigenvalue, multiplicity)``: filled by value if real, hollow by modulus if not; size by multiplicity."""
    real = [(x, z.real, m) for x, z, m in points if abs(z.imag) <= 1e-12 * max(1.0, abs(z))]
    other = [(x, abs(z), m) for x, z, m in points if abs(z.imag) > 1e-12 * max(1.0, abs(z))]
    if real:
        ax.scatter([p[0] for p in real], [p[1] for p in real], s=[14 + 10 * p[2] for p in real], color="C0", label="real: value")
    if other:
        ax.scatter([p[0] for p in other], [p[1] for p in other], s=[14 + 10 * p[2] for p in other], facecolors="none",
                   edgecolors="C3", label="complex: modulus")
    ax.axhline(1.0, color="0.6", lw=0.6, ls=":")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)


def spectrum_figure(spectrum, *, title: str | None = None, xlabel: str | None = None):
    """The eigenvalues of ``spectrum`` (a ``Spectrum`` or a ``RingSpectrum``) over the frequencies ``k = 0..n-1``.

    ``title`` and ``xlabel`` replace the ones of a vertex's 1-ring or K-ring (a scheme of the zoo says its own)."""
    entries = spectrum.eigenvalues
    points = [(k, as_complex(e.value), e.multiplicity)
              for e in entries for k in e.frequencies]
    fig = new_figure(7.5, 4.5)
    ax = fig.subplots()
    _scatter(ax, points)
    n = spectrum.n
    step = max(1, n // 16)
    ax.set_xticks(range(0, n, step))
    ax.set_xlabel(xlabel or "frequency k (the block M_k; k = 0: Eq. 43)")
    ax.set_ylabel("eigenvalue (marker size: multiplicity)")
    rings = getattr(spectrum, "rings", 1)
    where = f", {rings}-ring" if rings != 1 else ""
    ax.set_title(title or f"{spectrum.scheme}, valence n = {n}{where}: {len(entries)} distinct eigenvalues by frequency", fontsize=10)
    return fig


def sharp_spectrum_figure(levels, vertex: str):
    """One panel per level of a sharp vertex's spectrum (``SharpSpectrum`` objects): the eigenvalues by block."""
    fig = new_figure(7.5, 3.6 * len(levels) + 0.6)
    for ax, s in zip(fig.subplots(len(levels), 1, squeeze=False)[:, 0], levels):
        blocks = list(dict.fromkeys(b for e in s.entries for b in e.blocks))
        points = [(blocks.index(b), as_complex(e.ball), e.multiplicity) for e in s.entries for b in e.blocks]
        _scatter(ax, points)
        ax.set_xticks(range(len(blocks)), blocks, fontsize=7, rotation=30, ha="right")
        ax.set_ylabel("eigenvalue")
        level = "" if len(levels) == 1 else f", level {s.level} (sharpness {s.sharpness})"
        ax.set_title(f"{s.scheme}, {vertex}{level}: {s.size} eigenvalues, {len(s.entries)} distinct, by block", fontsize=10)
    return fig
