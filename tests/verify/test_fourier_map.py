"""BLZ's subdominant eigenvectors in closed form (:mod:`symdecomp.verify.fourier_modes`) and the map from them on a few
faces per k (:mod:`symdecomp.verify.fourier_map`), against the sector's exact matrix and the null-vector route."""

from __future__ import annotations

import dataclasses

import flint
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis.mirror import with_near_edge
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.symbols import theta_k
from symdecomp.verify.c1_mirror_blocks import MAP_METHOD, c1_mirror_blocks
from symdecomp.verify.fourier_map import FOURIER_METHOD, _ModeValues
from symdecomp.verify.fourier_modes import FIELD, WINDOW, sector_modes
from symdecomp.verify.mirror_parts import ball_matrix, mirror_label, sector_matrices
from symdecomp.verify.result import C1Verdict

BLZ = ("catmull-clark-blz", "loop-blz")


def _column(values) -> flint.acb_mat:
    return flint.acb_mat([[x] for x in values])


@pytest.mark.parametrize("name", BLZ)
@pytest.mark.parametrize("k", [WINDOW, 9, 13])
def test_the_closed_form_is_the_pair_of_eigenvectors_of_the_sector_matrix(name, k):
    # v = x + i y: S v = v/2 on the exact 2-ring matrix (Arb, to 1e-25), its refinement the level-1 values, x odd, y even
    scheme = load_scheme(name)
    with flint.ctx.workprec(128):
        sm = sector_matrices(scheme, sd.SharpVertex.boundary(k, scheme.lattice))
        chi = _ModeValues(scheme, k)
        v = [2 * chi[lab] for lab in sm.labels]  # level-1 values on the 2-ring are lambda v
        residual = ball_matrix(sm.matrix.tolist(), sm.weight) * _column(v) - _column([x / 2 for x in v])
        assert all(abs(residual[i, 0]) < 1e-25 for i in range(len(v)))
        fine = ball_matrix(sm.refine.tolist(), sm.weight) * _column(v)
        assert all(abs(fine[i, 0] - chi[lab]) < 1e-25 for i, lab in enumerate(sm.fine_labels))
        index = {lab: i for i, lab in enumerate(sm.labels)}
        mirrored = [v[index[mirror_label(lab, k)]] for lab in sm.labels]
        assert all(abs(m + x.conjugate()) < 1e-25 for m, x in zip(mirrored, v))  # Re odd, Im even
        assert abs(v[index[(1, 1, 0)]] - flint.acb(flint.fmpq(1, k)).exp_pi_i()) < 1e-25  # a_s = omega^s


def test_the_modes_closed_form_is_blz_s_polyline():
    # the 1-ring: a_s = omega^s and b_s = (1 + omega) omega^s, i.e. (A, B) = (1, 2 cos(pi/2k)) with the half-angle phase
    modes = sector_modes(load_scheme("catmull-clark-blz"))
    tau = sp.Symbol("tau", real=True)
    omega = (1 + sp.I * tau) / (1 - sp.I * tau)
    assert sp.simplify(FIELD.to_sympy(modes.coarse[(1, 1)]) - (1 + omega)) == 0
    assert modes.coarse[(1, 0)] == FIELD.one and modes.depth == 0


@pytest.mark.slow
def test_the_standard_rules_have_no_closed_form_modes():
    # lambda_1 is not 1/2 with the standard near-edge rule: only 0 solves the Fourier system (and the blocks fail the
    # tangent condition anyway from k = 5)
    with pytest.raises(NotApplicableError, match="1/2 has no eigenvector of Fourier form"):
        sector_modes(sd.catmull_clark())
    assert c1_mirror_blocks(sd.catmull_clark(), sd.SharpVertex.boundary(100, "quad")).verdict is C1Verdict.NOT_C1


@pytest.mark.slow
@pytest.mark.parametrize("name", BLZ)
def test_the_modes_route_reaches_the_null_vector_routes_verdict(name, monkeypatch):
    scheme = load_scheme(name)
    for k in range(WINDOW, 13):
        vertex = sd.SharpVertex.boundary(k, scheme.lattice)
        new = c1_mirror_blocks(scheme, vertex)
        with monkeypatch.context() as m:
            m.setattr("symdecomp.verify.c1_mirror_blocks.applies", lambda *args: False)
            old = c1_mirror_blocks(scheme, vertex)
        assert new.method == FOURIER_METHOD and old.method == MAP_METHOD
        assert new.verdict is old.verdict is C1Verdict.C1
        assert new.lambdas == pytest.approx(old.lambdas, abs=1e-15) and new.lambdas == pytest.approx([0.5, 0.5], abs=1e-15)
        assert new.opening == pytest.approx(old.opening, abs=1e-9)


def test_both_sides_of_a_crease_are_certified():
    scheme = load_scheme("loop-blz")
    r = c1_mirror_blocks(scheme, sd.SharpVertex.crease(300, 9, scheme.lattice))
    assert r.verdict is C1Verdict.C1 and r.method == FOURIER_METHOD and r.reason.count("closed-form modes") == 2


@pytest.mark.slow
def test_a_mutated_near_edge_weight_is_neither_a_closed_form_nor_c1():
    # 1/32 more on the edge's far end: the sine block's eigenvalue leaves 1/2, the Fourier system has only 0, and the
    # verdict at 100 faces flips from C1
    base = load_scheme("catmull-clark-blz")
    c = sp.cos(theta_k)
    bent = dataclasses.replace(base, name="bent", sharp=with_near_edge(base, sp.Rational(3, 8) + c / 4 - sp.Rational(1, 32),
                                                                        sp.Rational(3, 8) - c / 4 + sp.Rational(1, 32)))
    with pytest.raises(NotApplicableError):
        sector_modes(bent)
    assert c1_mirror_blocks(base, sd.SharpVertex.boundary(100, "quad")).verdict is C1Verdict.C1
    assert c1_mirror_blocks(bent, sd.SharpVertex.boundary(100, "quad")).verdict is not C1Verdict.C1


def test_a_face_that_reads_the_rays_is_not_taken_for_a_rotation(monkeypatch):
    # the rotation argument needs face g's nets to read Fourier values only: told that the nets read no face to either
    # side, the route takes a face next to the values of their own for g, the check sees it and the route refuses
    monkeypatch.setattr("symdecomp.verify.fourier_map.REACH", 0)
    r = c1_mirror_blocks(load_scheme("catmull-clark-blz"), sd.SharpVertex.boundary(100, "quad"))
    assert r.verdict is C1Verdict.UNDECIDED and "reads values next to a sharp ray" in r.reason
