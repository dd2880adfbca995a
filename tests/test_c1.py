"""Reif's test: the Bernstein-Bezier machinery, the characteristic map, and verdicts that must come out right."""

import json

import flint
import pytest
import sympy as sp

from symdecomp.analysis.characteristic import LEVEL1_LABELS, check_applicable, frequency_eigenvector, omega_ball
from symdecomp.analysis.defective import jordan_vertex_weights
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import refine, ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import Scheme, Stencil, catmull_clark
from symdecomp.symbols import alpha, beta
from symdecomp.symbols import n as N
from symdecomp.verify.bezier import certify_sign, curve_angle, jacobian_net, split_net
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_spectrum import spectral_conditions

R = sp.Rational


def _net(poly, degree=3):
    """Bernstein coefficients of ``sum c u^p v^q`` (``poly = {(p, q): c}``): ``u^p`` has ``C(i, p) / C(m, p)``."""
    from math import comb

    def coeff(i, k):
        return sum(flint.fmpq(c) * flint.fmpq(comb(i, p) * comb(k, q), comb(degree, p) * comb(degree, q)) for (p, q), c in poly.items())

    return [[flint.arb(coeff(i, k)) for k in range(degree + 1)] for i in range(degree + 1)]


def _bernstein(net, u, v):
    """The net's polynomial at a float point."""
    from math import comb

    m, k = len(net) - 1, len(net[0]) - 1
    return sum(
        comb(m, i) * u**i * (1 - u) ** (m - i) * comb(k, j) * v**j * (1 - v) ** (k - j) * float(net[i][j].mid())
        for i in range(m + 1) for j in range(k + 1)
    )


POINTS = [(0.1, 0.7), (0.5, 0.5), (0.93, 0.2), (0.0, 1.0), (0.37, 0.01)]


def test_jacobian_net_is_the_jacobian_in_bernstein_form():
    # (x, y) = (u + u v, v + u^2): J = (1 + v) * 1 - u * 2u = 1 + v - 2u^2
    J = jacobian_net(_net({(1, 0): 1, (1, 1): 1}), _net({(0, 1): 1, (2, 0): 1}))
    assert len(J) == 6 and len(J[0]) == 6
    for u, v in POINTS:
        assert abs(_bernstein(J, u, v) - (1 + v - 2 * u * u)) < 1e-13


def test_identity_map_has_unit_jacobian_and_a_fold_is_found():
    x, y = _net({(1, 0): 1}), _net({(0, 1): 1})
    cert = certify_sign([jacobian_net(x, y)])
    assert cert.status == "positive" and 1 - 1e-12 < cert.lower_bound <= 1 and cert.depth == 0
    fold = certify_sign([jacobian_net(_net({(2, 0): 4, (1, 0): -4, (0, 0): 1}), y)])  # J = 4(2u - 1): changes sign at u = 1/2
    assert fold.status == "changes"


def test_subdivision_decides_what_the_whole_net_cannot():
    # x = u^3 - u^2 + 2u/5, y = v: J = 3u^2 - 2u + 2/5 > 0 (minimum 1/15), yet a Bernstein coefficient is negative
    x = _net({(3, 0): 1, (2, 0): -1, (1, 0): flint.fmpq(2, 5)})
    y = _net({(0, 1): 1})
    J = jacobian_net(x, y)
    assert any(c < 0 for row in J for c in row)
    cert = certify_sign([J], max_depth=6)
    assert cert.status == "positive" and cert.depth > 0 and 0 < cert.lower_bound <= 1 / 15
    assert certify_sign([J], max_depth=0).status == "undecided"


def test_split_net_is_de_casteljau():
    net = _net({(2, 1): 1, (0, 3): 3, (1, 0): -1})
    for side_u, side_v, sub in split_net(net):
        for u, v in POINTS:
            assert abs(_bernstein(sub, u, v) - _bernstein(net, (u + side_u) / 2, (v + side_v) / 2)) < 1e-13


def test_curve_angle_of_a_quarter_turn():
    pts = [flint.acb(1), flint.acb(1, flint.fmpq(1, 2)), flint.acb(flint.fmpq(1, 2), 1), flint.acb(0, 1)]
    assert (curve_angle(pts) - flint.arb.pi() / 2).contains(0)
    assert curve_angle([flint.acb(1), flint.acb(-1, 1), flint.acb(-1, -1), flint.acb(1, 0)]) is not None


def test_characteristic_map_of_the_regular_grid_is_the_grid():
    vec = frequency_eigenvector(catmull_clark(), 4, 1, flint.acb(flint.fmpq(1, 2)))
    for u, v in LEVEL1_LABELS:
        assert (vec.values[(u, v)] - flint.acb(u, v) / 2).contains(0)


def test_ring_values_agree_with_refining_the_mesh():
    """The level-1 points from the per-frequency stencils equal those of refining the whole 2-ring mesh."""
    cc, n = catmull_clark(), 5
    lam = spectral_conditions(cc, n).subdominant.value
    vec = frequency_eigenvector(cc, n, 1, lam)

    def point(s, u, v):
        z = omega_ball(n, s) * vec.values[(u, v)] / lam if (u, v) != (0, 0) else flint.acb(0)
        return (float(z.real.mid()), float(z.imag.mid()))

    mesh = ring_mesh(n, 2, point)
    ident = {lab: i for i, lab in enumerate(ring_mesh_labels(n, 2))}
    step = refine(mesh, cc)
    for s in range(n):
        w = omega_ball(n, s)
        a, a2 = ident[(s, 1, 0)], ident[(s, 2, 0)]
        checks = {
            (1, 0): step.edge_point[frozenset((0, a))],
            (2, 0): step.vertex_point[a],
            (3, 0): step.edge_point[frozenset((a, a2))],
            (3, 1): step.face_point[s * 4 + 2],
            (2, 2): step.vertex_point[ident[(s, 1, 1)]],
        }
        for label, new in checks.items():
            z = w * vec.values[label]
            x, y = step.mesh.values[new]
            assert abs(x - float(z.real.mid())) < 1e-12 and abs(y - float(z.imag.mid())) < 1e-12


def test_catmull_clark_is_c1_for_valences_3_to_16():
    cc = catmull_clark()
    for n in range(3, 17):
        r = c1_test(cc, n)
        assert r.verdict == "c1", (n, r.reason)
        assert r.winding_number == 1 and r.jacobian_sign == 1 and r.jacobian_lower_bound > 0
        assert r.spectral.gap > 0 and r.frequency == 1


def test_regular_valence_numbers():
    r = c1_test(catmull_clark(), 4)
    assert (r.spectral.subdominant.value - flint.fmpq(1, 2)).contains(0)
    assert abs(r.spectral.gap - 0.25) < 1e-12  # 1/2 against 1/4
    assert abs(r.jacobian_lower_bound - 0.25) < 1e-12  # the map is (u, v)/2 on level-1 faces


def test_alpha_beta_zero_at_valence_3_is_not_c1_and_names_frequency_0():
    scheme = catmull_clark(0, 0)
    r = c1_test(scheme, 3)
    assert r.verdict == "not-c1" and "frequency 0" in r.reason
    dom = r.spectral.subdominant
    assert dom.frequency == 0 and (dom.value - (3 + flint.arb(5).sqrt()) / 8).contains(0)
    assert c1_test(catmull_clark(), 3).verdict == "c1"  # the vertex weights flip the verdict


def test_defective_subdominant_eigenvalue_is_not_c1():
    free = catmull_clark(alpha, beta)
    scheme = free.substitute(jordan_vertex_weights(free, 5, R(3, 4)))
    r = c1_test(scheme, 5)
    assert r.verdict == "not-c1" and "Jordan block" in r.reason
    assert r.spectral.subdominant.defective and (r.spectral.subdominant.value - flint.fmpq(3, 4)).contains(0)


def _frequency_two_scheme():
    """Catmull-Clark with the edge rule at O changed at n = 5 (centre and a_0 weights 5/8), unchanged at n = 4."""
    cc = catmull_clark()
    e = R(3, 8) + R(1, 4) * (N - 4)
    s = (1 - 2 * e) / 4
    edge = Stencil.from_weights(e, {-1: s, 0: e, 1: s}, {-1: s, 0: s})
    return Scheme("frequency two", edge, cc.face_rule, cc.vertex_rule)


def test_frequency_two_characteristic_map_winds_twice():
    r = c1_test(_frequency_two_scheme(), 5)
    assert r.spectral.status == "ok" and r.frequency == 2
    assert r.jacobian_sign is not None and r.winding_number == 2
    assert r.verdict == "not-c1" and "winds 2 times" in r.reason


def test_scheme_whose_regular_rules_differ_is_refused_in_one_line():
    cc = catmull_clark()
    edge = Stencil.from_weights(R(1, 2), {0: R(1, 2)}, {})
    with pytest.raises(InvalidSchemeError, match="not Catmull-Clark's"):
        check_applicable(Scheme("other", edge, cc.face_rule, cc.vertex_rule))
    with pytest.raises(InvalidSchemeError, match="free parameters"):
        check_applicable(catmull_clark(alpha, beta))


def test_command_line_json_and_exit_status(capsys):
    assert main(["c1", "--n", "3:5", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [row["n"] for row in rows] == [3, 4, 5]
    for row in rows:
        assert row["verdict"] == "c1" and row["winding_number"] == 1 and row["gap"] > 0 and row["jacobian_lower_bound"] > 0
        assert {"reason", "method", "lambda"} <= set(row)
    assert main(["c1", "--n", "3"]) == 0
    assert "n =   3: C1 certified" in capsys.readouterr().out


def test_command_line_rejects_a_bad_depth_in_one_line(capsys):
    assert main(["c1", "--n", "3", "--depth", "13"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "argument --depth: expected an integer >= 0 and <= 12, got 13" in err[0]


def test_complex_subdominant_eigenvalue_is_not_c1():
    """Edge rule at O with the a_{i+-1} weights 1/16 + 3(n - 4)/16 (Catmull-Clark's at n = 4): at n = 5 M_1 has complex roots."""
    cc = catmull_clark()
    t = R(1, 16) + R(3, 16) * (N - 4)
    b = (1 - 2 * R(3, 8) - 2 * t) / 2
    edge = Stencil.from_weights(R(3, 8), {-1: t, 0: R(3, 8), 1: t}, {-1: b, 0: b})
    scheme = Scheme("complex", edge, cc.face_rule, cc.vertex_rule)
    check_applicable(scheme)
    r = c1_test(scheme, 5)
    assert r.verdict == "not-c1" and "not real" in r.reason and r.spectral.subdominant.frequency == 1
    lam = r.spectral.subdominant.value
    # the roots of x^2 - tr x + det for M_1 at omega_5: tr and det from the exact matrix, numerically
    import numpy as np

    from symdecomp.analysis.frequency import per_frequency_matrix_at

    exact = per_frequency_matrix_at(scheme, 5, 1).subs(N, 5)  # the weights depend on n
    M = np.array([[complex(sp.N(x, 30)) for x in row] for row in exact.tolist()])
    roots = np.linalg.eigvals(M)
    assert min(abs(roots - complex(float(lam.real.mid()), float(lam.imag.mid())))) < 1e-12
    assert abs(abs(roots[0]) - abs(roots[1])) < 1e-12 and abs(roots[0].imag) > 0.2


def test_subdominant_eigenvalue_is_the_closed_form_of_eq_34():
    """The per-frequency Arb route agrees with the paper's closed form at j = 1 (c = cos(pi/n)), to the ball's width."""
    from symdecomp.analysis.tangent import tangent_eigenvalues

    dominant = tangent_eigenvalues(catmull_clark()).dominant
    c = sorted(dominant.free_symbols, key=str)[0]
    for n in range(3, 17):
        lam = spectral_conditions(catmull_clark(), n).subdominant.value
        exact = dominant.subs(c, sp.cos(sp.pi / n))
        assert lam.imag.contains(0) and abs(float(lam.real.mid()) - float(sp.N(exact, 30))) < 1e-13


def test_irrational_weights_get_one_line_not_a_traceback():
    scheme = catmull_clark(R(3, 2) / N**2 + sp.sqrt(2) / 100, R(1, 4) / N**2)
    with pytest.raises(InvalidSchemeError, match="needs rational weights at each valence; at n = 5"):
        c1_test(scheme, 5)
