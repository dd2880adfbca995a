"""The toolkit's own claims beyond the paper (claims/b1_curvature.py): their order, file, and statuses that flip."""

import pytest
import sympy as sp

from symdecomp import catmull_clark, loop, loop_warren, symbols
from symdecomp.claims import Scope, Status, all_claims, check_claim, section_key
from symdecomp.claims import b1_curvature as b1
from symdecomp.output.latex import section_file_name
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE

LABELS = ["Curvature regime: Catmull-Clark", "Curvature regime: Loop", "Loop's vertex weight", "Curvature at the regular valence",
          "Shape: the valence decides"]


def test_the_beyond_sections_come_after_the_papers_in_their_own_file():
    sections = [c.section for c in all_claims()]
    first = sections.index("B.1")
    assert all(section_key(s)[0] == 0 for s in sections[:first]) and set(sections[first:]) == {"B.1", "B.2"}
    assert [c.label for c in all_claims() if c.section == "B.1"] == LABELS
    assert section_file_name("B.1") == "beyond-1.tex" and section_file_name("5.1") == "section-5-1.tex"
    assert sorted(["B.2", "B.1", "6", "5.10", "5.2", "2"], key=section_key) == ["2", "5.2", "5.10", "6", "B.1", "B.2"]


@pytest.mark.slow
def test_the_statuses_for_catmull_clark():
    results = [check_claim(label) for label in LABELS]
    # Loop's regime and its hyperbolic cause are proved for every n >= 7, Catmull-Clark's for every n >= 5 (its cause by
    # a bound in n from 9, symdecomp.verify.regime_cause; issue 32)
    # the shape: the hyperbolic part dominates for every n >= 5 and >= 7 (symdecomp.verify.dominance_every_n)
    assert [r.status for r in results] == [Status.PROVED, Status.PROVED, Status.PROVED, Status.VERIFIED, Status.PROVED]
    assert [r.scope for r in results] == [Scope.EVERY_N, Scope.EVERY_N, Scope.EVERY_N, Scope.SINGLE_CASE, Scope.EVERY_N]
    assert "for every n >= 5 the hyperbolic eigenvalue exceeds lambda_1**2" in str(results[0].evidence)
    assert "for every n >= 5 the hyperbolic eigenvalue is the largest after 1 and lambda_1" in str(results[0].evidence)


def _off_regular(alpha3, beta3):
    """Catmull-Clark with the vertex weights alpha3, beta3 at n = 3 and its own at the regular valence (linear in n)."""
    n, a, b = symbols.n, sp.Rational(3, 2) / symbols.n**2, sp.Rational(1, 4) / symbols.n**2
    return catmull_clark(a + (alpha3 - a.subs(n, 3)) * (4 - n), b + (beta3 - b.subs(n, 3)) * (4 - n))


def test_another_scheme_refutes_the_statement_with_the_numbers():
    lifted = _off_regular(sp.Rational(1, 8), sp.Rational(1, 64))  # the elliptic eigenvalue above lambda_1^2 at n = 3
    r = check_claim("Curvature regime: Catmull-Clark", lifted)
    assert r.status is Status.REFUTED and "n = 3" in str(r.counterexample) and "unbounded" in str(r.counterexample)
    assert "|mu| > lambda_1**2" in str(r.counterexample)


def test_another_printed_statement_is_refuted_and_the_right_one_verified():
    swapped = ((3, 3, b1.B, None), (4, None, b1.U, None))  # bounded at n = 3 as printed: Catmull-Clark has a flat spot there
    assert b1.check_regimes(catmull_clark(), swapped, (3, 8)).status is Status.REFUTED
    assert b1.check_regimes(catmull_clark(), b1.CATMULL_CLARK, (3, 8)).status is Status.PROVED  # the cause for every n too
    assert b1.check_regimes(loop(), b1.CATMULL_CLARK, (3, 8)).status is Status.REFUTED  # Loop's n = 3 is not flat
    assert b1.check_regimes(loop_warren(), b1.LOOP, (3, 8)).status is Status.REFUTED  # Warren's weight: unbounded at n = 4


@pytest.mark.slow
def test_loops_weight_is_proved_and_warrens_refuted_exactly():
    assert b1._loop_weight(loop()).status is Status.PROVED
    r = b1._loop_weight(loop_warren())
    assert r.status is Status.REFUTED and r.scope is Scope.EVERY_N  # the counterexample is an exact number
    assert "n = 4" in str(r.counterexample) and "7/64" in str(r.counterexample)  # 1/4 - 9/64


def test_the_regular_valence_claim_for_each_lattice_another_count_and_other_regular_rules():
    assert b1.check_regular(loop(), 3).status is Status.VERIFIED
    assert b1.check_regular(catmull_clark(), 2).status is Status.REFUTED  # as if printed "twice"
    # other weights at the regular valence: the surface is no longer the bicubic spline, and the claim says it cannot tell
    other = catmull_clark(sp.Rational(1, 8), sp.Rational(1, 64))
    assert check_claim("Curvature at the regular valence", other).status is Status.NOT_APPLICABLE


def test_the_shape_claim_flips_with_the_vertex_rule_and_with_the_statement():
    assert check_claim("Shape: the valence decides").status is Status.PROVED
    n, a, b = symbols.n, sp.Rational(3, 2) / symbols.n**2, sp.Rational(1, 4) / symbols.n**2
    # at n = 5 the weights 1/20, 1/100 (Catmull-Clark's at n = 4): the elliptic eigenvalue rises above the hyperbolic one
    lifted = catmull_clark(a + (sp.Rational(1, 20) - a.subs(n, 5)) * (n - 4), b + (sp.Rational(1, 100) - b.subs(n, 5)) * (n - 4))
    r = b1.check_dominance(lifted, b1.DOMINANCE[BICUBIC], (3, 6))
    assert r.status is Status.REFUTED and "n = 5" in str(r.counterexample) and "computed: the elliptic part" in str(r.counterexample)
    assert b1.check_dominance(loop(), b1.DOMINANCE[BICUBIC], (3, 8)).status is Status.REFUTED  # Loop's n = 5, 6 are not hyperbolic
    assert b1.check_dominance(loop(), b1.DOMINANCE[BOX_SPLINE], (3, 8)).status is Status.PROVED


_LOOP_WITH_EDGE_WEIGHTS = """name = "loop-edge-{left}-{right}"
mesh = "triangle"
[edge]
O = "3/8"
a = {{ "-1" = "{left}", "0" = "3/8", "1" = "{right}" }}
[vertex]
beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"
"""


def test_loops_weight_needs_a_real_lambda_1_and_a_skewed_edge_rule_is_set_aside_not_refuted():
    """Loop's edge rule with its two outer weights 3/16, 1/16 instead of 1/8, 1/8: lambda_1 = M(omega_n) is complex, so
    comparing the elliptic eigenvalue with lambda_1^2 is no statement about the scheme (it was refuted with a complex
    'counterexample'); the mirrored rule (the two weights averaged) is Loop's and the claim is proved for it."""
    from symdecomp.analysis.frequency import one_ring_matrices
    from symdecomp.schemes.files import scheme_from_text

    skew = scheme_from_text(_LOOP_WITH_EDGE_WEIGHTS.format(left="3/16", right="1/16"))
    lam1 = one_ring_matrices(skew)[0][0, 0].subs(symbols.omega, sp.exp(2 * sp.pi * sp.I / 5))
    assert sp.simplify(sp.im(sp.expand_complex(lam1)) + sp.sin(2 * sp.pi / 5) / 8) == 0  # (1/16 - 3/16) sin(2 pi/5)
    result = check_claim("Loop's vertex weight", skew)
    assert result.status is Status.NOT_APPLICABLE and result.counterexample is None
    # M(omega) = omega/16 + 3/8 + 3/(16 omega) in c = cos(j pi/n), s = sin(j pi/n): odd in s, so not the same at j and n - j
    assert "c**2/2 - I*c*s/4 + 1/8" in str(result.evidence) and "the characteristic map rotates" in str(result.evidence)
    mirrored = scheme_from_text(_LOOP_WITH_EDGE_WEIGHTS.format(left="1/8", right="1/8"))
    assert check_claim("Loop's vertex weight", mirrored).status is Status.PROVED


def test_a_rule_that_is_loops_only_at_the_regular_valence_has_no_curvature_or_shape_verdict_where_lambda_1_is_complex():
    """Outer edge weights 1/8 -+ (n - 6)/64: Loop at n = 6 (its regular patches are the box spline), skewed at every other
    valence. Reif's test refutes C1 there (lambda_1 is not real, computed); the regimes and the shape compare mu with
    lambda_1^2 and are set aside with that reason (the shape was 'refuted': 'neither part' at n = 4)."""
    from symdecomp.schemes.files import scheme_from_text

    twist = scheme_from_text(_LOOP_WITH_EDGE_WEIGHTS.format(left="1/8 + (n - 6)/64", right="1/8 - (n - 6)/64"))
    c1 = check_claim("C1 (Reif's test)", twist)
    assert c1.status is Status.REFUTED and "not real" in str(c1.counterexample)
    for label in ("Curvature regime: Loop", "Loop's vertex weight", "Shape: the valence decides"):
        result = check_claim(label, twist)
        assert result.status is Status.NOT_APPLICABLE and "the characteristic map rotates" in str(result.evidence), label
    assert check_claim("Curvature at the regular valence", twist).status is Status.VERIFIED  # n = 6: Loop's own rules


TRIANGLE_WITH_FREE_W = """\
name = "loop with free w"
mesh = "triangle"
parameters = ["w"]
[edge]
O = "3/8"
a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }
[vertex]
beta = "w"
"""


def test_a_regime_claim_asks_its_requirements_of_the_scheme_it_reads():
    """Catmull-Clark's regimes read Catmull-Clark for a triangle scheme: a triangle file with a free parameter gets
    Catmull-Clark's verdict, as Loop does (they were 'not applicable' for parameters the check never reads), while a quad
    file with a free parameter is read itself and gets 'not applicable' naming that parameter; Loop's regimes the other
    way round. The requirements are declared once and asked of each scheme the check reads (Claim.schemes_read)."""
    from symdecomp.claims import get_claim
    from symdecomp.claims.applicability import MIRROR_SYMMETRIC, NO_FREE_PARAMETERS
    from symdecomp.schemes.files import scheme_from_text
    from tests.claims.test_one_model import CC_FACE_WITH

    triangle, quad = scheme_from_text(TRIANGLE_WITH_FREE_W), scheme_from_text(CC_FACE_WITH.format(p="P"))
    assert [str(p) for p in triangle.parameters] == ["w"] and [str(p) for p in quad.parameters] == ["P"]
    assert not hasattr(b1, "read_on") and not hasattr(b1, "real_lambda1_on")  # one concept: reads_on
    for label, own_lattice, reference in (("Curvature regime: Catmull-Clark", quad, catmull_clark()),
                                          ("Curvature regime: Loop", triangle, loop())):
        c = get_claim(label)
        assert c.requires == (NO_FREE_PARAMETERS, MIRROR_SYMMETRIC)
        other = triangle if own_lattice is quad else quad
        assert c.schemes_read(other) == (reference,) and c.schemes_read(own_lattice) == (own_lattice,)
        assert c.unmet(other) is None
        borrowed, theirs = check_claim(label, other), check_claim(label, reference)
        assert borrowed.status is theirs.status and borrowed.status in (Status.PROVED, Status.VERIFIED), label
        assert str(borrowed.evidence) == str(theirs.evidence)
        own = check_claim(label, own_lattice)
        name = str(own_lattice.parameters[0])
        assert own.status is Status.NOT_APPLICABLE and f"has free parameters {name};" in str(own.evidence), label
    shape = get_claim("Shape: the valence decides")  # reads both lattices: the scheme given on its own, the reference on the other
    assert shape.schemes_read(triangle) == (catmull_clark(), triangle) and shape.schemes_read(quad) == (quad, loop())
    for scheme, name in ((triangle, "w"), (quad, "P")):
        result = check_claim(shape.label, scheme)
        assert result.status is Status.NOT_APPLICABLE and f"has free parameters {name};" in str(result.evidence)
    # what those checks read is said once, by reads_on: the registry hands it to them, and no check picks it again
    assert not hasattr(b1, "_on")


def test_requirements_are_equal_only_when_they_test_with_the_same_function():
    """Two requirements sharing a name but testing differently are not equal (equality was by name alone)."""
    from symdecomp.claims import Requirement
    from symdecomp.claims.applicability import NO_FREE_PARAMETERS

    namesake = Requirement(NO_FREE_PARAMETERS.name, lambda scheme: None)
    assert namesake != NO_FREE_PARAMETERS and len({namesake, NO_FREE_PARAMETERS}) == 2
    assert Requirement(NO_FREE_PARAMETERS.name, NO_FREE_PARAMETERS.unmet) == NO_FREE_PARAMETERS
    assert namesake.unmet(loop()) is None and NO_FREE_PARAMETERS.unmet(scheme_with_w := _free_w()) is not None
    assert "w" in str(NO_FREE_PARAMETERS.unmet(scheme_with_w))


def _free_w():
    from symdecomp.schemes.files import scheme_from_text

    return scheme_from_text(TRIANGLE_WITH_FREE_W)
