"""The blocks of a sharp vertex's mirror that have each exact eigenvalue of its matrix, matched by value.

The dense route of :func:`~symdecomp.analysis.spectrum.sharp_spectrum` finds the eigenvalues of a boundary, crease,
corner or dart vertex's matrix part by part (:mod:`symdecomp.analysis.triangular_eigen`), each a root of an
irreducible rational factor with its exact multiplicity. Each is named here by the block of the mirror decomposition
(:func:`~symdecomp.analysis.mirror.sector_spectrum`) that has it: the crease block, the sine block ``j`` of a sector
(:meth:`~symdecomp.analysis.eigenvalue.MirrorBlock.name`), its last mode, or at a dart the symmetric (cosine) part, by
matching each block eigenvalue's 40-digit value to the nearest certified root; a block eigenvalue that is no root, or
counts that differ from the multiplicities, give no names (``check --certify`` says where). A value's printed exact form
is its closed form where the factor has degree <= 2, else the shortest of its blocks' closed forms, else the root of
its factor (:func:`exact_text`).
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

import flint
import sympy as sp

from symdecomp.analysis.eigenvalue import Eigenvalue, MirrorBlock
from symdecomp.analysis.mirror import sector_spectrum
from symdecomp.errors import InternalError, NotApplicableError
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.sector import SharpVertex

#: Block names and closed forms of each eigenvalue, by the eigenvalue's key.
Names = dict[Hashable, list[str]]
Forms = dict[Hashable, list[sp.Expr]]

__all__ = ["MAX_EXACT_TEXT", "block_names", "exact_text"]


#: Longest closed form printed for a block's eigenvalue; longer ones are shown as the root of their factor.
MAX_EXACT_TEXT = 90


def exact_text(v: Eigenvalue, candidates: Sequence[sp.Expr]) -> str:
    """The exact form of ``v`` (a root of a rational factor) as text: its closed form where the factor has degree <= 2,
    else the shortest real closed form among ``candidates`` (the blocks' forms of that value) up to
    :data:`MAX_EXACT_TEXT` characters, else ``"root i of <polynomial>"``."""
    if v.factor.degree() <= 2:
        return str(sp.sstr(v.exact))
    short = [c for c in candidates if len(sp.sstr(c)) <= MAX_EXACT_TEXT and not c.has(sp.I)]
    if short:
        return str(sp.sstr(min(short, key=lambda c: len(sp.sstr(c)))))
    x = sp.Symbol("x")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(v.factor.coeffs())], x).as_expr()
    return f"root {v.index} of {sp.sstr(poly)}"


def _centre(v: Eigenvalue) -> complex:
    """The midpoint of ``v``'s certified ball, as a complex float (only to match values that differ by far more)."""
    ball = v.ball
    if not isinstance(ball, flint.acb):
        raise InternalError(f"eigenvalue {v.text}: the dense route gives a certified ball, not {type(ball).__name__}")
    return complex(float(ball.real.mid()), float(ball.imag.mid()))


def block_names(scheme: Scheme, vertex: SharpVertex, values: list[Eigenvalue]) -> tuple[Names, Forms] | None:
    """``({key: [block names]}, {key: [closed forms]})`` from the mirror decomposition, or ``None`` where it does not apply
    or where its eigenvalues, matched by value, do not have the matrix's multiplicities."""
    try:
        spectrum = sector_spectrum(scheme, vertex)
    except NotApplicableError:
        return None
    names: Names = {v.key: [] for v in values}
    forms: Forms = {v.key: [] for v in values}
    counts: dict[Hashable, int] = {v.key: 0 for v in values}
    centres = [(_centre(v), v) for v in values]
    for e in spectrum:
        z = complex(sp.N(e.value, 40))
        centre, best = min(centres, key=lambda cv: abs(cv[0] - z))
        if abs(centre - z) > 1e-12 * max(1.0, abs(z)):
            return None  # a block eigenvalue that is no eigenvalue of the matrix
        block = e.blocks[0]
        if not isinstance(block, MirrorBlock):
            raise InternalError(f"mirror eigenvalue {e.text}: its block is a {type(block).__name__}, not a MirrorBlock")
        name = block.name(vertex)
        if name not in names[best.key]:
            names[best.key].append(name)
        forms[best.key].append(e.value)
        counts[best.key] += 1
    if any(counts[v.key] != v.multiplicity for v in values):
        return None  # the blocks are not this matrix's spectrum (check --certify says where): no names from them
    return names, forms
