"""Sector evaluation data (crease, boundary, corner; standard and BLZ rules): decomposition, routes, other evaluator."""

from fractions import Fraction

import flint
import pytest

from symdecomp.analysis import evaluation, subpatch_data
from symdecomp.analysis.sector_evaldata import CELLS, sector_evaldata
from symdecomp.analysis.sector_evaluation import evaluate
from symdecomp.errors import EvaluationError, InvalidInputError, InvalidTypeError, LatticeFactMissing, NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import modified_edges

CC = catmull_clark()
BLZ = load_scheme("catmull-clark-blz")
#: Dyadic parameters inside cells (not on the lattice the refinement reaches), and on it.
PARAMS = [(Fraction(3, 8), Fraction(5, 16)), (Fraction(1), Fraction(7, 9)), (Fraction(1, 3), Fraction(0)),
          (Fraction(0), Fraction(11, 64)), (Fraction(5, 1024), Fraction(3, 1024)), (Fraction(1, 2), Fraction(1, 2))]


def _net(size, seed=3):
    import random

    rng = random.Random(seed)
    return [[Fraction(rng.randint(-50, 50), rng.randint(1, 7)) for _ in range(2)] for _ in range(size)]


def _fraction(x):
    return Fraction(int(x.p), int(x.q))


@pytest.mark.parametrize("vertex", [SharpVertex.crease(2, 3, "quad"), SharpVertex.boundary(4, "quad"),
                                    SharpVertex.corner(3, "quad")], ids=repr)
def test_decomposition_is_exact(vertex):
    d = sector_evaldata(CC, vertex)
    a = d.matrix
    charpoly = flint.fmpq_poly([1])
    for b in d.decomposition:
        assert b.basis * b.block == a * b.basis                     # A W_i = W_i B_i, exactly
        assert _identity(b.left * b.basis)                           # W^-1 W = I on the block
        q = flint.fmpq_poly(list(b.factor))
        charpoly *= (q / q.coeffs()[-1]) ** b.multiplicity
        assert len(b.values) == len(b.factor) - 1
        assert all(flint.acb_poly(list(q.coeffs()))(z).contains(0) for z in b.values)   # balls holding the roots of q
    assert charpoly == a.charpoly()                                 # the blocks account for the whole spectrum
    assert sum(b.block.nrows() for b in d.decomposition) == d.size


def _identity(m):
    return all(m[i, j] == (1 if i == j else 0) for i in range(m.nrows()) for j in range(m.ncols()))


@pytest.mark.parametrize("vertex", [SharpVertex.crease(3, 3, "quad"), SharpVertex.boundary(5, "quad")], ids=repr)
def test_eigen_expansion_equals_powers(vertex):
    d = sector_evaldata(CC, vertex)
    net = _net(d.size)
    for s in range(d.faces):
        for u, v in PARAMS:
            e, p = evaluate(d, s, u, v, net), evaluate(d, s, u, v, net, route="powers")
            assert [e[k] for k in ("point", "du", "dv")] == [p[k] for k in ("point", "du", "dv")]


@pytest.mark.parametrize("k", range(1, 7))
@pytest.mark.parametrize("kind", ["boundary", "corner"])
def test_agrees_with_the_boundary_evaluator(kind, k):
    """Stam's sub-patches at distance 1..2 with matrix powers (another route) give the same exact points."""
    vertex = getattr(SharpVertex, kind)(k, "quad")
    d, other = sector_evaldata(CC, vertex), subpatch_data.sharp_patch_data(CC, vertex)
    net = _net(d.size)
    for s in range(k):
        for u, v in PARAMS:
            got, want = evaluate(d, s, u, v, net), evaluation.evaluate(other, s, u, v, net)
            assert [_fraction(x) for x in got["point"]] == want["point"]
            if (u, v) != (0, 0):
                assert [_fraction(x) for x in got["du"]] == want["du"]


@pytest.mark.parametrize("k1, k2", [(1, 2), (2, 3), (4, 4)])
def test_crease_sector_is_a_boundary_fan(k1, k2):
    """With standard rules the crease's second sector is evaluated as a boundary vertex with k2 faces."""
    crease = SharpVertex.crease(k1, k2, "quad")
    fan = SharpVertex.boundary(k2, "quad")
    d, other = sector_evaldata(CC, crease), subpatch_data.sharp_patch_data(CC, fan)
    net = _net(d.size)
    index = {lab: i for i, lab in enumerate(crease.ring_labels(2))}

    def mapped(label):
        s, u, v = label
        return label if (u, v) == (0, 0) else ((k1 + s) % crease.faces, u, v)

    fan_net = [net[index[mapped(lab)]] for lab in fan.ring_labels(2)]
    for s in range(k2):
        for u, v in PARAMS:
            got = evaluate(d, k1 + s, u, v, net)["point"]
            assert [_fraction(x) for x in got] == evaluation.evaluate(other, s, u, v, fan_net)["point"]


@pytest.mark.parametrize("k", range(1, 7))
def test_modified_rows_are_blz_near_edge_points(k):
    """The rows found not regular are the near-edge points (s, 1, 0) of the smooth rays, exactly where BLZ differ."""
    vertex = SharpVertex.boundary(k, "quad")
    d = sector_evaldata(BLZ, vertex)
    differs = modified_edges(BLZ, vertex, k) is not None
    assert d.modified == (tuple((s, 1, 0) for s in range(1, k)) if differs else ())
    assert sector_evaldata(CC, vertex).modified == ()
    assert d.exact is (k <= 3)          # cos(pi/k) is rational for k <= 3 only
    assert (d.decomposition is None) is (k > 3)


@pytest.mark.parametrize("scheme", [CC, BLZ], ids=lambda s: s.name)
def test_constants_are_reproduced(scheme):
    d = sector_evaldata(scheme, SharpVertex.crease(4, 4, "quad"))
    one = [[Fraction(7)]] * d.size
    for s in range(d.faces):
        for u, v in PARAMS:
            r = evaluate(d, s, u, v, one)
            assert all(x.contains(7) if isinstance(x, flint.arb) else x == 7 for x in r["point"])
            if r["du"] is not None:
                assert all(x.contains(0) if isinstance(x, flint.arb) else x == 0 for x in r["du"] + r["dv"])


def test_cells_are_the_wide_ring():
    assert len(CELLS) == 12 and all(2 <= max(c) <= 3 for c in CELLS)


@pytest.mark.parametrize("make, error, text", [
    (lambda: sector_evaldata(CC, SharpVertex.dart(5, "quad")), NotApplicableError, "sector evaluation data are for"),
    (lambda: sector_evaldata(CC, SharpVertex.crease(2, 2, "quad", sharpness=Fraction(1, 2))), NotApplicableError,
     "infinitely sharp"),
    (lambda: sector_evaldata(loop(), SharpVertex.boundary(2, "triangle")), LatticeFactMissing, "sector evaluation data"),
    (lambda: sector_evaldata(CC, "crease"), InvalidTypeError, "vertex must be a SharpVertex"),
])
def test_refusals(make, error, text):
    with pytest.raises(error, match=text):
        make()


def test_bad_evaluation_input():
    d = sector_evaldata(CC, SharpVertex.boundary(2, "quad"))
    net = _net(d.size)
    with pytest.raises(EvaluationError, match="u must be an exact rational in"):
        evaluate(d, 0, 0.5, Fraction(1, 2), net)
    with pytest.raises(EvaluationError, match="v must be"):
        evaluate(d, 0, Fraction(1, 2), Fraction(3, 2), net)
    with pytest.raises(InvalidInputError, match="face must be an integer from 0 to 1"):
        evaluate(d, 2, Fraction(1, 2), Fraction(1, 2), net)
    with pytest.raises(InvalidInputError, match=f"need {d.size} points"):
        evaluate(d, 0, Fraction(1, 2), Fraction(1, 2), net[:-1])
    with pytest.raises(InvalidInputError, match="route must be"):
        evaluate(d, 0, Fraction(1, 2), Fraction(1, 2), net, route="fast")


def test_the_inner_edge_of_the_ring_is_the_same_point():
    """A point on the ring's outer edge at level n is on its inner edge at level n - 1: both give one exact value."""
    d = sector_evaldata(BLZ, SharpVertex.boundary(3, "quad"))
    net = _net(d.size)
    for u, v in [(Fraction(1, 4), Fraction(3, 32)), (Fraction(5, 64), Fraction(1, 8))]:
        outer = evaluate(d, 1, u, v, net)
        inner = evaluate(d, 1, u, v, net, level=outer["level"] - 1)
        assert outer["point"] == inner["point"] and outer["du"] == inner["du"]
    with pytest.raises(EvaluationError, match="level must be an integer n >= 2"):
        evaluate(d, 1, Fraction(1, 4), Fraction(1, 8), net, level=2)
