"""The structural certificate of a boundary, crease or corner vertex: O(k) per vertex, no characteristic polynomial.

The dense route (:func:`~symdecomp.verify.certify.certify_sharp`) proves ``chi_S = det(l - C) prod_j det(l - M(theta_j))``
from the characteristic polynomial of the whole refined matrix ``S`` (cubic in the faces: 13 s at k = 64). This route
proves the same identity from ``S``'s rows, as the interior's structural route
(:mod:`symdecomp.verify.structural`) proves the bordered circulant-block form entry by entry:

1. **The rows.** ``S`` is built by exact refinement of the tagged ring mesh
   (:func:`~symdecomp.schemes.sector.sharp_matrix_rows`, sparse, with no knowledge of the blocks). Each of its rows is
   compared exactly, entry by entry, with the row of the mirror model
   (:func:`~symdecomp.analysis.mirror.sector_rows`): ``O`` and the sharp-edge points read the crease block ``C`` and
   nothing else; the edge point ``a_(p+i)`` of a sector's interior edge reads the smooth edge stencil (BLZ's modified one
   next to the sharp vertex, its ``cos(theta_k)`` weights at ``theta_k = pi/k``) on ``O, a_(p+i+d), b_(p+i+d)``; the face
   point ``b_(p+i)`` the face stencil. Weights are rationals, or (rules with ``cos(theta_k)`` weights) numbers
   ``p + q cos(pi/k)`` of ``Q(cos(pi/k))``, equal exactly when ``p`` and ``q`` are
   (:func:`~symdecomp.algebra.cos_field.affine_in`; ``1`` and ``cos(pi/k)`` are linearly independent over ``Q`` for
   ``k >= 4``, and ``cos(pi/k)`` is rational below). Every entry of ``S`` is read, so ``S`` *is* the model: O(k) work.
2. **The blocks.** For the model, the sine polylines ``a_(p+i) = A sin(theta i)``, ``b_(p+i) = B sin(theta (i + 1/2))``,
   ``theta = pi j/k``, are mapped to themselves by ``M(theta)`` (the identity in ``theta`` and the index ``i``,
   :func:`~symdecomp.analysis.mirror.sine_identity`, reduced to 0 once per scheme, so it holds for every ``k``; the
   polylines vanish on the sharp points, ``sin 0 = sin(pi j) = 0``), ``j = 1..k-1``, and on quads ``b_i = (-1)^i`` by
   ``h_0`` (``j = k``). The crease rows read only ``O`` and the sharp points (step 1), and no row of one sector reads
   another's interior points. With ``V`` the unit vectors of ``O`` and the sharp points followed by the polylines
   (per sector a discrete sine basis: DST-I on the ``a``, DST-II on the ``b``; ``V`` is invertible), ``S V = V B``
   with ``B`` block lower-triangular, diagonal ``C, M(theta_j), h_0``. So, in ``Q[l]`` (``Q(cos(pi/k))[l]`` for
   ``cos(theta_k)`` weights)::

       chi_S(l) = det(l - C) prod_sectors prod_{j=1}^{k-1} det(l - M(pi j/k)) (l - h_0)    (quads; no h_0 on triangles)

3. **The values.** The blocks' eigenvalues with their multiplicities, joined exactly in ``Q(cos(pi/k))``
   (:func:`~symdecomp.analysis.block_values.structural_values`: O(k) block evaluations; values whose Arb balls
   overlap are decided equal or not exactly): the distinct eigenvalues of ``S`` and their algebraic multiplicities.

A row of ``S`` that is not the model's refutes the decomposition for ``S`` (the row, the column and both weights are
named: the computed counterexample); a value the join cannot decide leaves the vertex undecided. Out of reach (refused,
:class:`~symdecomp.errors.NotApplicableError`; the dense route decides them): darts (their symmetric part is the
whole fan), semi-sharp edges, corners given an angle, rules that read ``theta_k`` other than through ``cos(theta_k)``.

>>> import symdecomp as sd
>>> c = certify_sector(sd.catmull_clark(), sd.SharpVertex.boundary(200, sd.QUAD))
>>> c.status.value, c.route, c.distinct, sum(c.multiplicities)
('agree', 'structural', 400, 402)
"""

from __future__ import annotations

import dataclasses
import functools
import math

import flint
import sympy as sp

from symdecomp.algebra.cos_field import affine_in
from symdecomp.algebra.numbers import to_sympy
from symdecomp.analysis.block_values import layout, structural_values
from symdecomp.analysis.mirror import sector_rows, vertex_of
from symdecomp.analysis.spectrum import acb_text
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import sharp_matrix_rows
from symdecomp.validate import check_digits
from symdecomp.verify.certify import SharpCertificate, describe_vertex
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["certify_sector", "applies", "default_route", "certify_vertex", "METHOD", "DENSE_UP_TO", "ROUTES"]

#: What the certificate proves, as the ``check`` row's certificate column says it.
METHOD = ("refined matrix = the mirror model, row by row ({entries} entries, exact in {field}); sine identity for every k; "
          "so chi_S = det(l - C) prod_j det(l - M(theta_j)): the blocks' values, joined exactly")


@functools.lru_cache(maxsize=4096)
def _same_weight(refined: sp.Expr, model: sp.Expr, k: int) -> bool | None:
    """Whether two exact weights are equal in ``Q(cos(pi/k))`` (``None``: a number not of the form ``p + q cos(pi/k)``)."""
    difference = sp.expand(refined - model)
    if difference.is_Rational:
        return difference == 0
    pq = affine_in(difference, sp.cos(sp.pi / k))
    if pq is None:
        return None
    return pq[0] == 0 and pq[1] == 0


def _point_name(lay, r: int) -> str:
    """The 1-ring point of row ``r``: ``O``, ``a_m`` or ``b_m``."""
    if r == 0:
        return "O"
    return f"a_{r - 1}" if r <= lay.a_count else f"b_{r - 1 - lay.a_count}"


def _first_difference(refined: tuple, model: tuple, lay, k: int) -> tuple[str | None, int, bool]:
    """``(the first entry where S is not the model, or None; entries compared; whether a weight is irrational)``;
    raises where a weight is undecidable."""
    if len(refined) != len(model):
        return f"the refined matrix has {len(refined)} rows, the model {len(model)}", 0, False
    entries, irrational = 0, False
    for r, (got, want) in enumerate(zip(refined, model)):
        got = {c: to_sympy(x) for c, x in got.items() if x != 0}
        want = {c: sp.sympify(x, strict=True) for c, x in want.items() if x != 0}
        for c in sorted(set(got) | set(want)):
            entries += 1
            x, y = got.get(c, sp.Integer(0)), want.get(c, sp.Integer(0))
            irrational = irrational or not x.is_Rational
            same = x == y or _same_weight(x, y, k)
            if same is None:
                raise NotApplicableError(f"the weight {x} of row {_point_name(lay, r)} is not p + q cos(pi/{k}) with "
                                         "rational p, q")
            if not same:
                return (f"row {_point_name(lay, r)} (the refined point of {_point_name(lay, r)}), column "
                        f"{_point_name(lay, c)}: the refined matrix has {sp.sstr(x)}, the mirror model {sp.sstr(y)}"), entries, irrational
    return None, entries, irrational


def _field(lay, irrational: bool) -> str:
    """The field of the weights: ``Q``, or ``Q(cos(pi/k))`` (per sector, where the sectors differ)."""
    ks = sorted(set(lay.sectors))
    return "Q" if not irrational else f"Q(cos(pi/{ks[0]}))" if len(ks) == 1 else "Q(cos(pi/k)) of each sector's k"


def certify_sector(scheme: Scheme, vertex, *, digits: int = 20, matrix: tuple | None = None) -> SharpCertificate:
    """Prove (or refute, with the entry that differs) that the mirror decomposition's blocks are the spectrum of the
    refined matrix of ``vertex``, in O(k) (module docstring: what is proved).

    ``vertex``: a boundary, crease or corner :class:`~symdecomp.schemes.sector.SharpVertex` with infinitely sharp edges;
    ``matrix``: the sparse rows to certify (:func:`~symdecomp.schemes.sector.sharp_matrix_rows`'s form; default: the
    rows of ``scheme``'s own refinement), so that a matrix built by other rules can be held against these blocks.
    Raises :class:`~symdecomp.errors.NotApplicableError` where the route does not reach (module docstring).
    """
    scheme, digits = check_scheme(scheme), check_digits(digits)
    vertex = vertex_of(scheme, vertex)
    lay, name = layout(scheme, vertex), describe_vertex(vertex)
    k = vertex.sectors[0]
    refined = sharp_matrix_rows(scheme, vertex) if matrix is None else tuple(matrix)
    where, entries, irrational = _first_difference(refined, sector_rows(scheme, vertex), lay, k)
    common = dict(n=k, scheme=scheme.name, height_bits=0, route="structural", vertex=name)
    if where is not None:
        return SharpCertificate(status=CrossCheckStatus.DISAGREE, method="refined matrix != the mirror model",
                                multiplicities_certified=False, distinct=0, multiplicities=(), values=(), **common,
                                message=f"{name}: refuted: {where} (exact)")
    prec = max(256, 4 * digits + 64)
    try:
        values, size = structural_values(scheme, vertex, prec=prec)
    except NotApplicableError as exc:  # the layout was read above: what is left is a pair of values not told apart
        return SharpCertificate(status=CrossCheckStatus.UNDECIDED, method="refined matrix = the mirror model; values not joined",
                                multiplicities_certified=False, distinct=0, multiplicities=(), values=(), **common,
                                message=f"{name}: undecided: the rows are the model's, but {exc}")
    with flint.ctx.workprec(prec):
        texts = tuple(acb_text(v.ball, digits) for v in values)
    method = METHOD.format(entries=entries, field=_field(lay, irrational))
    message = (f"{name}: proved: {method}; {len(values)} distinct eigenvalues of the {size} x {size} matrix, "
               "multiplicities exact")
    return SharpCertificate(status=CrossCheckStatus.AGREE, method=method, multiplicities_certified=True, message=message,
                            distinct=len(values), multiplicities=tuple(v.multiplicity for v in values), values=texts, **common)


def applies(scheme: Scheme, vertex) -> bool:
    """Whether :func:`certify_sector` reaches ``vertex`` (not a dart, a semi-sharp edge or a corner given an angle)."""
    try:
        layout(scheme, vertex)
    except NotApplicableError:
        return False
    return vertex.sharpness == math.inf


#: The faces up to which ``check --certify --k`` takes the dense route by default under rational rules (both routes run
#: and agree there: ``tests/verify/test_sector_structural.py``); past them the dense route's characteristic polynomial
#: (cubic in the faces, 13 s at 64) gives way to this one. Rules with ``cos(theta_k)`` weights take this route at every
#: size: their dense route works in ``Q(cos(pi/k))`` (minutes for ``check --k 1:16 --scheme catmull-clark-blz``).
DENSE_UP_TO = 16
#: The certificates of a sharp vertex: ``structural`` (:func:`certify_sector`) and ``charpoly`` (the dense route,
#: :func:`~symdecomp.verify.certify.certify_sharp`).
ROUTES = ("structural", "charpoly")


def default_route(scheme: Scheme, vertex) -> str:
    """``structural`` where :func:`certify_sector` reaches the vertex, except under rational rules up to
    :data:`DENSE_UP_TO` faces; else ``charpoly`` (darts, ...)."""
    reads_angle = scheme.sharp is not None and scheme.sharp.near_edge_centre is not None
    small = vertex.faces <= DENSE_UP_TO and not reads_angle
    return "structural" if not small and applies(scheme, vertex) else "charpoly"


def certify_vertex(vertex, *, scheme: Scheme, route: str | None = None) -> SharpCertificate:
    """The certificate of ``vertex`` by ``route`` (default :func:`default_route`), vertex first for the shared pool
    (:func:`symdecomp.parallel.ordered_map`; a vertex that travelled to a worker is given the scheme's own lattice object
    again, which the refinement compares by identity)."""
    from symdecomp.verify.certify import certify_sharp

    vertex = dataclasses.replace(vertex, lattice=scheme.lattice.name)
    route = route or default_route(scheme, vertex)
    return certify_sector(scheme, vertex) if route == "structural" else certify_sharp(scheme, vertex)
