"""Designed 1-rings: the written (rational) net's exact limit position, normal and tangent are the prescribed ones,
the amounts decay under exact subdivision by the predicted eigenvalues, and the least-squares redesign is the least
change that meets its constraints."""

import math
from fractions import Fraction
from pathlib import Path

import flint
import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.design import design_ring, limit_frame, ring_amounts
from symdecomp.analysis.frequency import ring_blocks
from symdecomp.analysis.inspection import inspect_vertex, position_weights
from symdecomp.analysis.masks import ring_masks
from symdecomp.analysis.redesign import redesign_vertex
from symdecomp.errors import InvalidInputError, InvalidMeshError, NotApplicableError
from symdecomp.schemes.loop import loop
from symdecomp.schemes.meshformats import decode_mesh, encode_mesh, read_mesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import omega as OMEGA

MODEL = Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"
SCHEMES = {"catmull-clark": catmull_clark(), "loop": loop()}
CASES = [(name, n) for name in SCHEMES for n in (3, 5, 6, 8)]


def ring_points(design):
    return [design.mesh.points[v] for v in design.ring]


def certified_tangents(scheme, n, points, digits=30):
    """The tangent masks as certified balls (ring_masks, another route than the design's) applied to the ring."""
    masks = ring_masks(scheme, n, 1, digits=digits)["tangents"]
    out = []
    with flint.ctx.workprec(4 * digits + 64):
        for mask in masks:
            weights = [flint.arb(mask["O"])] + [flint.arb(w) for key in sorted(mask["classes"]) for w in mask["classes"][key]]
            out.append([sum((w * flint.arb(flint.fmpq(p[c].numerator, p[c].denominator)) for w, p in zip(weights, points)),
                            flint.arb(0)) for c in range(3)])
    return out


@pytest.mark.parametrize("name, n", CASES)
def test_the_written_net_has_exactly_the_prescribed_position_normal_and_tangent(name, n):
    scheme = SCHEMES[name]
    normal, position, tangent = (1, 2, 2), (Fraction(1, 2), -2, Fraction(3, 4)), (1, 0, 0)
    design = design_ring(scheme, n, normal=normal, position=position, tangent=tangent)
    written = decode_mesh(encode_mesh(design.mesh, "obj"), "obj")
    assert written.points == design.mesh.points  # the file holds the net exactly (terminating decimals)
    achieved = limit_frame(scheme, written, 0, normal=normal, tangent=tangent)
    assert achieved.position == tuple(sp.Rational(x) for x in position)
    assert achieved.normal_exact is True and achieved.tangent_exact is True
    assert np.allclose(achieved.normal, np.array(normal) / 3, atol=1e-12, rtol=0)
    # the same by the tangent masks of ring_masks (Arb, printed to 30 digits: the products are below 1e-25, the tangents ~1)
    t1, t2 = certified_tangents(scheme, n, ring_points(design))
    v = (0, 1, -1)  # along N x u, u along (8/9, -2/9, -2/9)
    for t, direction in ((t1, normal), (t2, normal), (t1, v)):
        with flint.ctx.workprec(200):
            dot = sum((t[c] * direction[c] for c in range(3)), flint.arb(0))
        assert abs(dot).upper() < 1e-25
    cross = np.cross([float(x.mid()) for x in t1], [float(x.mid()) for x in t2])
    assert np.dot(cross, normal) > 0  # the normal points the prescribed way, not the opposite


@pytest.mark.parametrize("name, n", CASES)
def test_elliptic_heights_keep_position_and_normal_exact_where_the_mask_is_rational(name, n):
    scheme = SCHEMES[name]
    design = design_ring(scheme, n, normal=(0, 0, 1), position=(1, 2, 3), elliptic=Fraction(1, 2))
    a = design.achieved
    assert a.normal_exact is True and a.elliptic == pytest.approx(0.5, abs=1e-12)
    rational = all(w.is_Rational for w in position_weights(scheme, n))
    assert max(abs(float(x) - y) for x, y in zip(a.position, (1, 2, 3))) < 1e-14
    if rational:
        assert a.position == (1, 2, 3)


@pytest.mark.parametrize("name, n", [(name, n) for name in SCHEMES for n in (5, 6, 7, 8, 10)])
def test_a_saddle_keeps_the_normal_exact_exactly_at_even_valences(name, n):
    """At even n the heights of frequency 2 lie in a rational space without frequency 1 (the Galois orbit of 2 is the
    j with gcd(j, n) = 2); at odd n the orbit holds 1, so no rational ring has a saddle and an exact normal."""
    scheme = SCHEMES[name]
    design = design_ring(scheme, n, normal=(2, 3, 6), position=(1, 0, -1), hyperbolic=Fraction(1, 5), angle=Fraction(2, 5))
    a = design.achieved
    assert a.normal_exact is (n % 2 == 0) and a.tangent_exact is True  # t_1 along the default tangent
    assert np.allclose(a.normal, np.array([2, 3, 6]) / 7, atol=1e-12, rtol=0)
    assert a.hyperbolic == pytest.approx(0.2, abs=1e-12) and a.angle == pytest.approx(0.4, abs=1e-12)
    if name == "catmull-clark":
        assert a.position == (1, 0, -1)


def test_a_height_off_frequency_zero_breaks_the_exact_normal():
    """The exactness check can fail: one a_i raised by 1/1024 tilts the normal."""
    design = design_ring(catmull_clark(), 5, normal=(0, 0, 1))
    points = list(design.mesh.points)
    x, y, z = points[design.ring[1]]
    points[design.ring[1]] = (x, y, z + Fraction(1, 1024))
    tilted = type(design.mesh).from_arrays(points, design.mesh.faces)
    a = limit_frame(catmull_clark(), tilted, 0, normal=(0, 0, 1))
    assert a.normal_exact is False and max(abs(a.normal[0]), abs(a.normal[1])) > 1e-5


def _predicted(scheme, n, j):
    """The eigenvalue that carries the elliptic (j = 0: second of E_0) or hyperbolic (j = 2: dominant) component."""
    blocks = ring_blocks(scheme, 1)
    if j == 0:
        values = sorted((complex(v) for v in sp.Matrix(blocks.frequency_zero_matrix(n)).eigenvals(multiple=True)), key=lambda v: -abs(v))
        return values[1].real
    E = sp.Matrix(blocks.frequency_matrix()).subs(OMEGA, sp.exp(2 * sp.pi * sp.I * j / n))
    return max((complex(sp.N(v, 30)) for v in E.eigenvals(multiple=True)), key=abs).real


@pytest.mark.slow
@pytest.mark.parametrize("name, n", [("catmull-clark", 5), ("catmull-clark", 8), ("loop", 5), ("loop", 8)])
def test_exact_refinement_keeps_position_and_normal_and_decays_the_amounts_by_their_eigenvalues(name, n):
    scheme = SCHEMES[name]
    design = design_ring(scheme, n, normal=(0, 0, 1), position=(1, -1, 2), elliptic=Fraction(1, 4), hyperbolic=Fraction(1, 8),
                         angle=sp.pi / 7)
    S = ring_blocks(scheme, 1).full_matrix(n)
    P = sp.Matrix([[sp.Rational(c.numerator, c.denominator) for c in p] for p in ring_points(design)])
    e0, b0, t0 = ring_amounts(scheme, [tuple(float(c) for c in row) for row in P.tolist()], (0, 0, 1))
    mu, lam2 = _predicted(scheme, n, 0), _predicted(scheme, n, 2)
    w = position_weights(scheme, n)
    weights = sp.Matrix([[w[0]] + [w[1 + (k // n)] for k in range(len(design.ring) - 1)]])
    limit = weights * P
    for k in range(1, 4):
        P = S * P  # exact subdivision of the 1-ring
        assert all(sp.simplify(x - y) == 0 for x, y in zip(weights * P, limit))  # the limit point does not move
        e, b, t = ring_amounts(scheme, [tuple(float(sp.N(c, 30)) for c in row) for row in P.tolist()], (0, 0, 1))
        assert e == pytest.approx(e0 * mu**k, rel=1e-9)
        assert b == pytest.approx(b0 * lam2**k, rel=1e-9) and t == pytest.approx(t0, abs=1e-9)
    assert e0 == pytest.approx(0.25, abs=1e-12) and b0 == pytest.approx(0.125, abs=1e-12) and t0 == pytest.approx(math.pi / 7, abs=1e-12)


@pytest.mark.parametrize("name", SCHEMES)
def test_the_redesign_meets_its_constraints_with_the_least_change(name):
    scheme = SCHEMES[name]
    mesh = read_mesh(MODEL)
    if name == "loop":
        mesh = type(mesh).from_arrays(mesh.points, [t for f in mesh.faces for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))])
    vertex = next(v for v in mesh.extraordinary_vertices(scheme.lattice) if mesh.valence(v) >= 5)
    before = limit_frame(scheme, mesh, vertex)
    target = tuple(Fraction(round(x * 64), 64) for x in before.normal)  # near the measured normal, not on it
    d = redesign_vertex(scheme, mesh, vertex, normal=target, flatten_hyperbolic=True)
    unit = np.array([float(x) for x in target]) / math.sqrt(sum(float(x) ** 2 for x in target))
    assert np.allclose(d.achieved.normal, unit, atol=1e-12, rtol=0) and d.achieved.hyperbolic < 1e-12
    moved = [v for v in range(len(mesh.points)) if mesh.points[v] != d.mesh.points[v]]
    assert set(moved) <= set(d.ring)
    # another change meeting both constraints: remove the whole frequency-1 and frequency-2 content of each class's heights
    n, K = mesh.valence(vertex), len(ring_blocks(scheme, 1).classes)
    h = np.array([[float(c) for c in mesh.points[v]] for v in d.ring]) @ unit
    other = 0.0
    for q in range(K):
        spectrum = np.fft.fft(h[1 + q * n: 1 + (q + 1) * n])
        other += sum(abs(spectrum[j]) ** 2 for j in {1, 2, n - 2, n - 1}) / n
    assert d.change <= math.sqrt(other) + 1e-12


def test_flattening_keeps_the_limit_point_and_normal():
    mesh = read_mesh(MODEL)
    vertex = next(v for v in mesh.extraordinary_vertices(catmull_clark().lattice) if mesh.valence(v) == 6)
    before = limit_frame(catmull_clark(), mesh, vertex)
    d = redesign_vertex(catmull_clark(), mesh, vertex, flatten_hyperbolic=True)
    assert before.hyperbolic > 1e-3 and d.achieved.hyperbolic < 1e-12
    assert inspect_vertex(d.mesh, vertex, catmull_clark()).hyperbolic_off_plane < 1e-12  # the faster-decaying part went too
    assert np.allclose(d.achieved.normal, before.normal, atol=1e-12, rtol=0)
    assert max(abs(float(x - y)) for x, y in zip(d.achieved.position, before.position)) < 1e-14


@pytest.mark.parametrize("call, error, words", [
    (lambda: design_ring(catmull_clark(), 5, normal=(0, 0)), InvalidInputError, "normal must be 3 numbers"),
    (lambda: design_ring(catmull_clark(), 5, normal=(0, 0, 0)), InvalidInputError, "zero vector"),
    (lambda: design_ring(catmull_clark(), 5, normal=(0, 0, 1), tangent=(0, 0, 2)), InvalidInputError, "parallel"),
    (lambda: design_ring(catmull_clark(), 5, normal=(0.5, 0, 1)), InvalidInputError, "normal"),
    (lambda: design_ring(catmull_clark(), 5, normal=(0, 0, 1), position=("sqrt(2)", 0, 0)), InvalidInputError, "rational"),
    (lambda: design_ring(catmull_clark(), 3, normal=(0, 0, 1), hyperbolic=1), NotApplicableError, "valence 3"),
    (lambda: design_ring(loop(), 4, normal=(0, 0, 1), hyperbolic=1), NotApplicableError, "valence 4"),
    (lambda: design_ring(catmull_clark(), 5, normal=(0, 0, 1), elliptic="I"), InvalidInputError, "elliptic"),
    (lambda: design_ring(catmull_clark(), 5000, normal=(0, 0, 1)), InvalidInputError, "at most"),
    (lambda: redesign_vertex(catmull_clark(), read_mesh(MODEL), 11), InvalidInputError, "normal or flatten"),
    (lambda: redesign_vertex(catmull_clark(), "mesh.obj", 11, normal=(0, 0, 1)), InvalidMeshError, "PolygonMesh"),
    (lambda: redesign_vertex(catmull_clark(), read_mesh(MODEL), 0, flatten_hyperbolic=True), NotApplicableError, "valence 3"),
    (lambda: redesign_vertex(catmull_clark(), read_mesh(MODEL), 11, normal=(0, 0, -1)), NotApplicableError, "turns the tangent"),
])
def test_bad_input_is_one_clear_error(call, error, words):
    with pytest.raises(error, match=words):
        call()
