"""The registry: result invariants, the claims command (statuses: tests/claims/test_claim_statuses.py)."""

import itertools
import json

import pytest
import sympy as sp

from symdecomp.claims import CheckResult, Scope, Status, Text, all_claims, check_claim, scope_summary
from symdecomp.cli import main


def test_result_invariants():
    with pytest.raises(ValueError, match="counterexample"):
        CheckResult(Status.REFUTED, "x")
    with pytest.raises(ValueError, match="corrected statement"):
        CheckResult(Status.CORRECTED, "x")
    with pytest.raises(ValueError, match="digits"):
        CheckResult(Status.NUMERIC, "x")
    with pytest.raises(ValueError, match="range of valences"):
        CheckResult(Status.VERIFIED, "x")


def test_the_scope_of_a_verdict_is_computed():
    exact, rounded = Text("n = 3: ", sp.sqrt(5) / 8), Text("n = 3: ", sp.Float(0.2795, 4))
    assert CheckResult(Status.PROVED, "x").scope is Scope.EVERY_N
    assert CheckResult(Status.VERIFIED, "x", valences=(3, 12)).scope is Scope.RANGE
    assert CheckResult(Status.VERIFIED, "x", valences=(4, 4)).scope is Scope.SINGLE_CASE
    assert CheckResult(Status.REFUTED, "x", counterexample=exact).scope is Scope.EVERY_N
    assert CheckResult(Status.REFUTED, "x", counterexample=rounded).scope is Scope.SINGLE_CASE  # a number to 4 digits
    assert CheckResult(Status.REFUTED, "x", counterexample="n = 3 fails").scope is Scope.SINGLE_CASE  # words only
    # a correction states its scope; a counterexample that is not exact lowers it
    assert CheckResult(Status.CORRECTED, "x", correction="c", counterexample=exact, scope=Scope.EVERY_N).scope is Scope.EVERY_N
    assert CheckResult(Status.CORRECTED, "x", correction="c", counterexample=rounded, scope=Scope.EVERY_N).scope is Scope.SINGLE_CASE
    assert CheckResult(Status.CORRECTED, "x", correction="c", counterexample=exact).scope is Scope.SINGLE_CASE  # unstated
    assert CheckResult(Status.UNDECIDED, "x").scope is None
    with pytest.raises(ValueError, match="every n"):
        CheckResult(Status.PROVED, "x", scope=Scope.RANGE)
    with pytest.raises(ValueError, match="valences"):
        CheckResult(Status.VERIFIED, "x", valences=(3, 5), scope=Scope.EVERY_N)


def test_the_scope_summary_counts_errata_established_for_every_n():
    results = [check_claim(c.label) for c in all_claims()]
    summary = scope_summary(results)
    assert summary.total == len(results) == summary.every_n + summary.range_of_n + summary.single_case + summary.no_verdict
    assert summary.proved == sum(r.status is Status.PROVED for r in results)
    assert summary.errata_every_n == sum(r.status in (Status.CORRECTED, Status.REFUTED) and r.scope is Scope.EVERY_N for r in results)
    # Eq. 47 and Eq. 48 are corrected on one size of blocks: a single case, not every n
    assert check_claim("Eq. 47").scope is Scope.SINGLE_CASE and check_claim("Eq. 16").scope is Scope.EVERY_N


def test_claims_command_json(capsys):
    assert main(["claims", "--json", "--section", "5.1"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    by_label = {r["label"]: r for r in rows}
    section_51 = {"Eq. 25-30", "Eq. 31-32", "Eq. 33", "Eq. 34", "Eq. 35-37", "Eq. 38", "Proposition 5.1"}
    section_51 |= {"Remark 5.1", "Eq. 39", "Eq. 39 (n = 4)", "Eq. 39 (n → ∞)", "C1 (Reif's test)"}
    assert set(by_label) == section_51
    assert by_label["Remark 5.1"]["status"] == "refuted" and "counterexample" in by_label["Remark 5.1"]
    assert by_label["Proposition 5.1"]["status"] == "proved"  # certified range plus the exact tail bound
    for r in rows:
        assert {"label", "status", "scope", "evidence"} <= set(r)
    assert by_label["Eq. 39 (n = 4)"]["scope"] == "single case" and by_label["C1 (Reif's test)"]["scope"] == "every n"


def test_claims_command_unknown_label(capsys):
    assert main(["claims", "--label", "Eq. 99"]) == 2
    assert "no claim labelled Eq. 99" in capsys.readouterr().err


def test_prop51_check_can_fail():
    # with the vertex held fixed (alpha = beta = 0) an Eq. 43 eigenvalue exceeds lambda_1 at n = 3
    from symdecomp.schemes.scheme import catmull_clark

    result = check_claim("Proposition 5.1", catmull_clark(0, 0))
    assert result.status is Status.REFUTED and "n = 3" in str(result.counterexample)


def test_eq45_with_a_free_parameter_is_undecided_with_a_reason_not_an_error():
    # the vertex weight on the a's is a free parameter: Eq. 43's eigenvalues at n = 4 cannot be ordered by modulus
    from symdecomp.schemes.files import scheme_from_text

    text = ('name = "free"\nparameters = ["alpha"]\n[edge]\nO = "3/8"\na = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }\n'
            'b = { "-1" = "1/16", "0" = "1/16" }\n[face]\nO = "1/4"\na = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n'
            '[vertex]\na = "alpha/n**2"\nb = "1/(4*n**2)"\n')
    result = check_claim("Eq. 45", scheme_from_text(text))
    assert result.status is Status.UNDECIDED
    assert "free parameters alpha" in str(result.evidence)


def _registered(monkeypatch, check, requires=()):
    """A claim registered for the test only, under a label never used before (the registry caches per label and scheme)."""
    from symdecomp.claims import REGISTRY, Claim

    label = f"Eq. 99{next(_FRESH)}"
    monkeypatch.setitem(REGISTRY, label, Claim(label, "5.1", "t", "s", check, order=990, requires=tuple(requires)))
    return label


_FRESH = itertools.count()


def test_an_unmet_requirement_gives_not_applicable_with_its_reason_and_the_check_does_not_run(monkeypatch):
    from symdecomp.claims import Requirement
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.symbols import alpha, beta

    ran = []
    concrete = Requirement("no free parameters", lambda s: f"{s.name!r} has free parameters" if s.parameters else None)
    label = _registered(monkeypatch, lambda s: ran.append(s) or CheckResult(Status.PROVED, "x"), requires=(concrete,))
    assert check_claim(label, catmull_clark()).status is Status.PROVED and ran == [catmull_clark()]
    free = catmull_clark(alpha, beta)
    result = check_claim(label, free)
    assert result.status is Status.NOT_APPLICABLE and str(result.evidence) == f"{free.name!r} has free parameters"
    assert ran == [catmull_clark()]


def test_not_applicable_and_malformed_scheme_errors_inside_a_check(monkeypatch):
    from symdecomp.errors import InvalidSchemeError, NotApplicableError
    from symdecomp.schemes.scheme import catmull_clark

    def raising(error):
        def check(scheme):
            raise error
        return check

    for error in (NotApplicableError("needs a quad mesh"), InvalidSchemeError("needs a quad mesh")):
        result = check_claim(_registered(monkeypatch, raising(error)), catmull_clark())
        assert result.status is Status.NOT_APPLICABLE
        assert str(result.evidence) == "not applicable to the scheme 'catmull-clark': needs a quad mesh"
    result = check_claim(_registered(monkeypatch, raising(ZeroDivisionError("1/0"))), catmull_clark())
    assert result.status is Status.ERROR and "ZeroDivisionError" in str(result.evidence)


def test_the_mirror_symmetry_requirement_names_the_term_with_sin():
    from symdecomp.claims.applicability import MIRROR_SYMMETRIC, WHOLE_MESH
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.symbols import sin_jtheta
    from tests.claims.test_mutations import scheme

    assert MIRROR_SYMMETRIC.unmet(catmull_clark()) is None and WHOLE_MESH.unmet(catmull_clark()) is None
    reason = MIRROR_SYMMETRIC.unmet(scheme("asymmetric"))
    assert any(isinstance(p, sp.Basic) and p.has(sin_jtheta) for p in reason.parts)
    assert "whole meshes" in str(WHOLE_MESH.unmet(scheme("moved")))
    # the requirement itself, asked of each scheme the check reads (Claim.schemes_read): here the scheme given, except
    # where a claim reads another lattice's reference scheme in its place (B.1's Loop claims read Loop for a quad scheme)
    asymmetric = scheme("asymmetric")
    declared = {c.label for c in all_claims() if any(r is MIRROR_SYMMETRIC for r in c.requires) and asymmetric in c.schemes_read(asymmetric)}
    assert {"Proposition 5.1", "Remark 5.1", "Section 5.3: construction", "Curvature regime: Catmull-Clark",
            "Shape: the valence decides"} <= declared
    for label in declared:
        assert check_claim(label, scheme("asymmetric")).evidence == reason


def test_one_mirror_symmetry_requirement_one_reason_on_either_lattice():
    """Section 5's closed forms in c and the curvature regimes' real lambda_1 ask one requirement and give one reason (they
    were two, with two computations and two texts); its verdict is the invariance of M(omega)'s trace and determinant
    under omega -> 1/omega (the reflection j -> n - j), on quads and on triangles alike."""
    from symdecomp.analysis.frequency import one_ring_matrices
    from symdecomp.claims import applicability
    from symdecomp.claims.applicability import MIRROR_SYMMETRIC
    from symdecomp.expressions import identically_zero
    from symdecomp.schemes.files import scheme_from_text
    from symdecomp.schemes.loop import loop
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.symbols import omega
    from tests.claims.test_beyond_curvature_claims import _LOOP_WITH_EDGE_WEIGHTS
    from tests.claims.test_mutations import scheme

    assert not hasattr(applicability, "REAL_SUBDOMINANT")
    skew = scheme_from_text(_LOOP_WITH_EDGE_WEIGHTS.format(left="3/16", right="1/16"))
    twist = scheme_from_text(_LOOP_WITH_EDGE_WEIGHTS.format(left="1/8 + (n - 6)/64", right="1/8 - (n - 6)/64"))
    panel = (catmull_clark(), scheme("asymmetric"), scheme("frequency two"), loop(), skew, twist)
    for s in panel:
        M, _ = one_ring_matrices(s)
        mirrored = all(identically_zero(t - t.subs(omega, 1 / omega)) for t in (sp.expand(M.trace()), sp.expand(M.det())))
        assert (MIRROR_SYMMETRIC.unmet(s) is None) is mirrored, s.name
    assert [MIRROR_SYMMETRIC.unmet(s) is None for s in panel] == [True, False, True, True, False, False]
    asymmetric = scheme("asymmetric")
    reason = str(MIRROR_SYMMETRIC.unmet(asymmetric))
    for label in ("Proposition 5.1", "Section 5.3: smaller eigenvalues", "Curvature regime: Catmull-Clark", "Shape: the valence decides"):
        assert str(check_claim(label, asymmetric).evidence) == reason, label
    assert str(check_claim("Loop's vertex weight", skew).evidence) == str(MIRROR_SYMMETRIC.unmet(skew))


def test_claims_that_compute_with_numbers_are_not_applicable_to_a_scheme_with_free_parameters():
    from symdecomp.claims.applicability import NO_FREE_PARAMETERS
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.symbols import alpha, beta

    free = catmull_clark(alpha, beta)
    reason = f"the scheme {free.name!r} has free parameters alpha, beta; give them values first"
    assert str(NO_FREE_PARAMETERS.unmet(free)) == reason and NO_FREE_PARAMETERS.unmet(catmull_clark()) is None
    # "Section 5.3: construction" raised inside its check (status error) before it declared the requirement
    for label in ("C1 (Reif's test)", "Section 5.3: construction", "1-ring suffices (after Eq. 51)", "Larger neighbourhoods (after Eq. 51)"):
        result = check_claim(label, free)
        assert (result.status, str(result.evidence)) == (Status.NOT_APPLICABLE, reason), label
