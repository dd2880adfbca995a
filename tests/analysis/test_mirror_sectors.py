"""The mirror decomposition of boundary, crease, corner and dart vertices (analysis/mirror.py, mirror_threshold.py)."""

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp import catmull_clark, loop
from symdecomp.analysis.mirror import (
    THETA,
    THETA_K,
    block_eigenvalues,
    crease_block,
    mirror_stencils,
    sector_decomposition,
    sector_matrix,
    sector_spectrum,
    sine_block,
    sine_identity,
    with_near_edge,
)
from symdecomp.analysis.mirror_threshold import C, boundary_eigenvalue, charpoly_check, crease_eigenvectors, first_exceeding
from symdecomp.errors import InvalidTypeError, NotApplicableError
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.scheme import Scheme, Stencil
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix

CC, LOOP = catmull_clark(), loop()
Q = sp.Rational


def Vertex(sectors, closed, corner=False, lattice=QUAD):
    return SharpVertex(lattice, sectors, closed, corner)


def blz(scheme):
    c = sp.cos(THETA_K)
    return with_near_edge(scheme, Q(3, 8) + c / 4, Q(3, 8) - c / 4) if scheme.face_rule else \
        with_near_edge(scheme, Q(1, 4) + c / 4, Q(1, 2) - c / 4)


def test_the_sine_block_is_read_from_the_stencils_and_the_identity_vanishes():
    assert sine_block(CC) == sp.Matrix([[Q(3, 8) + sp.cos(THETA) / 8, sp.cos(THETA / 2) / 8], [sp.cos(THETA / 2) / 2, Q(1, 4)]])
    assert sine_block(LOOP) == sp.Matrix([[Q(3, 8) + sp.cos(THETA) / 4]])
    for s in (CC, LOOP):
        residual, boundary = sine_identity(s)
        assert all(r == 0 for r in residual) and all(b == 0 for b in boundary)


def test_the_sine_polylines_are_eigenvectors_of_the_assembled_matrix():
    """P * (a-part, b-part) = (a-part, b-part) * M(pi j/k), entry by entry, exactly (k = 5, j = 2)."""
    d = sector_decomposition(CC, 5)
    S, P = d.transform, d.matrix
    blk = d.blocks[1]
    assert (blk.j, blk.kind) == (2, "sine")
    cols = S[:, 3 + 2 * 1: 3 + 2 * 2]  # after O, a_0, a_5 and the block j = 1
    diff = (P * cols - cols * blk.matrix).applyfunc(lambda e: sp.simplify(sp.expand_trig(e)))
    assert diff == sp.zeros(*diff.shape)
    # the transform block-triangularises the whole matrix: numerically to 40 digits (exact above)
    with mpmath.workdps(40):
        Sn, Pn = mpmath.matrix(S.evalf(45).tolist()), mpmath.matrix(P.tolist())
        B = mpmath.inverse(Sn) * Pn * Sn
        assert max(abs(B[r, c]) for r in range(3) for c in range(3, P.shape[0])) < mpmath.mpf(10) ** -35


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
def test_the_crease_block_and_the_boundary_eigenvalue(scheme):
    Cb = crease_block(scheme)
    assert Cb == sp.Matrix([[Q(3, 4), Q(1, 8), Q(1, 8)], [Q(1, 2), Q(1, 2), 0], [Q(1, 2), 0, Q(1, 2)]])
    assert sorted(Cb.eigenvals()) == [Q(1, 4), Q(1, 2), 1]
    assert boundary_eigenvalue(scheme) == Q(1, 2)
    assert crease_block(scheme, corner=True).eigenvals() == {1: 1, Q(1, 2): 2}


def test_the_spectrum_of_a_boundary_vertex_by_block():
    spec = sector_spectrum(CC, 2)  # the regular boundary: the bicubic spline's 1/2 twice, 1/4, 1/8
    assert sorted((e.value for e in spec), key=float) == [Q(1, 8), Q(1, 4), Q(1, 4), Q(1, 2), Q(1, 2), 1]
    assert {(e.blocks[0].block, e.blocks[0].j) for e in spec} == {("crease", None), ("sine", 1), ("face", 2)}
    loop3 = sector_spectrum(LOOP, 3)  # Loop's regular boundary: 1/2 from the crease block and from j = 1
    assert [e.value for e in loop3 if e.blocks[0].block == "sine"] == [Q(1, 2), Q(1, 4)]
    # k = 3 on quads: the closed form (tr +- sqrt(tr^2 - 4 det))/2 of M(pi/3)
    top = max((e for e in sector_spectrum(CC, 3) if e.blocks[0].j == 1), key=lambda e: float(e.value))
    assert sp.simplify(top.value - (Q(11, 32) + sp.sqrt(57) / 32)) == 0
    assert block_eigenvalues(sp.Matrix([[Q(1, 2)]])) == (Q(1, 2),)


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
def test_blocks_against_the_matrix_for_k_1_to_12(scheme):
    """The product of the blocks' characteristic polynomials (Chebyshev resultant) is the matrix's, exactly in FLINT."""
    L = scheme.lattice
    vertices = [k for k in range(1, 13)] + [Vertex((k,), False, True, L) for k in (1, 3, 7)]
    vertices += [Vertex((k, 3), True, False, L) for k in (1, 2, 5)]
    vertices += [Vertex((n,), True, False, L) for n in (3, 4, 5, 8)] if scheme is CC else []  # Loop's dart weight: irrational
    for v in vertices:
        equal, full, blocks = charpoly_check(scheme, v)  # against the matrix by refinement of the tagged mesh
        assert equal, v
        assert full.degree() == sector_matrix(scheme, v).shape[0]
    # a matrix without the block structure is caught: O's rule moved 1/8 from O onto the interior point a_1
    P = sector_matrix(scheme, 4)
    P[0, 0] -= Q(1, 8)
    P[0, 2] += Q(1, 8)
    assert not charpoly_check(scheme, 4, matrix=P)[0]


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
def test_the_assembled_matrix_is_the_refined_one(scheme):
    """The stencils this module assembles are the rules of the whole mesh: equal to exact refinement, entry by entry."""
    L = scheme.lattice
    for k in range(1, 9):
        for v in (SharpVertex.boundary(k, L), SharpVertex.corner(k, L), SharpVertex.crease(k, 3, L), SharpVertex.dart(k + 2, L)):
            assert sector_matrix(scheme, v) == sharp_subdivision_matrix(scheme, v), v


def test_dart_antisymmetric_part_is_the_sine_blocks_at_2_pi_j_over_n():
    d = sector_decomposition(CC, Vertex((5,), True))
    assert [b.theta for b in d.blocks] == [2 * sp.pi / 5, 4 * sp.pi / 5]
    assert d.cosine.shape == (7, 7) and d.crease is None
    x = sp.Symbol("x")
    # the cosine part holds the eigenvalue 1 (affine rules) and the rest of the matrix's
    assert d.cosine.charpoly(x).as_expr().subs(x, 1) == 0
    full = flint.fmpq_mat([[flint.fmpq(int(e.p), int(e.q)) for e in r] for r in d.matrix.tolist()]).charpoly()
    assert full(1) == 0


def test_threshold_every_k_standard_and_modified():
    cc, lp = first_exceeding(CC), first_exceeding(LOOP)
    assert (cc.first, cc.g, cc.table) == (3, -C / 16, {2: "=", 3: ">"})
    assert (lp.first, lp.g, lp.table) == (4, C / 4 - Q(1, 8), {2: "<", 3: "=", 4: ">"})
    for s in (CC, LOOP):
        m = first_exceeding(s, blz(s))
        assert m.identically and m.g == 0
        # and at k = 7 the modified block really has the eigenvalue 1/2 (numbers, independently of g)
        M = sine_block(s, blz(s)).subs({THETA: sp.pi / 7, THETA_K: sp.pi / 7})
        assert min(abs(complex(v) - 0.5) for v in block_eigenvalues(M)) < 1e-14
    # numeric spot check of the standard rules: at k = 3..12 the j = 1 block's top eigenvalue is above 1/2 (CC)
    for k in range(3, 13):
        M = sine_block(CC).subs(THETA, sp.pi / k)
        assert max(float(v) for v in block_eigenvalues(M)) > 0.5


def _scheme(edge_a, face_a=None):
    face = Stencil.from_weights(Q(1, 4), face_a or {0: Q(1, 4), 1: Q(1, 4)}, {0: Q(1, 4)})
    rest = 1 - sum(edge_a.values()) - Q(1, 8)
    edge = Stencil.from_weights(rest, edge_a, {-1: Q(1, 16), 0: Q(1, 16)})
    return Scheme("lopsided", edge, face, CC.vertex_rule)


def test_refuses_rules_without_the_mirror_in_one_line():
    with pytest.raises(NotApplicableError, match=r"weights on a_\(i\+1\) \(1/8\) and a_\(i-1\) \(0\) differ"):
        mirror_stencils(_scheme({0: Q(3, 8), 1: Q(1, 8)}))
    with pytest.raises(NotApplicableError, match="reaches past the neighbouring edge"):
        mirror_stencils(_scheme({0: Q(3, 8), 2: Q(1, 16), -2: Q(1, 16)}))
    with pytest.raises(NotApplicableError, match="face rule's weights on a_i"):
        mirror_stencils(_scheme({0: Q(3, 8), 1: Q(1, 16), -1: Q(1, 16)}, {0: Q(1, 8), 1: Q(3, 8)}))
    with pytest.raises(InvalidTypeError, match="vertex"):
        sector_spectrum(CC, "5")
    with pytest.raises(InvalidTypeError, match="rules"):
        sector_matrix(CC, 3, rules=object())
    with pytest.raises(NotApplicableError, match="semi-sharp"):
        sector_spectrum(CC, SharpVertex.crease(2, 3, QUAD, sharpness=1))


@pytest.mark.parametrize("scheme, phi, resonant", [(CC, sp.pi / 2, (2, 4, 6)), (LOOP, sp.pi / 3, (3, 6))], ids=["cc", "loop"])
def test_the_boundary_tangent_continues_as_a_shifted_sine(scheme, phi, resonant):
    """The eigenvector of the crease block's 1/2 (on a_0 - a_k) continues into the sector as a_i ~ sin(phi (i - k/2)), phi the
    root of det(M(phi) - 1/2) = 0 (Catmull-Clark: -cos(phi)/16, phi = pi/2; Loop: cos(phi)/4 - 1/8, phi = pi/3); where
    phi = pi j/k, 1/2 is also a sine eigenvalue and the continuation is not unique."""
    g = first_exceeding(scheme).g
    assert g.subs(C, sp.cos(phi)) == 0
    for k in range(2, 8):
        (lam, v, parity), = [e for e in crease_eigenvectors(scheme, k) if e[0] == Q(1, 2)]
        if k in resonant:
            assert v is None
            continue
        assert parity == -1
        a = [v[1 + i] for i in range(k + 1)]
        shape = [sp.sin(phi * (2 * i - k) / 2) for i in range(k + 1)]
        assert all(sp.simplify(a[i] * shape[0] - a[0] * shape[i]) == 0 for i in range(k + 1)), k
        assert sp.simplify(sector_matrix(scheme, k) * v - v / 2) == sp.zeros(v.shape[0], 1)
