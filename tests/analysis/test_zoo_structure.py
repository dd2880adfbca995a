"""The blocks read once (zoo_structure) against the explicit matrices at valences beyond the reading and its checks.

At each valence the explicit matrix is built by refinement (zoo_matrix) and its blocks read off it (zoo_blocks,
every entry checked against the rotation); the structural block of every frequency, evaluated in Arb from the
form read at n = 16, must hold the explicit block's exact entries, and the Fourier sum of a centre family must be
its symbol's closed form (zoo_symbols), which the structure uses in place of the n terms.
"""

import flint
import pytest
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_structure import READ_AT, zoo_structure
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.stencil_convert import as_stencils
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencil_rows import is_zero
from symdecomp.schemes.stencils import J, M
from symdecomp.symbols import omega as OMEGA
from tests.analysis.zoo_engine_schemes import catmull_clark_stencils

SCHEMES = {
    "doo-sabin": lambda: load_zoo("doo-sabin"),
    "midedge": lambda: load_zoo("midedge"),
    "sqrt3": lambda: load_zoo("sqrt3"),
    "modified-butterfly": lambda: load_zoo("modified-butterfly"),
    "catmull-clark": catmull_clark_stencils,
    "loop": lambda: as_stencils(load_scheme("loop")),
}


def _explicit_block(blocks, k: int, n: int) -> flint.acb_mat:
    """The explicit frequency-k block (bordered at k = 0) in Arb, from its exact entries."""
    B = blocks.frequency_zero_matrix() if k == 0 else blocks.frequency_matrix(sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)))
    return flint.acb_mat([[flint.acb(compile_expression(sp.expand(e, complex=True), (), "arb")()) for e in row]
                          for row in sp.Matrix(B).tolist()])


@pytest.mark.parametrize("name", sorted(SCHEMES))
@pytest.mark.parametrize("n", [READ_AT + 5, pytest.param(2 * READ_AT + 1, marks=pytest.mark.slow)])
def test_the_structural_blocks_hold_the_explicit_ones(name, n):
    scheme = SCHEMES[name]()
    st = zoo_structure(scheme)
    blocks = zoo_blocks(zoo_matrix(scheme, n))
    with flint.ctx.workprec(128):
        for k in range(n):
            explicit, structural = _explicit_block(blocks, k, n), st.frequency_block(n, k)
            assert (explicit.nrows(), explicit.ncols()) == (structural.nrows(), structural.ncols())
            for a, b in zip(explicit.entries(), structural.entries()):
                assert b.overlaps(a) and float(b.rad().abs_upper()) < 1e-30, (name, n, k, a, b)


def test_the_structural_blocks_on_a_deeper_neighbourhood_hold_the_explicit_ones():
    """Zorin's test reads the butterfly's eigenvector on depth 4, beyond the smallest invariant depth (2)."""
    scheme, n = load_zoo("modified-butterfly"), READ_AT + 5
    st = zoo_structure(scheme, depth=4)
    assert (st.depth, st.class_count) == (4, 10) and zoo_structure(scheme).depth == 2
    blocks = zoo_blocks(zoo_matrix(scheme, n, 4))
    with flint.ctx.workprec(128):
        for k in (0, 1, 2, 5):
            explicit, structural = _explicit_block(blocks, k, n), st.frequency_block(n, k)
            assert (explicit.nrows(), explicit.ncols()) == (structural.nrows(), structural.ncols())
            for a, b in zip(explicit.entries(), structural.entries()):
                assert b.overlaps(a) and float(b.rad().abs_upper()) < 1e-30, (k, a, b)


@pytest.mark.slow
def test_a_centre_family_s_fourier_sum_is_its_symbol():
    st = zoo_structure(load_zoo("doo-sabin"))
    (symbol,) = st.symbols
    (sigma,) = st.sigma
    m = READ_AT + 7
    weight = load_zoo("doo-sabin").kinds[0].rules[0].terms[0].weight
    for k in range(m):
        direct = sp.Add(*[weight.subs({M: m, J: j}) * sp.exp(2 * sp.pi * sp.I * j * k / m) for j in range(m)])
        closed = symbol.value(k if k <= m // 2 else k - m).subs(symbol.size, m)
        assert abs(complex(sp.N(direct - closed, 40))) < 1e-30
    assert st.block.has(sigma)  # the centre face's corners enter through the symbol, not n terms


def test_below_the_reading_the_form_is_not_claimed():
    st = zoo_structure(load_zoo("midedge"))
    with pytest.raises(NotApplicableError, match=f"n = 5: the structural form holds from n = {READ_AT}"):
        st.frequency_block(5, 1)


def test_the_block_has_no_dense_offsets():
    """The reading's point: B(omega) is a Laurent polynomial of a few terms, not of degree n/2."""
    for name in ("doo-sabin", "modified-butterfly"):
        st = zoo_structure(SCHEMES[name]())
        shifted = [sp.Poly(sp.expand(e * OMEGA**8), OMEGA) for e in st.block if e != 0]
        offsets = {m[0] - 8 for p in shifted for m in p.monoms()}
        assert offsets and max(map(abs, offsets)) <= 2, offsets


@pytest.mark.parametrize("name", [pytest.param(x, marks=pytest.mark.slow) if x != "midedge" else x
                                  for x in ("doo-sabin", "midedge", "sqrt3", "modified-butterfly")])
def test_the_structural_spectrum_is_the_explicit_one(name):
    """Exact values, multiplicities and Jordan blocks from the structural form equal those of the explicit matrix's
    blocks (a depth given: the explicit route) beyond the reading."""
    from symdecomp.analysis.zoo_large_spectrum import structural_spectrum
    from symdecomp.analysis.zoo_spectrum import zoo_spectrum

    scheme, n = SCHEMES[name](), READ_AT + 5
    explicit = zoo_spectrum(scheme, n, zoo_matrix(scheme, n).depth, digits=15)
    structural = structural_spectrum(scheme, n, digits=15)
    assert structural.size == explicit.size and structural.rings == explicit.rings
    assert len(structural.eigenvalues) == len(explicit.eigenvalues)
    for a, b in zip(structural.eigenvalues, explicit.eigenvalues):
        assert (a.multiplicity, a.jordan, a.frequencies) == (b.multiplicity, b.jordan, b.frequencies)
        assert a.value.overlaps(b.value)
        if a.exact is not None and b.exact is not None:
            assert is_zero(a.exact - b.exact)  # exact: its minimal polynomial is x
