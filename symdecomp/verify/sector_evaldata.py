"""The crease, boundary and corner evaluation data against exact refinement, at dyadic parameters.

The reference uses neither the data's picking matrices, their phantom points nor the eigen-decomposition: a
random exact control net on the 3-ring of the vertex is refined ``m`` times by the 3-ring matrix of the tagged
mesh (:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, the scheme's rules for the whole mesh), and at
the lattice point ``(p, q)`` of face ``s`` with ``max(p, q) = 2`` (a regular point whose neighbourhood is
refined by the regular rules from level ``m`` on, BLZ's included) the limit position is the regular limit mask
on its 1-ring (:func:`~symdecomp.verify.patch_eval.regular_limit`: the smooth valence-4 vertex's, or the
crease vertex's on a sharp ray, each the exact left eigenvector of its 1-ring matrix). That is the patch's point
at ``(u, v) = (p / 2^m, q / 2^m)``. With irrational rules (BLZ, ``k >= 4``) the reference and the data are Arb
balls containing the exact values: they agree when the balls overlap and are narrower than ``2^-100``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> r = dyadic_check(catmull_clark(), SharpVertex.crease(2, 2, "quad"), levels=(1,))
>>> r["points"], r["mismatches"]
(20, 0)
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.sector_evaldata import PREC, SectorEvalData, real_ball, sector_evaldata
from symdecomp.analysis.sector_evaluation import evaluate
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix
from symdecomp.validate import check_int, check_type
from symdecomp.verify.patch_eval import regular_limit

__all__ = ["dyadic_check", "TOLERANCE"]

#: Widest ball accepted as a value (irrational rules).
TOLERANCE = 2.0**-100


def _reference_matrix(scheme: Scheme, vertex: SharpVertex, exact: bool):
    m = sharp_subdivision_matrix(scheme, vertex, rings=3)
    out = (flint.fmpq_mat if exact else flint.arb_mat)(m.rows, m.cols)
    for (i, j), w in m.todok().items():
        out[i, j] = to_fmpq(w) if exact else real_ball(w)
    return out


def _sector(vertex: SharpVertex, face: int) -> tuple[int, int]:
    start = 0
    for k in vertex.sectors:
        if face < start + k:
            return start, k
        start += k
    raise ValueError(face)  # pragma: no cover - faces come from range(vertex.faces)


def _reference(scheme, vertex, face, p, q, value):
    """The regular limit at ``(p, q)`` of ``face``, read in the face's sector as a boundary fan of its faces."""
    start, k = _sector(vertex, face)

    def local(label):
        s, u, v = label
        if (u, v) == (0, 0):
            return value(label)
        g = start + s
        return value((g % vertex.faces if vertex.closed else g, u, v))

    fan = SharpVertex.boundary(k, vertex.lattice)
    return regular_limit(scheme, fan, face - start, p, q, local)


class _Ball:
    """An Arb ball that the reference's exact mask weights (``Fraction``) multiply."""

    __slots__ = ("x",)

    def __init__(self, x):
        self.x = x

    def __rmul__(self, w):
        return _Ball(self.x * flint.arb(w.numerator) / w.denominator)

    def __add__(self, other):
        return _Ball(self.x + other.x)


def _value(x, exact: bool):
    return Fraction(int(x.p), int(x.q)) if exact else _Ball(x)


def _agree(got, want, exact: bool) -> bool:
    if exact:
        return all(Fraction(int(a.p), int(a.q)) == b for a, b in zip(got, want))
    want = [b.x for b in want]
    return all(a.overlaps(b) and a.rad() < TOLERANCE and b.rad() < TOLERANCE for a, b in zip(got, want))


def _levels(u, v) -> tuple:
    """Both levels whose wide ring holds ``(u, v)``: its outer edge (``2^n max = 4``) and its inner one (``= 2``)."""
    m = max(u, v)
    n = next(n for n in range(2, 64) if 2**n * m > 2)
    return (n, n - 1) if 2**n * m == 4 and n > 2 else (n,)


def dyadic_check(scheme: Scheme, vertex: SharpVertex, *, levels=(1, 2, 3), seed: int = 0,
                 data: SectorEvalData | None = None) -> dict:
    """Evaluate every face at ``(p / 2^m, q / 2^m)``, ``max(p, q) = 2``, ``m`` in ``levels``, against the reference.

    Each point is evaluated at both levels whose wide ring holds it (on its outer and on its inner edge), so that
    every cell of the ring is read.

    ``data``: the data to check (default: :func:`~symdecomp.analysis.sector_evaldata.sector_evaldata`'s; a test
    passes altered data to see the check fail). Returns ``{"points", "mismatches", "routes"}``: the parameters
    checked, how many evaluations (by every route the data have) differ from the reference, and the routes.
    """
    scheme = check_scheme(scheme)
    levels = tuple(check_int(m, "level", minimum=1, maximum=12) for m in levels)
    data = sector_evaldata(scheme, vertex) if data is None else check_type(data, SectorEvalData, "data")
    rng = random.Random(seed)
    labels = vertex.ring_labels(3)
    index = {lab: i for i, lab in enumerate(labels)}
    net = [[Fraction(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(3)] for _ in labels]
    routes = ("eigen", "powers") if data.decomposition is not None else ("powers",)
    points = mismatches = 0
    with flint.ctx.workprec(PREC):
        big = _reference_matrix(scheme, vertex, data.exact)
        kind = flint.fmpq_mat if data.exact else flint.arb_mat
        refined = kind(len(net), 3, [to_fmpq(x) for row in net for x in row])
        done = 0
        for m in sorted(set(levels)):
            while done < m:
                refined, done = big * refined, done + 1
            values = refined
            for s in range(vertex.faces):
                for p, q in ((p, q) for p in range(3) for q in range(3) if max(p, q) == 2 and max(p, q) <= 2**m):
                    want = _reference(scheme, vertex, s, p, q, lambda lab, v=values: [_value(v[index[lab], c], data.exact) for c in range(3)])
                    u, v = Fraction(p, 2**m), Fraction(q, 2**m)
                    for route, level in ((r, n) for r in routes for n in _levels(u, v)):
                        got = evaluate(data, s, u, v, net[:data.size], route=route, level=level)["point"]
                        mismatches += not _agree(got, want, data.exact)
                    points += 1
    return {"points": points, "mismatches": mismatches, "routes": routes}
