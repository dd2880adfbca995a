"""One table of what the checks establish about the paper, compared with the whole registry by equality.

A claim registered without an entry here, or an entry without a claim, fails the test: every claim is
tested. A change of a status is a change in the mathematics, to be reviewed. Statuses are for
standard Catmull-Clark (the default scheme); tests/claims/test_mutations.py checks other schemes.
"""

import pytest
import sympy as sp

from symdecomp.claims import Status, all_claims, check_claim

P, V, R, C, U, NA = Status.PROVED, Status.VERIFIED, Status.REFUTED, Status.CORRECTED, Status.UNDECIDED, Status.NOT_APPLICABLE

EXPECTED = {
    # Section 2
    "Eq. 1": P,  # F_n invertible for every n: any n-tuple decomposes (closing rows: issue 12 item 5)
    "Eq. 2-4": P,
    "Eq. 5": P,
    "Eq. 6": P,
    "Eq. 7": P,
    "Eq. 8": P,
    "Eq. 9": P,
    "Proposition 2.1": P,
    # Section 3
    "Section 3: symmetry": P,  # window of sectors: every n
    "Section 3: 9 and 25 points": V,  # exact at n = 4, the only case (scope: single case)
    "Section 3: boundary influence": P,  # window of sectors: every n
    "Section 3: Catmull-Clark support": P,  # window of sectors: every n
    # Section 4
    "Eq. 10-11": P,
    "Eq. 12-13": P,
    "Eq. 14-15": P,
    "Eq. 16": C,  # weight 1 - alpha - beta on O is not affine
    "Eq. 17-21": P,
    "Proposition 4.1": P,
    "Proposition 4.2": P,
    "Proposition 4.3": P,
    "Eq. 22": P,
    "Eq. 23": P,
    "Eq. 24": P,
    # Section 5.1
    "Eq. 25-30": P,
    "Eq. 31-32": P,
    "Eq. 33": P,
    "Eq. 34": P,
    "Eq. 35-37": C,  # 0/0 at j = n/2
    "Eq. 38": C,  # M_j = I/4 at j = n/2
    "Proposition 5.1": P,  # certified n = 3..1000, exact tail bound from n = 4
    "Remark 5.1": R,  # j = n +- 1 shrink at the tangent-plane rate
    "Eq. 39": C,  # B^j = r A^j, not A^j = r B^j
    "Eq. 39 (n = 4)": V,  # a statement about n = 4 alone, exact there (scope: single case)
    "Eq. 39 (n → ∞)": P,
    "C1 (Reif's test)": P,  # the characteristic map for every n by exact signs in cos(2 pi/n) (c1_uniform)
    # Section 5.2
    "Eq. 40": P,
    "Eq. 41": P,
    "Proposition 5.2": P,
    "Eq. 42": P,
    "Eq. 43": C,  # alpha, beta are per-neighbour weights
    "Eq. 44": P,
    "Eq. 45": V,  # a statement about n = 4 alone, exact there (scope: single case)
    "Remark 5.2": C,  # the component j = n feeds (0, 1, -1)
    "Section 5.2: Catmull-Clark example": P,
    # Section 5.3
    "Section 5.3: smaller eigenvalues": C,  # equal at n = 3
    "Section 5.3: quadratic speed": P,
    "Section 5.3: construction": P,  # frequencies j = 1, 2 closed under the rules for every n (symbolic row i)
    "Section 5.3: basis function": P,  # resultants in n without integer zeros
    # Section 6
    "Proposition 6.1": C,  # index range 0<i,j<n-1 as printed
    "Proposition 6.2": C,  # same index range
    "Eq. 46": V,  # the block vector is alpha (x) v; block products for symbolic order, 2..6 blocks
    "Eq. 47": C,  # C_{1,n-1} in the first row
    "Eq. 48": C,  # e_{1,n-1} in the first row
    "Eq. 49": P,
    "Eq. 50": P,
    "Remark 6.1": P,
    "Proposition 6.3": C,  # t_ij = m a_ij, eigenvalues not eigenvectors, no diagonalizability needed
    "Eq. 51": P,
    "S' (after Eq. 51)": P,
    "Tuning weights (after Eq. 51)": P,
    "Tangent plane unaffected (after Eq. 51)": C,
    # the closing paragraph of Section 6 (issue 12 item 5)
    "Tuning and multiplicities (after Eq. 51)": P,
    "1-ring suffices (after Eq. 51)": P,  # left eigenvectors of 1, lambda_1 vanish outside the 1-ring, every n
    "Larger neighbourhoods (after Eq. 51)": C,  # the 2-ring adds 1/8, 1/16, 1/32, 1/64, not null columns
    "Spectrum (Eq. 34, Eq. 43)": P,  # block factorization for symbolic n (certified n = 3..48 too)
    # beyond the paper: curvature and shape (issue 21)
    "Curvature regime: Catmull-Clark": P,  # n = 3..64 certified; unbounded for every n >= 5 and its hyperbolic cause proved (issue 32)
    "Curvature regime: Loop": P,  # n = 3..64 certified; unbounded (hyperbolic) for every n >= 7 proved (issue 32)
    "Loop's vertex weight": P,  # the elliptic eigenvalue is lambda_1^2 identically in n
    "Curvature at the regular valence": V,  # mu = 1/4 = lambda_1^2 three times at n = 4
    "Shape: the valence decides": P,  # the hyperbolic part dominates for every n >= 5 (Catmull-Clark), >= 7 (Loop)
    # beyond the paper: boundary and crease vertices (issue 20)
    "Sector: sine decomposition": P,  # a trig identity in the index and theta: every k
    "Sector: crease block": P,  # 1, 1/2, 1/4 for every k
    "Sector: standard rules' subdominant eigenvalue": P,  # above 1/2 from k = 3 (Catmull-Clark), every k
    "Sector: modified rules (BLZ 2000)": P,  # det(M(pi/k) - 1/2) = 0 identically in cos(pi/k)
    "Sector: the blocks are the spectrum": V,  # FLINT charpolys, k = 1..12
    "Sector: the boundary tangent's continuation": P,  # det(M(phi) - 1/2) = 0 at phi = pi/2 (CC), pi/3 (Loop)
}


@pytest.mark.slow
def test_the_table_is_the_registry():
    statuses = {c.label: check_claim(c.label).status for c in all_claims()}
    assert statuses == EXPECTED


@pytest.mark.parametrize("label", sorted(EXPECTED))
def test_result_is_complete_and_printable(label):
    result = check_claim(label)
    assert result.evidence
    if result.status is Status.CORRECTED:
        assert result.counterexample and result.correction
    if result.status is Status.REFUTED:
        assert result.counterexample
    for step in result.steps:
        for obj in (step.expr, step.lhs):
            if obj is not None:
                sp.latex(obj)  # every displayed step is printable by sympy
