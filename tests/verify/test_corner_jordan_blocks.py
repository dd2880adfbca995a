"""The Jordan chain of 1/2 at BLZ's corners from the 1-ring block and rational lifts (corner_jordan_blocks), against the
whole-matrix kernels of corner_jordan: the same dimensions, the same eigenspace and generalized eigenspace (each
whole-matrix vector minus its expansion in the block basis reduces to zero), the same chain's eigenvector up to a
scalar (every 2 x 2 minor of the pair is zero), and a mutated corner rule changes the result in both alike.
"""

from __future__ import annotations

import dataclasses

import flint
import pytest
import sympy as sp

from symdecomp.algebra.number_field import FieldElement
from symdecomp.analysis.leading_values import leading_values
from symdecomp.analysis.mirror import with_near_edge
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_corner_jordan import JORDAN_METHOD, blocks_jordan_spectrum, chain_vectors, jordan_spectrum
from symdecomp.verify.c1_mirror_blocks import _window, c1_mirror_blocks
from symdecomp.verify.corner_jordan import JORDAN_FACES, constant, jordan_chain
from symdecomp.verify.corner_jordan_blocks import BLOCK_JORDAN_FACES, _rational, block_jordan_chain, sparse_kernel
from symdecomp.verify.mirror_parts import mirror_label
from symdecomp.verify.result import C1Verdict

NAMES = ("catmull-clark-blz", "loop-blz")


def _residual(vector: list[FieldElement], basis: list[list[FieldElement]]) -> list[FieldElement]:
    """``vector`` minus its expansion in ``basis`` (exact elimination; all zero iff ``vector`` is in the span)."""
    mod = vector[0].modulus
    rows, pivots = [list(b) for b in basis], []
    for r in range(len(rows)):  # echelon form of the basis
        for p in pivots:
            rows[r] = [a - rows[r][p[0]] * b for a, b in zip(rows[r], p[1])]
        c = next(i for i, x in enumerate(rows[r]) if x)  # a basis vector reducing to zero would not be a basis
        inv = rows[r][c].inverse()
        pivots.append((c, [x * inv for x in rows[r]]))
    out = list(vector)
    for c, row in pivots:
        u = out[c]
        out = [a - u * b for a, b in zip(out, row)]
    assert len(out) == len(vector) and all(isinstance(x, FieldElement) for x in out)
    return out or [constant(0, mod)]


@pytest.mark.parametrize(("name", "k"), [("catmull-clark-blz", k) for k in (2, 3, 5, 8, 12)] + [("loop-blz", k) for k in (2, 4, 7)])
def test_the_block_chain_is_the_whole_matrix_chain(name, k):
    scheme = load_scheme(name)
    whole, blocks = jordan_chain(scheme, k), block_jordan_chain(scheme, k)
    assert whole.modulus == blocks.modulus and whole.sm.labels == blocks.sm.labels
    assert (len(blocks.eigen), len(blocks.general)) == (len(whole.eigen), len(whole.general)) == (2, 3)
    for mine, theirs in ((blocks.eigen, whole.eigen), (blocks.general, whole.general)):
        for v in theirs:
            assert not any(_residual(v, mine))
        for v in mine:  # and the other way: the spans are equal
            assert not any(_residual(v, theirs))
    assert whole.chain is not None and blocks.chain is not None
    e, f = whole.chain[1], blocks.chain[1]
    i = next(i for i, x in enumerate(e) if x)
    assert f[i] and not any(e[i] * y - f[i] * x for x, y in zip(e, f))  # e and f are proportional, f != 0
    assert not blocks.on_rays(f) and blocks.partner() is not None
    index = {lab: i for i, lab in enumerate(blocks.sm.labels)}
    mirror = [index[mirror_label(lab, k)] for lab in blocks.sm.labels]
    assert not any(f[i] - f[mirror[i]] for i in range(len(f)))  # e is mirror-even: sine block 1's mode


def test_the_block_chain_beyond_the_dense_cap():
    found = block_jordan_chain(load_scheme("catmull-clark-blz"), 24)
    assert (len(found.eigen), len(found.general)) == (2, 3) and found.chain is not None
    assert found.modulus.degree() == 8  # the weight 3/8 - cos(pi/24)/4 generates Q(cos(pi/24)), of degree phi(48)/2
    assert not found.on_rays(found.chain[1])


def _bent(name: str):
    base = load_scheme(name)
    shift = sp.Rational(1, 32)
    return dataclasses.replace(base, name="bent", sharp=with_near_edge(base, base.sharp.near_edge_centre - shift,
                                                                        base.sharp.near_edge_end + shift))


@pytest.mark.parametrize(("name", "k"), [("catmull-clark-blz", 3), ("catmull-clark-blz", 16), ("loop-blz", 5)])
def test_a_mutated_corner_rule_loses_the_block(name, k):
    bent = block_jordan_chain(_bent(name), k)
    assert len(bent.general) == len(bent.eigen) and bent.chain is None
    if k <= 5:
        whole = jordan_chain(_bent(name), k)
        assert (len(whole.eigen), len(whole.general)) == (len(bent.eigen), len(bent.general))


def test_the_sparse_kernel_of_a_rank_one_matrix():
    mod = flint.fmpq_poly([-2, 0, 1])  # Q(sqrt 2)
    root, one = FieldElement(flint.fmpq_poly([0, 1]), mod), constant(1, mod)
    basis = sparse_kernel({0: {0: one, 1: root}, 1: {0: root, 1: root * root}}, [0, 1], mod)
    assert len(basis) == 1 and basis[0][1] == one and not (basis[0][0] + root * basis[0][1])  # x + sqrt(2) y = 0


def test_an_outer_entry_in_the_weight_is_refused():
    mod = flint.fmpq_poly([-2, 0, 1])
    with pytest.raises(NotApplicableError, match="outer block is not rational"):
        _rational(FieldElement(flint.fmpq_poly([0, 1]), mod))


@pytest.mark.parametrize("name", NAMES)
def test_c1_past_the_dense_cap_from_the_blocks(name):
    scheme = load_scheme(name)
    k = JORDAN_FACES + 4
    found = c1_mirror_blocks(scheme, SharpVertex.corner(k, scheme.lattice))
    assert found.verdict is C1Verdict.C1 and found.method == JORDAN_METHOD
    assert "dim ker(S - I/2)^2 = 3 (exact)" in found.reason and "(blocks)" in found.reason
    mutated = c1_mirror_blocks(_bent(name), SharpVertex.corner(k, scheme.lattice))
    assert mutated.verdict is not C1Verdict.C1 or "Jordan" not in mutated.reason


def test_the_blocks_spectral_bound_holds_the_whole_matrix_spectrum():
    # at 12 faces both routes run: the largest modulus after 1 and 1/2, from the whole matrix's certified eigenvalue balls and
    # from the blocks' leading values and bounds, is the same eigenvalue (a sine block's) to 12 digits, below 1/2
    scheme, k = load_scheme("catmull-clark-blz"), JORDAN_FACES
    whole = jordan_spectrum(jordan_chain(scheme, k))
    lead = leading_values(scheme, SharpVertex.corner(k, scheme.lattice))
    outer = _window(scheme, scheme.lattice, True).outer  # the outer block's bound, as c1_mirror_blocks reads it
    bounds = [flint.arb(outer.numerator) / outer.denominator] + ([lead.tail] if lead.tail is not None else [])
    blocks = blocks_jordan_spectrum(block_jordan_chain(scheme, k), lead.values, bounds)
    assert whole.status is blocks.status is C1Verdict.C1
    assert whole.second is not None and blocks.second is not None and abs(whole.second - blocks.second) < 1e-12 and blocks.second < 0.49


def test_the_chain_as_balls_at_64_faces():
    # the entries are degree-15 polynomials in the weight with large coefficients: at 53 bits their evaluation loses every
    # digit unless it is raised; the rounded balls agree with a 212-bit evaluation to 12 digits
    found = block_jordan_chain(load_scheme("catmull-clark-blz"), 64)
    with flint.ctx.workprec(53):
        low = chain_vectors(found)
    with flint.ctx.workprec(212):
        high = chain_vectors(found)
    for a, b in zip(low, high):
        assert a is not None and b is not None
        assert all(x.rad() < 1e-13 and abs(float(x.mid()) - float(y.mid())) < 1e-12 for x, y in zip(a, b))


def test_past_the_blocks_cap_the_structure_is_not_computed():
    scheme = load_scheme("catmull-clark-blz")
    found = c1_mirror_blocks(scheme, SharpVertex.corner(BLOCK_JORDAN_FACES + 1, scheme.lattice))
    assert found.verdict is C1Verdict.UNDECIDED and f"computed for at most {BLOCK_JORDAN_FACES} faces" in found.reason
