"""BLZ's corners: the eigenvalue 1/2 is a triple root with one Jordan block of size 2 (corner_jordan).

The module counts ``ker(S - I/2)`` and ``ker(S - I/2)^2`` over ``Q(cos(pi/k))``; here the same facts are recomputed
independently on the sector's matrix with sympy where it is rational (k = 2, 3), the chain is rebuilt and checked,
and a mutated corner rule loses the block and changes the verdict (from the block's certified C1, c1_corner_jordan, to
Zorin's not C1).
"""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp

from symdecomp.analysis.mirror import with_near_edge
from symdecomp.cli import main
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.symbols import theta_k
from symdecomp.verify.c1_corner_jordan import JORDAN_METHOD
from symdecomp.verify.c1_mirror_blocks import c1_mirror_blocks
from symdecomp.verify.corner_jordan import corner_jordan
from symdecomp.verify.mirror_parts import sector_matrices
from symdecomp.verify.result import C1Verdict

NAMES = ("catmull-clark-blz", "loop-blz")


def _on_sharp_ray(label, k: int) -> bool:
    return label == ORIGIN or (label[2] == 0 and label[0] in (0, k))


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("k", [2, 3])
def test_the_triple_root_has_two_eigenvectors_and_a_chain_off_the_rays_recomputed_in_sympy(name, k):
    scheme = load_scheme(name)
    sm = sector_matrices(scheme, SharpVertex.corner(k, scheme.lattice))
    assert sm.weight is None  # cos(pi/2) and cos(pi/3) are rational: the matrix is exact in Q
    S = sp.Matrix(sm.matrix)
    lam = sp.Symbol("lam")
    factors = dict(sp.factor_list(S.charpoly(lam).as_expr())[1])
    assert factors[2 * lam - 1] == 3  # algebraic multiplicity 3
    A = S - sp.eye(S.rows) / 2
    assert S.rows - A.rank() == 2 and S.rows - (A * A).rank() == 3  # geometric 2, one Jordan block of size 2
    g = next(v for v in (A * A).nullspace() if A * v != sp.zeros(S.rows, 1))
    e = A * g
    assert A * e == sp.zeros(S.rows, 1) and e != sp.zeros(S.rows, 1)
    assert all(x == 0 for x, lab in zip(e, sm.labels) if _on_sharp_ray(lab, k))
    found = corner_jordan(scheme, k)
    assert (found.eigenvectors, found.generalized, found.block, found.chain_on_rays, found.field) == (2, 3, 2, False, "Q")


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("k", [4, 5, 7])
def test_the_jordan_block_in_the_cosine_field(name, k):
    found = corner_jordan(load_scheme(name), k)
    assert (found.eigenvectors, found.generalized, found.chain_on_rays) == (2, 3, False)
    assert found.field == f"Q(cos(pi/{k}))"


@pytest.mark.parametrize("name", NAMES)
def test_one_face_has_no_block(name):
    found = corner_jordan(load_scheme(name), 1)
    assert (found.eigenvectors, found.generalized, found.block, found.chain_on_rays) == (2, 2, 1, None)


def _bent(name: str):
    """BLZ's near-edge weights moved by 1/32 from the centre to the far end (the corner rule mutated)."""
    base = load_scheme(name)
    shift = sp.Rational(1, 32)
    centre, end = base.sharp.near_edge_centre, base.sharp.near_edge_end
    assert theta_k in centre.free_symbols  # the rule read is BLZ's, in the sector angle
    return dataclasses.replace(base, name="bent", sharp=with_near_edge(base, centre - shift, end + shift))


@pytest.mark.parametrize("name", NAMES)
def test_a_mutated_corner_rule_loses_the_block_and_changes_the_verdict(name):
    scheme, bent = load_scheme(name), _bent(name)
    vertex = SharpVertex.corner(3, scheme.lattice)
    assert corner_jordan(bent, 3).block == 1
    real = c1_mirror_blocks(scheme, vertex)
    assert real.verdict is C1Verdict.C1 and real.method == JORDAN_METHOD and "a Jordan block of size 2" in real.reason
    mutated = c1_mirror_blocks(bent, vertex)
    assert mutated.verdict is C1Verdict.NOT_C1 and "Jordan" not in mutated.reason  # a tangent misses the plane


def test_the_command_line_states_the_jordan_block(capsys):
    assert main(["c1", "--corner", "--k", "2:3", "--scheme", "loop-blz"]) == 0  # every k is C1
    out = capsys.readouterr().out
    lines = [line for line in out.splitlines() if line.startswith("corner k = ")]
    assert len(lines) == 2
    for line in lines:
        assert "C1 certified" in line and "dim ker(S - I/2) = 2, dim ker(S - I/2)^2 = 3 (exact)" in line
        assert "vanishes on both sharp rays" in line and "J(f_e', f_e)" in line


@pytest.mark.parametrize("name", NAMES)
def test_the_block_is_the_angle_pi_s_and_a_convex_corner_has_none(name):
    # theta_k = angle/k: at angle pi the sine mode joins 1/2 (the block); at pi/2 and 3 pi/4 only the two boundary
    # tangents have 1/2, and Zorin's test decides
    scheme = load_scheme(name)
    assert corner_jordan(scheme, 3, sp.pi).block == 2
    for angle in (sp.pi / 2, 3 * sp.pi / 4):
        found = corner_jordan(scheme, 3, angle)
        assert (found.eigenvectors, found.generalized, found.block) == (2, 2, 1)
        assert c1_mirror_blocks(scheme, SharpVertex.corner(3, scheme.lattice, angle)).verdict is C1Verdict.C1
    dense = c1_mirror_blocks(scheme, SharpVertex.corner(2, scheme.lattice, sp.pi))  # the dense test's tie, then the block
    assert dense.verdict is C1Verdict.C1 and dense.method == JORDAN_METHOD and "a Jordan block of size 2" in dense.reason
