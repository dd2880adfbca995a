"""The boundary and corner patch evaluator against exact refinement: limit positions at dyadic parameters.

The reference does not use the evaluator's sub-patches, phantom points or matrix powers: a random exact
control net on the ``R``-ring of the vertex is refined ``m`` times by the ``R``-ring matrix
(:func:`~symdecomp.schemes.sector.exact_sharp_matrix`, the whole mesh with the sharp rules), and at the
lattice point ``(p, q)`` of face ``s`` of the refined net, a regular vertex, the limit position is its
1-ring times the limit mask of a regular vertex: the exact left eigenvector for 1 of the 1-ring matrix of
a smooth valence-4 (quads) or 6 (triangles) vertex, or of a boundary vertex with 2 (quads) or 3
(triangles) faces on a boundary ray. That is the patch's point at ``(u, v) = (p/2^m, q/2^m)``. At
``(0, 0)`` the reference is the vertex's own limit mask applied to the net.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> r = dyadic_check(catmull_clark(), SharpVertex.corner(2, "quad"), levels=(1,), seed=1)
>>> r["points"], r["exact_mismatches"], r["float_error"] < 1e-13
(17, 0, True)
"""

from __future__ import annotations

import random
from fractions import Fraction

from symdecomp.algebra.numbers import to_fraction
from symdecomp.analysis.sharp_evaluation import evaluate, limit_mask, sharp_patch_data
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.lattice import Lattice
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix
from symdecomp.schemes.sector_patch import sector_point
from symdecomp.validate import check_int

__all__ = ["dyadic_check", "regular_limit"]

#: Rings of the reference net: lattice points up to distance ``RINGS - 1`` have their 1-ring in it.
RINGS = 3


def _rows(m) -> list[dict]:
    return [{c: to_fraction(m[i, c]) for c in range(m.ncols()) if m[i, c] != 0} for i in range(m.nrows())]


def _mask(scheme: Scheme, vertex: SharpVertex) -> tuple[Fraction, ...]:
    return limit_mask(_rows(exact_sharp_matrix(scheme, vertex)), vertex.one_ring_size())


def _one_ring(lat: Lattice, p: int, q: int, where: str) -> list[tuple[int, int]]:
    """The 1-ring of ``(p, q)`` in SharpVertex order (``O``, edge neighbours, face neighbours) in face coordinates."""
    out = [(p, q)]
    for offsets in lat.neighbour_offsets:  # edge neighbours, then face neighbours, counter-clockwise from (1, 0)
        if where != "inside":  # on ray 0 the half-plane v >= 0; on ray k its mirror u >= 0, clockwise from (0, 1)
            offsets = tuple((du, dv) if where == "ray0" else (dv, du) for du, dv in offsets if dv >= 0)
        out += [(p + du, q + dv) for du, dv in offsets]
    return out


def regular_limit(scheme: Scheme, vertex: SharpVertex, face: int, p: int, q: int, value) -> list:
    """The limit position at the regular lattice point ``(p, q) != (0, 0)`` of ``face``; ``value(label)`` of the net."""
    lat, k = vertex.lattice, vertex.faces
    if face == 0 and q == 0:
        where, fan = "ray0", SharpVertex.boundary(lat.regular_boundary_faces, lat)
    elif face == k - 1 and p == 0:
        where, fan = "rayk", SharpVertex.boundary(lat.regular_boundary_faces, lat)
    else:
        where, fan = "inside", SharpVertex.dart(lat.regular_valence, lat, sharpness=0)
    mask = _mask(scheme, fan)
    total = None
    for w, (x, y) in zip(mask, _one_ring(lat, p, q, where)):
        (one, label), = sector_point(lat, k, face, x, y)  # a real point: the 1-ring of a regular point
        term = [w * c for c in value(label)]
        total = term if total is None else [a + b for a, b in zip(total, term)]
    return total


def _parameters(lat: Lattice, m: int):
    top = min(2**m, RINGS - 1)  # the 1-ring of a point at distance top is in the RINGS-ring
    for p in range(top + 1):
        for q in range(top + 1):
            if (p, q) != (0, 0) and lat.level_measure(p, q, None) <= top and lat.in_domain(Fraction(p, 2**m), Fraction(q, 2**m)):
                yield p, q


def dyadic_check(scheme: Scheme, vertex: SharpVertex, *, levels=(1, 2, 3), seed: int = 0) -> dict:
    """Evaluate every face at ``(p/2^m, q/2^m)`` (``m`` in ``levels``) and at ``(0, 0)`` against the reference.

    Returns ``{"points", "exact_mismatches", "float_error"}``: the number of parameters checked, how many
    exact (Fraction) evaluations differ from the exact reference, and the largest float64 deviation.
    """
    scheme = check_scheme(scheme)
    levels = tuple(check_int(m, "level", minimum=0, maximum=20) for m in levels)
    data = sharp_patch_data(scheme, vertex)
    rng = random.Random(seed)
    labels = vertex.ring_labels(RINGS)
    index = {lab: i for i, lab in enumerate(labels)}
    net = [[Fraction(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(3)] for _ in labels]
    big = _rows(exact_sharp_matrix(scheme, vertex, rings=RINGS))
    coarse, coarse_f = net[:data.size], [[float(x) for x in p] for p in net[:data.size]]
    cases = [(0, 0, 0, 1, data.limit, net)]
    refined, done = net, 0
    for m in sorted(set(levels)):
        while done < m:
            refined = [[sum((w * refined[c][i] for c, w in row.items()), Fraction(0)) for i in range(3)] for row in big]
            done += 1
        cases += [(s, p, q, 2**m, None, refined) for s in range(vertex.faces) for p, q in _parameters(vertex.lattice, m)]
    mismatches, error = 0, 0.0
    for s, p, q, scale, mask, values in cases:
        if mask is not None:
            if len(labels) < len(mask):
                raise InvalidInputError("the reference net is smaller than the 2-ring")
            want = [sum((w * values[i][d] for i, w in enumerate(mask)), Fraction(0)) for d in range(3)]
        else:
            want = regular_limit(scheme, vertex, s, p, q, lambda lab, v=values: v[index[lab]])
        u, v = Fraction(p, scale), Fraction(q, scale)
        got = evaluate(data, s, u, v, coarse)["point"]
        mismatches += got != want
        got_f = evaluate(data, s, float(u), float(v), coarse_f)["point"]
        error = max(error, float(max(abs(a - float(b)) for a, b in zip(got_f, want)) / max(1.0, *(abs(float(b)) for b in want))))
    return {"points": len(cases), "exact_mismatches": mismatches, "float_error": error}
