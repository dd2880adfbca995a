"""Reif's test at large valences: the route that is linear in n per valence agrees with the per-frequency norm bounds.

The outer blocks (the regular rules) have one characteristic polynomial at every frequency, so their exact
eigenvalues replace a norm bound per frequency; the blocks compute only the powers of omega their stencils use.
The norm-bound route stays here as the independent confirmation.
"""

import json

import flint
import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.characteristic import frequency_block, outer_charpoly, outer_radius, outer_row_sum, ring_layout
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.cli import main
from symdecomp.schemes.loop import loop
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify import c1_spectrum
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.result import C1Verdict
from tests.verify.test_c1 import standard_at_regular, tuned

R = sp.Rational


def _mid(z: flint.acb) -> complex:
    return complex(float(z.real.mid()), float(z.imag.mid()))


def _eigenvalues(B: flint.acb_mat, lo: int, hi: int) -> np.ndarray:
    return np.linalg.eigvals(np.array([[_mid(B[r, c]) for c in range(lo, hi)] for r in range(lo, hi)]))


@pytest.mark.parametrize("mesh, roots", [("quad", [R(1, 8), R(1, 16), R(1, 32), R(1, 64)]), ("triangle", [R(1, 8), R(1, 16)])])
def test_the_outer_block_has_the_same_eigenvalues_at_every_frequency(mesh, roots):
    """outer_charpoly is free of omega: its roots are S_j's eigenvalues for every j of every n (numpy on the Arb blocks)."""
    x = sp.Symbol("x")
    coeffs = outer_charpoly(mesh)
    assert sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in coeffs], x) == sp.Poly(sp.Mul(*[x - r for r in roots]), x)
    assert (outer_radius(mesh) - flint.fmpq(1, 8)).contains(0) and outer_radius(mesh).rad() < 1e-15
    scheme = catmull_clark() if mesh == "quad" else loop()
    layout = ring_layout(mesh)
    for n in (3, 7, 50):
        for j in range(n):
            found = np.sort_complex(_eigenvalues(frequency_block(scheme, n, j), layout.one_ring, layout.two_ring))
            assert np.allclose(found, sorted(float(r) for r in roots), atol=1e-7), (n, j, found)


@pytest.mark.parametrize("scheme, n", [(catmull_clark(), 5), (loop(), 7)])
def test_the_outer_eigenvalues_are_in_the_full_matrix_n_times(scheme, n):
    """Independent of the frequency blocks: the refined 2-ring matrix (no block structure) has each root n times."""
    M = ring_subdivision_matrix(scheme, n, 2).exact_matrix()
    eigenvalues = np.linalg.eigvals(np.array([[float(sp.N(v, 30)) for v in row] for row in M.tolist()]))
    x = sp.Symbol("x")
    roots = sp.roots(sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in outer_charpoly(scheme.lattice)], x), x)
    assert all(r.is_Rational and r > 0 for r in roots)
    for root in roots:
        # a defective eigenvalue of multiplicity n spreads numerically like eps^(1/k): count within a loose radius
        assert sum(abs(eigenvalues - float(root)) < 2e-3) >= n, root


@pytest.mark.parametrize("scheme, n", [(catmull_clark(), 50), (catmull_clark(), 37), (loop(), 41)])
def test_frequency_blocks_hold_the_exact_one_ring_matrices(scheme, n):
    """The 1-ring part of B_j (only the powers of omega the stencils use) contains the exact M(omega_n^j), every j."""
    M = one_ring_matrices(scheme)[0]
    k = ring_layout(scheme.lattice).one_ring
    for j in range(1, n):
        exact = M.subs(N, n).subs(OMEGA, sp.exp(2 * sp.pi * sp.I * sp.Rational(j, n)))
        B = frequency_block(scheme, n, j, rows=k)
        for r in range(k):
            for c in range(k):
                value = complex(sp.N(exact[r, c], 30))
                assert abs(_mid(B[r, c]) - value) < 1e-14 and B[r, c].rad() < 1e-15


def _norm_route(monkeypatch):
    """The per-frequency route: every S_j bounded by ||S_j^k||^(1/k) on the whole block, as before."""
    monkeypatch.setattr(c1_spectrum, "outer_radius", lambda mesh: None)


CASES = [
    (catmull_clark(), (3, 4, 5, 7, 16, 33)),
    (loop(), (3, 4, 5, 6, 9, 16, 33)),
    (tuned(R(-1, 4), R(1, 2), 5), (5,)),
    (tuned(R(-1, 4), R(1, 4), 6), (6,)),
]


@pytest.mark.parametrize("scheme, valences", CASES, ids=["catmull-clark", "loop", "tuned-5", "tuned-6"])
def test_the_exact_outer_route_agrees_with_the_norm_bounds(scheme, valences, monkeypatch):
    """Verdict, lambda, frequency, gap, depth, winding and Jacobian bound are the same on both routes."""
    new = {n: c1_test(scheme, n) for n in valences}
    _norm_route(monkeypatch)
    for n in valences:
        old = c1_test(scheme, n)
        a, b = new[n].as_json(), old.as_json()
        for key in ("verdict", "lambda", "frequency", "gap", "subdivision_depth", "winding_number", "jacobian_sign",
                    "jacobian_lower_bound"):
            assert a[key] == b[key], (n, key, a[key], b[key])
        assert a["verdict"] == "c1" and new[n].spectral.second == old.spectral.second
        bounds = c1_spectrum.other_frequency_eigenvalues(scheme, n)[1]
        assert [j for j, _ in bounds] == list(range(n // 2 + 1))
        assert all(1 / 8 <= float(b.upper()) <= float(outer_row_sum(scheme.lattice)) + 1e-15 for _, b in bounds)


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=["catmull-clark", "loop"])
def test_large_valences_compute_no_norm_bound(scheme, monkeypatch):
    """At n = 64 a 1-ring eigenvalue after lambda exceeds the outer row sum (CC 15/64, Loop 3/16), which bounds every norm
    bound: the gap is the same without them, so none is computed (the per-frequency route would cost n/2 + 1 blocks)."""
    assert outer_row_sum(scheme.lattice) == (flint.fmpq(15, 64) if scheme.lattice.name == "quad" else flint.fmpq(3, 16))
    expected = c1_test(scheme, 64).as_json()

    def refuse(*args):
        raise AssertionError("outer_bounds called")

    monkeypatch.setattr(c1_spectrum, "outer_bounds", refuse)
    assert c1_test(scheme, 64).as_json() == expected
    with pytest.raises(AssertionError, match="outer_bounds called"):
        c1_test(scheme, 3)  # at n = 3 the gap is measured against a norm bound (Loop: 1/4 - 0.1475 = 0.1025)


def _small_scheme():
    """At n = 5 every 1-ring eigenvalue after 1 is 1/10 or 1/20 (new a_i = 9/10 O + a_i/10, b_i = 19/20 O + b_i/20, O fixed);
    Catmull-Clark at the regular valence 4."""
    cc = catmull_clark()

    def at5(standard, value):
        return standard + (value - standard) * (N - 4)

    edge = Stencil.from_weights(at5(R(3, 8), R(9, 10)), {-1: at5(R(1, 16), 0), 0: at5(R(3, 8), R(1, 10)), 1: at5(R(1, 16), 0)},
                                {-1: at5(R(1, 16), 0), 0: at5(R(1, 16), 0)})
    face = Stencil.from_weights(at5(R(1, 4), R(19, 20)), {0: at5(R(1, 4), 0), 1: at5(R(1, 4), 0)}, {0: at5(R(1, 4), R(1, 20))})
    vertex = VertexRule.affine(standard_at_regular(0, cc.vertex_rule.each_a, 4, (5,)), standard_at_regular(0, cc.vertex_rule.each_b, 4, (5,)))
    return Scheme("small", edge, face, vertex)


def test_an_outer_eigenvalue_above_every_one_ring_eigenvalue_is_not_c1(monkeypatch):
    """The outer eigenvalue 1/8 at all 5 frequencies exceeds lambda = 1/10: multiplicity >= 5, not C1 (before: undecided)."""
    scheme = _small_scheme()
    M = one_ring_matrices(scheme)[0].subs(N, 5)
    assert sp.simplify(M - sp.diag(R(1, 10), R(1, 20))) == sp.zeros(2, 2)
    r = c1_test(scheme, 5)
    assert r.verdict is C1Verdict.NOT_C1 and "at every frequency (multiplicity at least 5)" in r.reason, r.reason
    _norm_route(monkeypatch)
    old = c1_test(scheme, 5)
    assert old.verdict is C1Verdict.UNDECIDED and "bounded only by" in old.reason


def test_the_command_line_takes_the_new_valence_bound(capsys):
    """Issue 24: a c1 sweep over n = 3..10,000 (on a Dask cluster when one machine is not enough) is accepted."""
    assert main(["c1", "--n", "10000", "--json"]) == 0
    (row,) = json.loads(capsys.readouterr().out)["rows"]
    assert row["n"] == 10000 and row["verdict"] == "c1" and 0 < row["gap"] < 1e-6 and row["subdivision_depth"] == 0
    assert main(["c1", "--n", "10001"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--n" in err[0] and "10000" in err[0]
