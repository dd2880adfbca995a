"""C1 at BLZ's corners from the Jordan block of 1/2 (c1_corner_jordan).

Recomputed here with sympy on the sector's exact matrix (rational at k = 2, 3): the chain identity ``(S - I/2) g = e``
and the power formula ``S^m g = 2^-m g + m 2^(1-m) e`` reduce to zero; the level-``m`` net's normal grows like
``2 m (c_e' x c_g)`` times the pair's discrete Jacobian, exactly; the certified map is oriented as a half-plane (``f_e``
of one sign inside, the rays' images opposite).
"""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.verify.c1_corner_jordan import JORDAN_METHOD, chain_vectors, jordan_sector, jordan_spectrum
from symdecomp.verify.c1_mirror_blocks import c1_mirror_blocks
from symdecomp.verify.corner_jordan import jordan_chain
from symdecomp.verify.result import C1Verdict

NAMES = ("catmull-clark-blz", "loop-blz")


def _rational(vector) -> sp.Matrix:
    """An exact vector over ``Q`` (the field's modulus is ``x``: every entry a constant) as a sympy column."""
    out = []
    for x in vector:
        assert x.poly.degree() <= 0
        q = x.poly[0]
        out.append(sp.Rational(int(q.p), int(q.q)))
    return sp.Matrix(out)


def _on_ray(label, k: int) -> bool:
    return label == ORIGIN or (label[2] == 0 and label[0] in (0, k))


def _exact_chain(name: str, k: int):
    found = jordan_chain(load_scheme(name), k)
    assert found.sm.weight is None and found.chain is not None
    S = sp.Matrix(found.sm.matrix)
    g, e = (_rational(v) for v in found.chain)
    return found, S, g, e, _rational(found.partner())


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("k", [2, 3])
def test_the_chain_identity_and_the_power_formula_reduce_to_zero(name, k):
    found, S, g, e, ep = _exact_chain(name, k)
    half = sp.Rational(1, 2)
    assert (S * g - half * g - e).applyfunc(sp.expand) == sp.zeros(S.rows, 1)
    assert (S * ep - half * ep) == sp.zeros(S.rows, 1) and (S * e - half * e) == sp.zeros(S.rows, 1)
    assert all(x != 0 for x, lab in zip(ep, found.sm.labels) if lab == (0, 1, 0) or lab == (k, 1, 0))
    power = g
    for m in range(1, 5):
        power = S * power
        assert (power - half**m * g - m * half ** (m - 1) * e).applyfunc(sp.expand) == sp.zeros(S.rows, 1)


def _discrete_jacobian(u: sp.Matrix, v: sp.Matrix, idx: dict, o, a, b) -> sp.Expr:
    """``det [[u_a - u_o, u_b - u_o], [v_a - v_o, v_b - v_o]]`` at three labels of the net."""
    du = [u[idx[a]] - u[idx[o]], u[idx[b]] - u[idx[o]]]
    dv = [v[idx[a]] - v[idx[o]], v[idx[b]] - v[idx[o]]]
    return du[0] * dv[1] - du[1] * dv[0]


@pytest.mark.parametrize("name", NAMES)
def test_the_level_m_normal_grows_like_2m_cross_the_pairs_jacobian(name):
    # p = c_e' e' + c_g g + c_e e; the net S^m p scaled by 2^m, its normal at a point off the rays: 4^m n_m minus
    # 2 m (c_e' x c_g) D(e', e) must not depend on m (module docstring's expansion, exact)
    k = 2
    found, S, g, e, ep = _exact_chain(name, k)
    idx = {lab: i for i, lab in enumerate(found.sm.labels)}
    o, a, b = (1, 1, 0), (1, 2, 0), (0, 1, 1)  # a point next to O off the rays and two of its neighbours
    c_ep, c_g, c_e = sp.Matrix([1, 2, -1]), sp.Matrix([0, 3, 5]), sp.Matrix([7, -2, 1])
    P = ep * c_ep.T + g * c_g.T + e * c_e.T  # one row per point, xyz columns
    D = _discrete_jacobian(ep, e, idx, o, a, b)
    assert D != 0
    rests = []
    for m in range(1, 5):
        P = S * P
        rows = [(P.row(idx[x]) * 2**m).T for x in (o, a, b)]
        normal = (rows[1] - rows[0]).cross(rows[2] - rows[0])
        rests.append((normal - 2 * m * c_ep.cross(c_g) * D).applyfunc(sp.expand))
    assert all(r == rests[0] for r in rests)


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("k", [2, 3, 5])
def test_the_chains_map_is_certified_and_oriented_as_a_half_plane(name, k):
    scheme = load_scheme(name)
    found = jordan_chain(scheme, k)
    with flint.ctx.workprec(64):
        result = jordan_sector(scheme, SharpVertex.corner(k, scheme.lattice), 6, found)
        ep, e = chain_vectors(found)
    assert result.verdict is C1Verdict.C1 and result.final and result.method == JORDAN_METHOD
    assert result.bound is not None and result.bound > 0 and result.opening == pytest.approx(1.0, abs=1e-6)
    labels = found.sm.labels
    inside = [x for x, lab in zip(e, labels) if not _on_ray(lab, k)]
    assert all(x > 0 for x in inside)  # f_e has one sign off the rays: the image is a half-plane
    e0, ek = ep[labels.index((0, 1, 0))], ep[labels.index((k, 1, 0))]
    assert (e0 + ek).contains(0) and not e0.contains(0)  # the rays go to opposite directions of one line
    assert result.sign == (1 if e0 > 0 else -1)  # ray 0 -> +x, inside -> +y, ray k -> -x: counterclockwise iff e'_0 > 0


@pytest.mark.parametrize("name", NAMES)
def test_a_sector_without_the_block_is_not_read_as_one(name):
    found = jordan_chain(load_scheme(name), 1)
    spectral = jordan_spectrum(found)
    assert spectral.status is C1Verdict.UNDECIDED and "dim ker(S - I/2)^2 = 2" in spectral.reason


@pytest.mark.parametrize("name, k", [("catmull-clark", 2), ("loop", 3)])
def test_the_standard_rules_regular_corner_has_the_block_too(name, k):
    # the standard corner rule at the faces of a flat boundary (2 quads, 3 triangles): the sine mode has 1/2 as well
    scheme = load_scheme(name)
    found = jordan_chain(scheme, k)
    assert (len(found.eigen), len(found.general)) == (2, 3) and not found.on_rays(found.chain[1])
    result = c1_mirror_blocks(scheme, SharpVertex.corner(k, scheme.lattice))
    assert result.verdict is C1Verdict.C1 and result.method == JORDAN_METHOD
    assert len(jordan_chain(scheme, k + 1).general) == 2  # one face more: no block
