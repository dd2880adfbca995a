"""The toolkit's claims about boundary and crease vertices (claims/b2_mirror.py): order, file, and verdicts that flip."""

import sympy as sp

from symdecomp import catmull_clark, loop
from symdecomp.analysis.mirror import THETA_K
from symdecomp.claims import Scope, Status, all_claims, check_claim
from symdecomp.claims import b2_mirror as b2
from symdecomp.output.latex import SECTION_TITLES, aslatex, section_file_name
from symdecomp.schemes.files import scheme_from_text
from symdecomp.schemes.lattice import BOX_SPLINE

Q = sp.Rational
LABELS = ["Sector: sine decomposition", "Sector: crease block", "Sector: standard rules' subdominant eigenvalue",
          "Sector: modified rules (BLZ 2000)", "Sector: the blocks are the spectrum", "Sector: the boundary tangent's continuation"]
MIDPOINT = scheme_from_text('name = "midpoint edges"\n[edge]\nO = "1/2"\na = { "0" = "1/2" }\n[face]\nO = "1/4"\n'
                            'a = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n')


def test_the_section_its_file_and_title():
    assert [c.label for c in all_claims() if c.section == "B.2"] == LABELS
    assert section_file_name("B.2") == "beyond-2.tex"
    assert SECTION_TITLES["B.2"] == "Beyond the paper: boundary and crease vertices"


def test_the_statuses_and_scopes_for_both_lattices():
    for scheme in (catmull_clark(), loop()):
        results = [check_claim(label, scheme) for label in LABELS]
        assert [r.status for r in results] == [Status.PROVED] * 4 + [Status.VERIFIED, Status.PROVED], scheme.name
        assert [r.scope for r in results] == [Scope.EVERY_N] * 4 + [Scope.RANGE, Scope.EVERY_N]
        assert results[4].valences == b2.SECTORS
        # the scope ranges over k, the sector's faces, and is printed so; the paper's claims stay in n
        assert [r.scope_text for r in results] == ["every k"] * 4 + ["range of k", "every k"]
        assert "for each $k = 1" in aslatex(results[4]) and "$n =" not in aslatex(results[4])
    assert check_claim("Eq. 34", catmull_clark()).scope_text == "every n"


def test_the_threshold_is_computed_so_a_wrong_printed_k_or_another_scheme_is_refuted():
    cc, lp = catmull_clark(), loop()
    assert b2.check_first_k(cc, 3).status is Status.PROVED
    r = b2.check_first_k(cc, 4)  # printed "from k = 4" for Catmull-Clark: k = 3 already exceeds
    assert r.status is Status.REFUTED and "from k = 3" in str(r.counterexample)
    assert b2.check_first_k(lp, 3).status is Status.REFUTED  # Loop at k = 3 is the regular boundary: equal
    r = b2.check_first_k(MIDPOINT, 3)  # midpoint edges: M(pi/k) has 1/2 for every k, never above
    assert r.status is Status.REFUTED and "never" in str(r.counterexample)


def test_the_modified_rule_is_proved_and_another_weight_refuted_with_the_number():
    cc, lp = catmull_clark(), loop()
    assert b2.check_blz(cc).status is Status.PROVED and b2.check_blz(lp).status is Status.PROVED
    wrong = (Q(1, 4) + sp.cos(THETA_K) / 2, Q(1, 2) - sp.cos(THETA_K) / 2)  # gamma with cos/2 instead of cos/4
    r = b2.check_blz(cc, wrong)
    assert r.status is Status.REFUTED and "k = 2" in str(r.counterexample)
    assert "g = -1/32" in str(r.counterexample)  # det(M - 1/2) at c = cos(pi/2) = 0: (1/2 - 1/2)(-1/4) - (1/2)/16
    loop_weights_on_quads = b2.BLZ_RULE[BOX_SPLINE]  # Loop's gamma does not work for Catmull-Clark
    assert b2.check_blz(cc, loop_weights_on_quads).status is Status.REFUTED


def test_the_crease_claim_flips_with_the_printed_eigenvalues():
    assert b2.check_crease(catmull_clark()).status is Status.PROVED
    r = b2.check_crease(catmull_clark(), (1, Q(1, 2), Q(1, 8)))
    assert r.status is Status.REFUTED and "eigenvalues are {1/4, 1/2, 1}" in str(r.counterexample)


def test_the_matrix_check_is_refuted_on_a_range_and_not_applicable_without_the_mirror():
    assert b2.check_against_matrix(catmull_clark(), (1, 3)).status is Status.VERIFIED
    lopsided = scheme_from_text('name = "lopsided"\n[edge]\nO = "3/8"\na = { "0" = "3/8", "1" = "1/8" }\n'
                                'b = { "-1" = "1/16", "0" = "1/16" }\n[face]\nO = "1/4"\na = { "0" = "1/4", "1" = "1/4" }\n'
                                'b = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n')
    r = check_claim("Sector: the blocks are the spectrum", lopsided)
    assert r.status is Status.NOT_APPLICABLE and "a_(i+1) (1/8) and a_(i-1) (0) differ" in str(r.evidence)


def test_the_tangent_frequency_is_computed():
    assert b2.check_tangent(catmull_clark()).status is Status.PROVED
    r = b2.check_tangent(catmull_clark(), sp.pi / 3)  # Loop's frequency on quads: g(1/2) = -1/32
    assert r.status is Status.REFUTED and "-1/32" in str(r.counterexample)
    assert b2.check_tangent(loop(), sp.pi / 2).status is Status.REFUTED  # g(0) = -1/8 on Loop


def test_the_standard_rules_claim_reads_the_standard_rules_not_a_schemes_own_modified_ones():
    """loop-blz and catmull-clark-blz carry BLZ's modified edge rule: with it the first sine eigenvalue of M(pi/k) is the
    boundary curve's 1/2 for every k (never above; that is the other claim). The statement is about the standard rules,
    on which their smooth rules (Loop's, Catmull-Clark's) exceed 1/2 from k = 4, k = 3; it was refuted for loop-blz."""
    from symdecomp.schemes.files import load_scheme

    label = "Sector: standard rules' subdominant eigenvalue"
    for name, first in (("loop-blz", 4), ("catmull-clark-blz", 3)):
        scheme = load_scheme(name)
        own = b2.first_exceeding(scheme)  # the scheme's own (modified) rules: 1/2 exactly, identically in c
        assert (own.g, own.first) == (0, None), name
        result = check_claim(label, scheme)
        assert result.status is Status.PROVED and f"for every k >= {first}" in str(result.evidence), name
    assert check_claim(label, MIDPOINT).status is Status.REFUTED  # a change of the smooth rules still flips it
