"""Reif's test on triangle meshes (Loop): triangular Bernstein-Bezier machinery, verdicts, and exact ties."""

import math
import random

import flint
import numpy as np
import pytest
import sympy as sp

from symdecomp.algebra.triangle_bezier import bezier_indices, bezier_value
from symdecomp.analysis.characteristic import check_applicable, frequency_eigenvector, ring_layout
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.loop import loop, loop_warren, triangle_scheme
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, Stencil, catmull_clark
from symdecomp.symbols import n as N
from symdecomp.verify.bezier import bisect_triangle, certify_sign_triangles, triangle_jacobian_net
from symdecomp.verify.c1 import c1_test, characteristic_nets
from symdecomp.verify.c1_spectrum import exact_charpoly, spectral_conditions
from symdecomp.verify.result import C1Verdict
from tests.verify.test_c1 import standard_at_regular

R = sp.Rational
POINTS = [(0.1, 0.7), (0.25, 0.25), (0.6, 0.3), (0.0, 1.0), (0.33, 0.01)]


def _random_net(degree, seed):
    rng = random.Random(seed)
    return [flint.arb(flint.fmpq(rng.randint(-9, 9), rng.randint(1, 5))) for _ in bezier_indices(degree)]


def _value(net, degree, u, v):
    return float(bezier_value([float(c.mid()) for c in net], degree, u, v))


def test_bisection_is_de_casteljau():
    """Each half's polynomial, mapped back through its corners, is the parent's polynomial."""
    net = _random_net(4, 1)
    corners = ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))
    for half, (p0, p1, p2) in bisect_triangle(net, 4, corners):
        for s, t in POINTS:
            u = p0[0] + s * (p1[0] - p0[0]) + t * (p2[0] - p0[0])
            v = p0[1] + s * (p1[1] - p0[1]) + t * (p2[1] - p0[1])
            assert abs(_value(half, 4, s, t) - _value(net, 4, u, v)) < 1e-12
    # the longest edge is the one cut: the hypotenuse first, then the halves' own hypotenuses
    assert {c for _, cs in bisect_triangle(net, 4, corners) for c in cs} == {(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.5, 0.5)}


def test_triangle_jacobian_net_is_the_jacobian():
    """Against central differences of the two degree-4 polynomials (step 1e-5: agreement to 1e-7)."""
    x, y = _random_net(4, 2), _random_net(4, 3)
    J = triangle_jacobian_net(x, y)
    assert len(J) == len(bezier_indices(6))
    h = 1e-5
    for u, v in [(0.2, 0.3), (0.5, 0.1), (0.1, 0.8)]:
        xu = (_value(x, 4, u + h, v) - _value(x, 4, u - h, v)) / (2 * h)
        xv = (_value(x, 4, u, v + h) - _value(x, 4, u, v - h)) / (2 * h)
        yu = (_value(y, 4, u + h, v) - _value(y, 4, u - h, v)) / (2 * h)
        yv = (_value(y, 4, u, v + h) - _value(y, 4, u, v - h)) / (2 * h)
        assert abs(_value(J, 6, u, v) - (xu * yv - xv * yu)) < 1e-6 * (1 + abs(xu * yv))


def test_triangle_sign_needs_subdivision_and_finds_a_fold():
    """J = (u - 1/3)^2 + 1/100 > 0 has negative Bernstein coefficients; J = u - 1/2 changes sign."""
    # (u - 1/3)^2 + 1/100 in degree 2: the coefficient (a, b, c) is the blossom (u_1 - 1/3)(u_2 - 1/3) + 1/100
    # with b of the two arguments at the corner (1, 0) (u = 1) and the others at u = 0

    def blossom(i):
        us = [0] * i[0] + [1] * i[1] + [0] * i[2]
        return flint.arb((flint.fmpq(us[0]) - flint.fmpq(1, 3)) * (flint.fmpq(us[1]) - flint.fmpq(1, 3)) + flint.fmpq(1, 100))

    net = [blossom(i) for i in bezier_indices(2)]
    assert any(c < 0 for c in net)
    cert = certify_sign_triangles([net], 2, max_depth=12)
    assert cert.status == "positive" and cert.depth > 0 and 0 < cert.lower_bound <= 0.01
    assert certify_sign_triangles([net], 2, max_depth=0).status == "undecided"
    fold = [flint.arb(flint.fmpq(b, 1) - flint.fmpq(1, 2)) for _, b, _ in bezier_indices(1)]
    assert certify_sign_triangles([fold], 1).status == "changes"


def test_regular_valence_is_the_lattice():
    """n = 6: lambda = 1/2, the level-1 points are the lattice (u + v e^{i pi/3})/2, |J| = sqrt(3)/8 exactly."""
    vec = frequency_eigenvector(loop(), 6, 1, flint.acb(flint.fmpq(1, 2)))
    w = flint.acb(flint.fmpq(1, 3)).exp_pi_i()
    for u, v in ring_layout("triangle").labels:
        assert (vec.values[(u, v)] - (u + v * w) / 2).contains(0)
    r = c1_test(loop(), 6)
    assert r.verdict == "c1" and (r.spectral.subdominant.value - flint.fmpq(1, 2)).contains(0)
    assert abs(r.jacobian_lower_bound - math.sqrt(3) / 8) < 1e-12 and r.jacobian_lower_bound <= math.sqrt(3) / 8


@pytest.mark.parametrize("scheme", [loop(), loop_warren()], ids=["loop", "loop-warren"])
def test_loop_is_c1_for_valences_3_to_16(scheme):
    for n in range(3, 17):
        r = c1_test(scheme, n)
        assert r.verdict == "c1", (n, r.reason)
        assert r.winding_number == 1 and r.jacobian_sign == 1 and r.jacobian_lower_bound > 0 and r.frequency == 1
        lam = 3 / 8 + math.cos(2 * math.pi / n) / 4  # Loop's subdominant eigenvalue
        assert abs(float(r.spectral.subdominant.value.real.mid()) - lam) < 1e-14


def _two_ring_moduli(scheme, n):
    """The moduli of the (3n + 1) x (3n + 1) 2-ring matrix, by exact refinement of the mesh (no frequency blocks)."""
    M = ring_subdivision_matrix(scheme, n, 2).exact_matrix()
    A = np.array([[float(sp.N(x, 30)) for x in row] for row in M.tolist()])
    return sorted(abs(np.linalg.eigvals(A)), reverse=True)


@pytest.mark.parametrize("n", [3, 5, 7, 10])
def test_the_certified_loop_spectrum_is_the_whole_two_ring_spectrum(n):
    moduli = _two_ring_moduli(loop(), n)
    assert len(moduli) == 3 * n + 1
    r = c1_test(loop(), n)
    lam = float(r.spectral.subdominant.value.real.mid())
    assert abs(moduli[0] - 1) < 1e-9 and abs(moduli[1] - lam) < 1e-9 and abs(moduli[2] - lam) < 1e-9
    assert moduli[3] <= r.spectral.second + 1e-9 and r.spectral.gap <= lam - moduli[3] + 1e-9


def test_loop_with_beta_zero_is_not_c1_at_frequency_0():
    """beta = 0: the frequency-0 eigenvalue 5/8 exceeds lambda = 3/8 + cos(2 pi/5)/4; Loop's beta flips it."""
    r = c1_test(triangle_scheme("beta zero", standard_at_regular(0, loop().vertex_rule.each_a, 6, (5,))), 5)
    assert r.verdict == "not-c1" and "frequency 0" in r.reason
    assert (r.spectral.subdominant.value - flint.fmpq(5, 8)).contains(0)
    assert c1_test(loop(), 5).verdict == "c1"


def test_loop_with_frequency_two_dominant_is_not_c1():
    """Edge rule at O with side weights 1/8 + (n - 6)/4 (Loop's at n = 6): at n = 5 frequency 2 dominates."""
    side = R(1, 8) + (N - 6) / 4
    scheme = triangle_scheme("frequency two", loop().vertex_rule.each_a, edge_end=R(1, 2) - side, edge_side=side)
    check_applicable(scheme)
    r = c1_test(scheme, 5)
    assert r.spectral.status is C1Verdict.C1 and r.frequency == 2
    lam = 5 / 8 - math.cos(4 * math.pi / 5) / 4
    assert abs(float(r.spectral.subdominant.value.real.mid()) - lam) < 1e-14
    assert r.verdict == "not-c1"


def test_an_exact_opposite_eigenvalue_is_not_strictly_dominant():
    """beta = (1 + cos(2 pi/n)/4)/n puts -lambda at frequency 0 exactly, for every n (in Q(e^{2 pi i/n}))."""
    scheme = triangle_scheme("opposite", standard_at_regular((1 + sp.cos(2 * sp.pi / N) / 4) / N, R(1, 16), 6, (3, 5, 7)))
    for n in (3, 5, 7):
        r = c1_test(scheme, n)
        assert r.verdict == "not-c1" and "exactly its negative" in r.reason, r.reason
        moduli = _two_ring_moduli(scheme, n)
        lam = 3 / 8 + math.cos(2 * math.pi / n) / 4
        assert all(abs(m - lam) < 1e-9 for m in moduli[1:4]) and moduli[4] < lam - 1e-3  # three of modulus lambda
    # a beta off by 1/1000 separates them: the ordinary route decides, and no tie is claimed
    near = triangle_scheme("near", standard_at_regular((1 + sp.cos(2 * sp.pi / N) / 4) / N - R(1, 1000), R(1, 16), 6, (5,)))
    assert "negative" not in c1_test(near, 5).reason


def test_the_conjugate_frequency_copy_is_not_a_tie():
    """lambda at frequency j and at n - j is one eigenvalue of multiplicity 2 (exactly the same block), so C1."""
    for n in (5, 8):
        assert all(a == b for a, b in zip(exact_charpoly(loop(), n, 1), exact_charpoly(loop(), n, n - 1)))
        r = c1_test(loop(), n)
        assert r.verdict == "c1" and r.spectral.subdominant.multiplicity == 2


def test_an_exact_double_root_at_frequency_one_is_multiplicity_four():
    """Catmull-Clark with the edge rule at O changed at n = 3 so that M_1 = (x - 1/4)^2 exactly: not C1, decided."""
    cc = catmull_clark()
    t = R(1, 16) - (N - 4) / 16
    b = (1 - 2 * R(3, 8) - 2 * t) / 2
    scheme = Scheme("double", Stencil.from_weights(R(3, 8), {-1: t, 0: R(3, 8), 1: t}, {-1: b, 0: b}), cc.face_rule, cc.vertex_rule)
    from symdecomp.analysis.frequency import per_frequency_matrix_at

    M = per_frequency_matrix_at(scheme, 3, 1).subs(N, 3)
    # x^2 - tr x + det = (x - 1/4)^2
    assert sp.simplify(sp.expand_complex(M.trace())) == R(1, 2) and sp.simplify(sp.expand_complex(M.det())) == R(1, 16)
    r = c1_test(scheme, 3)
    assert r.verdict == "not-c1" and "multiplicity 4" in r.reason and r.spectral.subdominant.double
    assert (r.spectral.subdominant.value - flint.fmpq(1, 4)).contains(0)


def test_a_triangle_scheme_with_other_regular_rules_is_refused_in_one_line():
    scheme = triangle_scheme("butterfly-ish", R(1, 16), edge_end=R(1, 2), edge_side=R(0))
    with pytest.raises(InvalidSchemeError, match=r"edge rule at valence 6 is not Loop's, so its regular patches are not quartic"):
        check_applicable(scheme)
    with pytest.raises(InvalidSchemeError) as info:
        spectral_conditions(scheme, 5)
    assert "\n" not in str(info.value)


def test_command_line_loop(capsys):
    assert main(["c1", "--scheme", "loop", "--n", "3:5"]) == 0
    out = capsys.readouterr().out
    assert "quartic box-spline" in out and out.count("C1 certified") == 3


def test_characteristic_nets_of_loop_have_fifteen_coefficients():
    nets, vec = characteristic_nets(loop(), 5)
    assert len(nets) == 3 and all(len(x) == len(y) == 15 for x, y in nets) and vec.mesh == "triangle"


def test_scheme_files_get_a_verdict_or_one_line(tmp_path, capsys):
    """A triangle file with Loop's rules is certified; one with other regular rules gets one line and exit status 2."""
    from symdecomp.schemes.files import scheme_to_text

    good = tmp_path / "mine.toml"
    good.write_text(scheme_to_text(loop()))
    assert main(["c1", "--scheme", str(good), "--n", "5"]) == 0
    assert "n =   5: C1 certified" in capsys.readouterr().out
    quad = tmp_path / "quad.toml"
    quad.write_text(scheme_to_text(catmull_clark()))
    assert main(["c1", "--scheme", str(quad), "--n", "5"]) == 0
    assert "bicubic" in capsys.readouterr().out
    other = tmp_path / "other.toml"
    other.write_text('mesh = "triangle"\n[edge]\nO = "1/2"\na = { "0" = "1/2" }\n[vertex]\na = "1/(2*n)"\n')
    assert main(["c1", "--scheme", str(other), "--n", "5"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "does not apply" in err[0] and "not quartic box-splines" in err[0]


def test_loop_ring_values_agree_with_refining_the_mesh():
    """The level-1 3-ring from the frequency blocks equals the 3-ring matrix (exact refinement) applied to the eigenvector.

    The 2-ring rows check that it is an eigenvector; the ring-3 rows the extension the sub-patches read.
    """
    n = 5
    lam = spectral_conditions(loop(), n).subdominant.value
    vec = frequency_eigenvector(loop(), n, 1, lam)
    ring = ring_subdivision_matrix(loop(), n, 3)
    A = np.array([[complex(sp.N(x, 30)) for x in row] for row in ring.exact_matrix().tolist()])
    w = np.exp(2j * np.pi / n)
    before = np.zeros(ring.size, dtype=complex)  # level 0: the eigenvector on the 2-ring (lambda^-1 times level 1), 0 on ring 3
    for i, (s, u, v) in enumerate(ring.labels):
        if 0 < u + v <= 2:
            before[i] = w**s * complex(vec.values[(u, v)].mid()) / complex(lam.mid())
    after = A @ before
    for i, (s, u, v) in enumerate(ring.labels):
        if i:
            assert abs(after[i] - w**s * complex(vec.values[(u, v)].mid())) < 1e-12, (s, u, v)


def test_loop_jacobian_bound_is_below_the_sampled_jacobian():
    """The certified |J| bound is <= the Jacobian of the patches evaluated from the box-spline basis (central differences)."""
    from symdecomp.analysis.characteristic import subpatch_nets
    from symdecomp.schemes.box_spline import BOX_POINTS, regular_patch
    from symdecomp.verify.c1 import _TRIANGLE_MAPS

    patch = regular_patch()
    for n in (3, 7):
        r = c1_test(loop(), n)
        vec = frequency_eigenvector(loop(), n, 1, r.spectral.subdominant.value)
        sampled = math.inf
        for values, (o, e1, e2) in zip(subpatch_nets(vec), _TRIANGLE_MAPS):
            P = [complex(values[(o[0] + a * e1[0] + b * e2[0], o[1] + a * e1[1] + b * e2[1])].mid()) for a, b in BOX_POINTS]

            def f(u, v, P=P):
                return sum(p * b for p, b in zip(P, patch.basis(u, v)))

            h = 1e-6
            for u, v in [(0.1, 0.1), (0.5, 0.2), (0.2, 0.7), (1 / 3, 1 / 3), (0.8, 0.1)]:
                du, dv = (f(u + h, v) - f(u - h, v)) / (2 * h), (f(u, v + h) - f(u, v - h)) / (2 * h)
                sampled = min(sampled, (du.conjugate() * dv).imag)
        assert 0 < r.jacobian_lower_bound <= sampled + 1e-8


@pytest.mark.parametrize("n", [3, 5])
def test_loop_sub_patches_are_the_limit_surface(n):
    """At the level-2 points of ring <= 2 the limit (regular mask 1/2, 1/12 on the twice-refined ring) equals the patches.

    n = 3 included: there the middle triangle's 12 control points name a_2 twice (its corners' 1-rings meet
    across the extraordinary vertex), and the box-spline patch still is the limit surface.
    """
    from symdecomp.analysis.characteristic import subpatch_nets
    from symdecomp.schemes.box_spline import BOX_POINTS, regular_patch
    from symdecomp.schemes.lattice import TRIANGLE
    from symdecomp.verify.c1 import _TRIANGLE_MAPS

    patch = regular_patch()
    assert patch.mask == (R(1, 2), R(1, 12))
    vec = frequency_eigenvector(loop(), n, 1, spectral_conditions(loop(), n).subdominant.value)
    ring = ring_subdivision_matrix(loop(), n, 3)
    A = np.array([[complex(sp.N(x, 30)) for x in row] for row in ring.exact_matrix().tolist()])
    w = np.exp(2j * np.pi / n)
    level1 = np.array([0] + [w**s * complex(vec.values[(u, v)].mid()) for s, u, v in ring.labels[1:]])
    level2 = A @ level1
    index = {label: i for i, label in enumerate(ring.labels)}

    def at(u, v):
        label = TRIANGLE.canonical(0, u, v)
        return level2[0] if label is None else level2[index[(label[0] % n, label[1], label[2])]]

    def limit(u, v):
        return at(u, v) / 2 + sum(at(u + a, v + b) for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, -1), (-1, 1))) / 12

    values = subpatch_nets(vec)

    def patch_at(t, pu, pv):
        o, e1, e2 = _TRIANGLE_MAPS[t]
        P = [complex(values[t][(o[0] + a * e1[0] + b * e2[0], o[1] + a * e1[1] + b * e2[1])].mid()) for a, b in BOX_POINTS]
        return sum(p * b for p, b in zip(P, patch.basis(pu, pv)))

    # (level-2 point, triangle, its parameters there): the inner edge's midpoint and the corners a_0, a_1 at level 1
    for (u, v), t, pu, pv in [((1, 1), 1, 0, 0.5), ((2, 0), 1, 0, 0), ((2, 0), 0, 0, 0), ((0, 2), 1, 0, 1), ((0, 2), 2, 0, 0)]:
        assert abs(limit(u, v) - patch_at(t, pu, pv)) < 1e-13
