"""Reif's test: the Bernstein-Bezier machinery, the characteristic map, and verdicts that must come out right."""

import json

import flint
import pytest
import sympy as sp

from symdecomp.analysis.characteristic import LEVEL1_LABELS, check_applicable, frequency_eigenvector, omega_ball
from symdecomp.analysis.defective import jordan_vertex_weights
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import ring_mesh, ring_mesh_labels
from symdecomp.schemes.refinement import refine
from symdecomp.schemes.scheme import Scheme, Stencil, catmull_clark
from symdecomp.symbols import alpha, beta
from symdecomp.symbols import n as N
from symdecomp.verify.bezier import certify_sign, curve_angle, jacobian_net, split_net
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_spectrum import spectral_conditions
from symdecomp.verify.result import C1Verdict

R = sp.Rational


def standard_at_regular(weight, standard, regular, valences):
    """``weight`` at each of ``valences``, ``standard`` at the ``regular`` valence: ``weight`` plus the difference times
    the polynomial in n that is 1 at ``regular`` and 0 at every one of ``valences``.

    A scheme is one set of rules for the whole mesh: every regular vertex uses the vertex rule at the regular
    valence, so a scheme changed at the extraordinary vertex only keeps the standard weights there.
    """
    weight, standard = sp.sympify(weight, strict=True), sp.sympify(standard, strict=True)
    lagrange = sp.Mul(*[(N - v) / sp.Integer(regular - v) for v in valences])
    return weight + (standard - weight.subs(N, regular)) * lagrange


def tuned(a, b, *valences):
    """Catmull-Clark with vertex weights ``(a, b)`` at ``valences``, standard at the regular valence 4."""
    return catmull_clark(standard_at_regular(a, R(3, 2) / N**2, 4, valences), standard_at_regular(b, R(1, 4) / N**2, 4, valences))


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
    scheme = tuned(0, 0, 3)
    r = c1_test(scheme, 3)
    assert r.verdict == "not-c1" and "frequency 0" in r.reason
    dom = r.spectral.subdominant
    assert dom.frequency == 0 and (dom.value - (3 + flint.arb(5).sqrt()) / 8).contains(0)
    assert c1_test(catmull_clark(), 3).verdict == "c1"  # the vertex weights flip the verdict


def test_the_test_and_its_spectral_part_speak_one_verdict_vocabulary():
    broken, standard = c1_test(tuned(0, 0, 3), 3), c1_test(catmull_clark(), 3)
    assert (broken.verdict, broken.spectral.status) == (C1Verdict.NOT_C1, C1Verdict.NOT_C1)  # fails at frequency 0
    assert (standard.verdict, standard.spectral.status) == (C1Verdict.C1, C1Verdict.C1)
    assert [json.loads(json.dumps(r.as_json()))["verdict"] for r in (broken, standard)] == ["not-c1", "c1"]


def test_defective_subdominant_eigenvalue_is_not_c1():
    free = catmull_clark(alpha, beta)
    weights = jordan_vertex_weights(free, 5, R(3, 4))
    scheme = tuned(weights[alpha], weights[beta], 5)
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
    assert r.spectral.status is C1Verdict.C1 and r.frequency == 2
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
    rows = json.loads(capsys.readouterr().out)["rows"]
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
    scheme = catmull_clark(R(3, 2) / N**2 + sp.sqrt(2) * (N - 4) / 100, R(1, 4) / N**2)
    with pytest.raises(InvalidSchemeError, match=r"needs rational weights at each valence \(or rational in cos\(2 pi k/n\)\); at n = 5"):
        c1_test(scheme, 5)


def test_an_exact_eigenvalue_minus_one_is_not_c1_not_undecided():
    """alpha = 1/10, beta = 1/4 at n = 5: the Eq. 43 block has the exact eigenvalue -1, so 1 is not strictly dominant."""
    scheme = tuned(R(1, 10), R(1, 4), 5)
    from symdecomp.analysis.frequency import recursion_matrix

    assert sp.Matrix(recursion_matrix(scheme, 5)).eigenvals() == {1: 1, -1: 1, 0: 1}
    r = c1_test(scheme, 5)
    assert r.verdict == "not-c1" and "frequency 0" in r.reason and "not smaller than 1" in r.reason
    assert (r.spectral.subdominant.value + 1).contains(0) and r.spectral.subdominant.value.imag.contains(0)


def test_an_exact_tie_of_frequencies_0_and_1_is_multiplicity_3_not_undecided():
    """alpha = 0, beta = 1/16 at n = 3: (9 +- sqrt 17)/32 is a root at frequencies 0, 1 and 2 (triple), so not C1.

    More precision never separates equal eigenvalues; the tie is shown exactly (in Q(e^{2 pi i / n})).
    """
    from symdecomp.schemes.scheme import subdivision_matrix

    scheme = tuned(0, R(1, 16), 3)
    x = sp.Symbol("x")
    poly = sp.Matrix(subdivision_matrix(scheme, 3)).charpoly(x).as_expr()
    assert sp.expand(poly - (x - 1) * (x**2 - R(9, 16) * x + R(1, 16)) ** 3) == 0
    r = c1_test(scheme, 3)
    assert r.verdict == "not-c1" and "multiplicity 3" in r.reason and "frequencies 0, 1" in r.reason
    assert (r.spectral.subdominant.value - (9 + flint.arb(17).sqrt()) / 32).contains(0)
    # a nearby beta separates the eigenvalues, and the test decides by the ordinary route
    assert c1_test(tuned(0, R(1, 15), 3), 3).verdict in ("c1", "not-c1")
    assert "multiplicity 3" not in c1_test(tuned(0, R(1, 15), 3), 3).reason


def _two_ring_matrix(scheme, n):
    """The ``(6n + 1) x (6n + 1)`` 2-ring matrix (floats) by refining the whole 2-ring mesh of unit vectors.

    Independent of the frequency blocks: every level-1 point is read off :func:`refine` with
    Catmull-Clark's rules, except the new ``O``, read off ``refine`` with ``scheme``'s rules
    (the C1 test applies ``scheme``'s vertex rule at ``O`` only).
    """
    from fractions import Fraction

    import numpy as np

    labels = ring_mesh_labels(n, 2)
    ident = {lab: i for i, lab in enumerate(labels)}
    size = len(labels)
    mesh = ring_mesh(n, 2, lambda s, u, v: tuple(Fraction(int(ident[(s, u, v)] == k)) for k in range(size)))
    step = refine(mesh, catmull_clark())

    def old(s, u, v):
        s %= n
        return 0 if (u, v) == (0, 0) else ident[((s + 1) % n, v, 0)] if u == 0 else ident[(s, u, v)]

    rows = {}
    for s in range(n):
        rows[ident[(s, 1, 0)]] = step.edge_point[frozenset((0, old(s, 1, 0)))]
        rows[ident[(s, 1, 1)]] = step.face_point[s * 4]
        rows[ident[(s, 1, 2)]] = step.edge_point[frozenset((old(s, 0, 1), old(s, 1, 1)))]
        rows[ident[(s, 2, 0)]] = step.vertex_point[old(s, 1, 0)]
        rows[ident[(s, 2, 1)]] = step.edge_point[frozenset((old(s, 1, 0), old(s, 1, 1)))]
        rows[ident[(s, 2, 2)]] = step.vertex_point[old(s, 1, 1)]
    A = [[float(x) for x in step.mesh.values[rows[i]]] if i else None for i in range(size)]
    at_o = refine(mesh, scheme)
    A[0] = [float(x) for x in at_o.mesh.values[at_o.vertex_point[0]]]
    return np.array(A)


@pytest.mark.parametrize(
    "alpha_beta, n",
    [(None, 3), (None, 5), (None, 6), (None, 8), ((R(-1, 4), R(1, 2)), 5), ((R(-1, 4), R(1, 4)), 6)],
)
def test_the_certified_spectrum_is_the_whole_two_ring_spectrum(alpha_beta, n):
    """lambda, its multiplicity 2 and the bound of every other eigenvalue hold for the full (6n+1) matrix (numpy)."""
    import numpy as np

    scheme = tuned(*alpha_beta, n) if alpha_beta else catmull_clark()
    A = _two_ring_matrix(scheme, n)
    assert A.shape == (6 * n + 1, 6 * n + 1) and np.allclose(A.sum(axis=1), 1)
    moduli = sorted(abs(np.linalg.eigvals(A)), reverse=True)
    r = c1_test(scheme, n)
    assert r.verdict == "c1", r.reason
    lam = float(r.spectral.subdominant.value.real.mid())
    assert abs(moduli[0] - 1) < 1e-9 and moduli[1] < 1 - 1e-6  # 1 simple
    assert abs(moduli[1] - lam) < 1e-9 and abs(moduli[2] - lam) < 1e-9  # lambda twice
    assert moduli[3] <= r.spectral.second + 1e-9 and r.spectral.gap <= lam - moduli[3] + 1e-9  # every other one


def _triangular_scheme():
    """At n = 3 the edge rule at O has no b weights, so M_1 is lower triangular and lambda = 7/16 is its b-b entry."""
    cc = catmull_clark()
    e, t = R(5, 8) - N / 16, N / 16 - R(3, 16)
    edge = Stencil.from_weights(e, {-1: R(1, 16), 0: e, 1: R(1, 16)}, {-1: t, 0: t})
    face = Stencil.from_weights(N / 16, {0: N / 16, 1: N / 16}, {0: 1 - 3 * N / 16})
    return Scheme("triangular", edge, face, cc.vertex_rule)


def test_an_eigenvector_vanishing_on_the_a_i_gets_a_verdict_not_an_error():
    """lambda's eigenvector is 0 at every a_i (normalised at b_0 instead); before, 'could not be normalised'."""
    from symdecomp.analysis.frequency import per_frequency_matrix_at
    from symdecomp.verify.c1 import characteristic_nets

    scheme = _triangular_scheme()
    check_applicable(scheme)
    M = per_frequency_matrix_at(scheme, 3, 1).subs(N, 3)
    assert M[0, 1] == 0 and M[1, 1] == R(7, 16) and sp.expand_complex(M[0, 0] - R(3, 8)) == 0
    r = c1_test(scheme, 3)
    assert r.verdict == "c1" and r.frequency == 1 and r.winding_number == 1, r.reason
    assert (r.spectral.subdominant.value - flint.fmpq(7, 16)).contains(0)
    nets, vec = characteristic_nets(scheme, 3)
    assert vec.values[(1, 0)].contains(0) and (vec.values[(1, 1)] - flint.fmpq(7, 16)).contains(0)  # lambda (a_0, b_0)
    # the certified bound is a lower bound of the Jacobian sampled on each sub-patch
    from symdecomp.verify.bezier import jacobian_net

    grid = [i / 8 for i in range(9)]
    sampled = min(_bernstein(jacobian_net(x, y), u, v) for x, y in nets for u in grid for v in grid)
    assert 0 < r.jacobian_lower_bound <= sampled


def test_an_undecided_valence_makes_the_claim_undecided_not_an_error(monkeypatch):
    """The claim's status follows the test's verdict: undecided stays undecided (never 'error')."""
    import dataclasses

    from symdecomp.claims import Status
    from symdecomp.claims import s5_1_tangent_c1 as module

    real = module.c1_test

    def undecided_at_5(scheme, n):
        r = real(scheme, n)
        return dataclasses.replace(r, verdict="undecided", reason="not separated") if n == 5 else r

    monkeypatch.setattr(module, "c1_test", undecided_at_5)
    result = module._c1_reif(catmull_clark())
    assert result.status is Status.UNDECIDED and "n = 5" in str(result.evidence)


@pytest.mark.parametrize("name", ["catmull-clark", "loop"])
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_the_block_roots_are_the_one_eigenvalue_type_and_count_the_one_ring(name, n):
    """The roots of the frequency blocks (the one type, Eigenvalue) with the eigenvalue 1 are the whole 1-ring spectrum:
    their copies add up to the size of the 1-ring matrix, each frequency k = 0..n-1 holding one block's roots."""
    from collections import Counter

    from symdecomp.analysis.eigenvalue import Eigenvalue
    from symdecomp.schemes.files import load_scheme
    from symdecomp.schemes.rings import ring_subdivision_matrix
    from symdecomp.verify.c1_spectrum import frequency_zero_eigenvalues, other_frequency_eigenvalues

    scheme = load_scheme(name)
    with flint.ctx.workprec(128):
        eigen = frequency_zero_eigenvalues(scheme, n)[0] + other_frequency_eigenvalues(scheme, n, outer=False)[0]
    size = len(ring_subdivision_matrix(scheme, n, 1).labels)  # the 1-ring's points, from the mesh's rules
    assert all(type(e) is Eigenvalue for e in eigen) and 1 + sum(e.multiplicity for e in eigen) == size
    copies = Counter(k for e in eigen for k in e.frequencies for _ in range(e.multiplicity // len(e.frequencies)))
    block = (size - 1) // n  # the 1-ring points per sector: each frequency's block has that many roots
    assert copies == {k: block for k in range(n)}
