"""The exact spectrum of a boundary, crease, corner or dart vertex, each eigenvalue with the block it comes from.

The eigenvalues are those of the one-step matrix ``S`` of the vertex's 1-ring built by exact refinement
(:func:`~symdecomp.schemes.sector.exact_sharp_matrix`, or over ``Q(cos(pi/k))`` for rules with ``cos(theta_k)``
weights: :mod:`symdecomp.analysis.triangular_eigen`, :attr:`SharpSpectrum.field`), found part by part
(:mod:`symdecomp.analysis.triangular_eigen`: the crease block and each sector), each a root of an irreducible
rational factor, with its exact multiplicity. Each is then named by the block of the mirror decomposition
(:func:`~symdecomp.analysis.mirror.sector_spectrum`) that has it: the crease block, the sine block ``j`` of a
sector of ``k`` faces (``theta = pi j/k``), its last mode (``j = k`` on quads: ``b_i = (-1)^i``), or at a dart
the symmetric (cosine) part. The names are matched by value (a block eigenvalue's 40-digit value to the
nearest certified root); that the blocks *are* the spectrum, with multiplicities, is what
``check --certify`` proves (:mod:`symdecomp.verify.certify`). Semi-sharp edges (finite sharpness) have
no mirror decomposition: their eigenvalues are named by part only, at each refinement level whose matrix
differs from the level before, until the sharpness has decayed to 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.analysis.eigenvalue import Eigenvalue, MirrorBlock
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.triangular_eigen import merge
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_digits

__all__ = ["SharpSpectrum", "sharp_spectrum", "sharp_levels", "MAX_EXACT_TEXT", "STRUCTURAL_FROM"]

#: Longest closed form printed for a block's eigenvalue; longer ones are shown as the root of their factor.
MAX_EXACT_TEXT = 90


@dataclass(frozen=True)
class SharpSpectrum:
    """The spectrum of one sharp vertex at one refinement level."""

    scheme: str
    #: The vertex (a :class:`~symdecomp.schemes.sector.SharpVertex`).
    vertex: object
    level: int
    #: The sharpness at this level (``math.inf``, a ``Fraction``).
    sharpness: object
    size: int
    #: Whether the names come from the mirror decomposition (else from the parts of the matrix).
    decomposed: bool
    #: The distinct eigenvalues (a certified ball each, its decimal text, its multiplicity), each with its ``blocks`` as
    #: text: the blocks of the mirror decomposition that have it (``"crease"``, ``"sine j=1 (theta = pi/5)"``, ...), or
    #: the parts of the matrix (``"crease"``, ``"sector 1"``, ``"whole"``) when there is no decomposition; and its
    #: ``exact`` form as text: a closed form, or ``"root i of <irreducible polynomial>"``.
    entries: tuple[Eigenvalue, ...]
    #: The field of the matrix's entries: ``"Q"``, or ``"Q(cos(pi/k))"`` for rules with ``cos(theta_k)`` weights.
    field: str = "Q"
    #: ``"dense"`` (the matrix's characteristic polynomial) or ``"structural"`` (the mirror decomposition's blocks).
    route: str = "dense"

    def as_json(self) -> dict:
        s = self.sharpness
        return {"level": self.level, "sharpness": "inf" if s == math.inf else str(s), "size": self.size, "field": self.field,
                "decomposed": self.decomposed, "route": self.route, "eigenvalues": [_entry_json(e) for e in self.entries]}


def _entry_json(e: Eigenvalue) -> dict:
    return {"value": e.text, "multiplicity": e.multiplicity, "blocks": list(e.blocks), "exact": e.exact}


def _block_name(e: MirrorBlock, vertex) -> str:
    if e.block in ("crease", "cosine"):
        return "crease" if e.block == "crease" else "cosine (symmetric part)"
    k = vertex.sectors[e.sector]
    where = f", sector {e.sector + 1}" if len(vertex.sectors) > 1 else ""
    if e.block == "face":
        return f"last mode j={e.j} (b_i = (-1)^i){where}"
    return f"sine j={e.j} (theta = {pi_multiple(Fraction(e.j * (2 if vertex.closed and len(vertex.sectors) == 1 else 1), k))}){where}"


def pi_multiple(q: Fraction) -> str:
    """``q pi`` as sympy prints it (``pi/5``, ``2*pi/5``, ``pi``), without building the expression (20,000 names at a
    vertex of 10,000 faces)."""
    head = "pi" if q.numerator == 1 else f"{q.numerator}*pi"
    return head if q.denominator == 1 else f"{head}/{q.denominator}"


def _exact_text(v: Eigenvalue, candidates: list) -> str:
    if v.factor.degree() <= 2:
        return sp.sstr(v.exact)
    short = [c for c in candidates if len(sp.sstr(c)) <= MAX_EXACT_TEXT and not c.has(sp.I)]
    if short:
        return sp.sstr(min(short, key=lambda c: len(sp.sstr(c))))
    x = sp.Symbol("x")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(v.factor.coeffs())], x).as_expr()
    return f"root {v.index} of {sp.sstr(poly)}"


def _names(scheme, vertex, values: list[Eigenvalue]) -> tuple[dict, dict] | None:
    """``({key: [block names]}, {key: [closed forms]})`` from the mirror decomposition, or ``None`` where it does not apply
    or where its eigenvalues, matched by value, do not have the matrix's multiplicities."""
    from symdecomp.analysis.mirror import sector_spectrum

    try:
        spectrum = sector_spectrum(scheme, vertex)
    except NotApplicableError:
        return None
    names: dict = {v.key: [] for v in values}
    forms: dict = {v.key: [] for v in values}
    counts: dict = {v.key: 0 for v in values}
    for e in spectrum:
        z = complex(sp.N(e.value, 40))
        best = min(values, key=lambda v: abs(complex(float(v.ball.real.mid()), float(v.ball.imag.mid())) - z))
        if abs(complex(float(best.ball.real.mid()), float(best.ball.imag.mid())) - z) > 1e-12 * max(1.0, abs(z)):
            return None  # a block eigenvalue that is no eigenvalue of the matrix
        name = _block_name(e.blocks[0], vertex)
        if name not in names[best.key]:
            names[best.key].append(name)
        forms[best.key].append(e.value)
        counts[best.key] += 1
    if any(counts[v.key] != v.multiplicity for v in values):
        return None  # the blocks are not this matrix's spectrum (check --certify says where): no names from them
    return names, forms


#: From this many faces on, ``route="auto"`` takes the structural route (where it applies).
STRUCTURAL_FROM = 9
_ROUTES = ("auto", "dense", "structural")


def sharp_spectrum(scheme: Scheme, vertex, *, level: int = 0, digits: int = 20, route: str = "auto") -> SharpSpectrum:
    """The exact spectrum of ``vertex`` at refinement ``level``, each eigenvalue named by its block (module docstring).

    ``route``: ``"dense"`` (the matrix built by refinement, its characteristic polynomial factored), ``"structural"``
    (the mirror decomposition's blocks, O(k): :mod:`symdecomp.analysis.sharp_structural`; refused where it does not
    apply), or ``"auto"``: structural from :data:`STRUCTURAL_FROM` faces on where it applies, else dense.
    """
    from symdecomp.analysis.triangular_eigen import sharp_values

    scheme, digits = check_scheme(scheme), check_digits(digits)
    if route not in _ROUTES:
        raise InvalidInputError(f"route: expected one of {', '.join(_ROUTES)}, got {route!r:.40}")
    here = vertex.at_level(level)
    if route == "structural" or (route == "auto" and here.faces >= STRUCTURAL_FROM and here.sharpness == math.inf):
        try:
            return _structural_spectrum(scheme, vertex, level, digits)
        except NotApplicableError:
            if route == "structural":
                raise
    S, _, values = sharp_values(scheme, vertex, level=level, prec=max(256, 4 * digits + 64))
    values = merge(values)
    named = _names(scheme, here, values) if here.sharpness == math.inf else None
    entries = []
    with flint.ctx.workprec(4 * digits + 64):
        for v in values:
            blocks = tuple(named[0][v.key]) if named else tuple(v.part.split(", "))
            text = acb_text(v.ball, digits)
            entries.append(replace(v, text=text, blocks=blocks, exact=_exact_text(v, named[1][v.key] if named else [])))
    return SharpSpectrum(scheme.name, vertex, level, here.sharpness, S.nrows(), named is not None, tuple(entries),
                         field_name(S))


def _structural_spectrum(scheme: Scheme, vertex, level: int, digits: int) -> SharpSpectrum:
    """:func:`sharp_spectrum` from the blocks of the mirror decomposition (no matrix of the vertex)."""
    from symdecomp.analysis.sharp_structural import structural_values
    from symdecomp.analysis.triangular_eigen import near_weight

    here = vertex.at_level(level)
    values, size = structural_values(scheme, here, prec=max(256, 4 * digits + 64))
    entries = []
    with flint.ctx.workprec(4 * digits + 64):
        for v in values:
            names: list[str] = []
            for e in v.blocks:
                if _block_name(e, here) not in names:
                    names.append(_block_name(e, here))
            entries.append(replace(v, text=acb_text(v.ball, digits), blocks=tuple(names)))
    irrational = sorted(k for k in set(here.sectors) if near_weight(scheme, here, k) is not None)
    field = f"Q({', '.join(f'cos(pi/{k})' for k in irrational)})" if irrational else "Q"
    return SharpSpectrum(scheme.name, vertex, level, here.sharpness, size, True, tuple(entries), field, "structural")


def field_name(S) -> str:
    """``"Q"`` for a rational matrix, else its entries' field, e.g. ``"Q(cos(pi/5))"`` (``"Q(w), w = ..."`` otherwise)."""
    if isinstance(S, flint.fmpq_mat) or S.modulus.degree() == 1:
        return "Q"
    atoms = S.weight.atoms(sp.cos)
    if len(atoms) == 1:
        return f"Q({sp.sstr(atoms.pop())})"
    k = _cos_index(S)
    return f"Q(cos(pi/{k}))" if k else f"Q({sp.sstr(S.weight)})"


def _cos_index(S) -> int | None:
    """The ``k`` with ``Q(w) = Q(cos(pi/k))``: ``cos(pi/k)`` has ``w``'s degree and is a rational affine function of it."""
    from symdecomp.algebra.cos_field import affine_in

    d = S.modulus.degree()
    for k in range(2, 4 * d + 8):
        c = sp.cos(sp.pi / k)
        pq = affine_in(c, S.weight)
        if pq is not None and pq[1] != 0:
            return k
    return None


def sharp_levels(scheme: Scheme, vertex, *, digits: int = 20) -> list[SharpSpectrum]:
    """The spectra at level 0 and at each later level whose matrix differs from the one before, until the
    sharpness has decayed to 0 (one spectrum for infinitely sharp edges)."""
    from symdecomp.analysis.triangular_eigen import sharp_matrix
    from symdecomp.schemes.sector import MAX_LEVEL

    out = [sharp_spectrum(scheme, vertex, digits=digits)]
    if vertex.sharpness == math.inf:
        return out
    previous = sharp_matrix(scheme, vertex)
    for level in range(1, MAX_LEVEL + 1):
        S = sharp_matrix(scheme, vertex, level=level)
        if S != previous:
            out.append(sharp_spectrum(scheme, vertex, level=level, digits=digits))
            previous = S
        if vertex.at_level(level).sharpness == 0:
            break
    return out
