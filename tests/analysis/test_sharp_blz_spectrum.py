"""Spectrum and masks of Biermann-Levin-Zorin's rules at sharp vertices, exactly over ``Q(cos(pi/k))``.

The eigenvalues are checked against things computed without the field machinery: the determinant of the refined
matrix (mpmath at 60 digits from its exact sympy entries), the mirror decomposition's closed forms (how often
``1/2`` is an eigenvalue of the crease and sine blocks), and the masks as exact left eigenvectors of the matrix.
"""

from __future__ import annotations

import flint
import mpmath
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.algebra.cos_field import FieldMatrix, field_charpoly, norm_charpoly
from symdecomp.algebra.number_field import FieldElement
from symdecomp.analysis.masks import sharp_masks
from symdecomp.analysis.mirror import sector_spectrum
from symdecomp.analysis.spectrum import sharp_spectrum
from symdecomp.analysis.triangular_eigen import sharp_matrix
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import sharp_subdivision_matrix

CC, LOOP = load_scheme("catmull-clark-blz"), load_scheme("loop-blz")
SLOW = pytest.mark.slow


def _det(scheme, vertex) -> mpmath.mpf:
    S = sharp_subdivision_matrix(scheme, vertex)
    with mpmath.workdps(60):
        return mpmath.det(mpmath.matrix([[mpmath.mpf(str(sp.N(e, 70))) for e in row] for row in S.tolist()]))


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
@pytest.mark.parametrize("k", [3, 4, 5, 6, pytest.param(7, marks=SLOW), pytest.param(8, marks=SLOW)])
def test_half_has_the_multiplicity_of_the_blocks_and_the_product_is_the_determinant(scheme, k):
    vertex = sd.SharpVertex.boundary(k, scheme.lattice)
    s = sharp_spectrum(scheme, vertex, digits=40)
    assert s.decomposed and s.field == ("Q" if k == 3 else f"Q(cos(pi/{k}))")
    halves = sum(1 for e in sector_spectrum(scheme, vertex) if sp.simplify(e.value - sp.Rational(1, 2)) == 0)
    assert halves == 2  # the boundary curve's 1/2 and BLZ's first sine eigenvalue
    (half,) = [e for e in s.entries if e.factor == flint.fmpq_poly([-1, 2]) / 2]
    assert half.multiplicity == halves and "crease" in half.blocks and any("sine j=1" in b for b in half.blocks)
    assert sum(e.multiplicity for e in s.entries) == s.size
    with flint.ctx.workprec(256):
        product = flint.acb(1)
        for e in s.entries:
            product *= e.ball ** e.multiplicity
    det = _det(scheme, vertex)
    assert abs(complex(product.real.mid(), product.imag.mid()) - complex(det)) < 1e-30 * max(1, abs(det))
    assert abs(float(product.imag.mid())) < 1e-30


def test_the_field_charpoly_has_the_norm_of_its_conjugates():
    """``chi_S`` over ``K`` evaluated at each real embedding of ``w``: the product of those is the norm, exactly."""
    S = sharp_matrix(CC, sd.SharpVertex.boundary(5, CC.lattice))
    assert isinstance(S, FieldMatrix) and S.modulus.degree() == 2
    chi = field_charpoly(S)
    x = sp.Symbol("x")
    product = sp.Integer(1)
    for root in sp.Poly(sp.minimal_polynomial(S.weight, x), x).all_roots():
        product *= sum(sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(e.poly.coeffs())] or [0], x).as_expr()
                       .subs(x, root) * sp.Symbol("l") ** i for i, e in enumerate(chi))
    norm = norm_charpoly(S)
    expanded = sp.Poly(sp.expand(product), sp.Symbol("l"))
    assert [sp.radsimp(c) for c in expanded.all_coeffs()] == [sp.Rational(int(c.p), int(c.q)) for c in reversed(norm.coeffs())]


def _residual(S: FieldMatrix, mask) -> list:
    lam = FieldElement(flint.fmpq_poly([-mask.eigenvalue.factor[0]]), S.modulus)
    out = []
    for j in range(S.nrows()):
        acc = FieldElement(flint.fmpq_poly([]), S.modulus)
        for i, w in enumerate(mask.weights):
            acc = acc + w * S[i, j]
        out.append(acc - lam * mask.weights[j])
    return out


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
@pytest.mark.parametrize("k", [4, 5, pytest.param(7, marks=SLOW)])
def test_masks_are_exact_left_eigenvectors_over_the_field(scheme, k):
    vertex = sd.SharpVertex.boundary(k, scheme.lattice)
    S = sharp_matrix(scheme, vertex)
    m = sharp_masks(scheme, vertex)
    assert m.tangent_plane and "share the eigenvalue 0.5" in m.reason
    for mask in (m.position, *m.tangents):
        assert mask.generator is not None
        assert not any(_residual(S, mask))
    total = sum(m.position.exact())
    assert sp.radsimp(total) == 1
    curve, cross = m.tangents
    assert all(sp.radsimp(sum(t.exact())) == 0 for t in m.tangents)
    a0, ak = m.names.index("a_0"), m.names.index(f"a_{k}")
    assert cross.eigenvalue.key == curve.eigenvalue.key
    assert cross.weights[a0] == cross.weights[ak] and not (curve.weights[a0] + curve.weights[ak])
