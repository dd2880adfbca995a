"""Claims for a scheme given as a file: the issue's Catmull-Clark file gives the built-in statuses, and a file
with one weight moved by 1/64 gives statuses that agree with iterating that scheme's own subdivision matrix."""

import json

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.claims import Status, all_claims, check_claim
from symdecomp.cli import main
from symdecomp.schemes.files import scheme_from_text
from symdecomp.schemes.scheme import subdivision_matrix
from tests.claims.test_claim_statuses import EXPECTED
from tests.claims.test_mutations import MOVED
from tests.schemes.test_scheme_files import CC_TOML


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_the_catmull_clark_file_gives_the_built_in_statuses(tmp_path, capsys):
    path = tmp_path / "cc.toml"
    path.write_text(CC_TOML)
    assert main(["claims", "--scheme", str(path), "--json", "--section", "5.1"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert {r["label"]: r["status"] for r in rows} == {k: v.value for k, v in EXPECTED.items() if k in {r["label"] for r in rows}}
    scheme = scheme_from_text(CC_TOML)
    assert {c.label: check_claim(c.label, scheme).status for c in all_claims()} == EXPECTED


def _iterate(S, x, steps):
    with mpmath.workdps(40):
        A = mpmath.matrix(S.tolist())
        v = mpmath.matrix(x)
        norms = []
        for _ in range(steps):
            v = A * v
            norms.append(mpmath.norm(v))
        return norms


def _lambda1(scheme, n):
    return sp.N(tangent_eigenvalues(scheme).dominant.subs(sp.Symbol("c", real=True), sp.cos(sp.pi / n)), 40)


def test_moved_scheme_remark_5_1_agrees_with_its_matrix():
    moved = scheme_from_text(MOVED)
    result = check_claim("Remark 5.1", moved)
    assert result.status is Status.REFUTED
    # iterate the component j = n + 1 alone (a's and b's on the 2n-gon mode) with the scheme's own matrix
    n = 5
    S = subdivision_matrix(moved, n).evalf(40)
    zeta = [sp.exp(sp.I * sp.pi * (n + 1) * m / n) for m in range(2 * n)]
    x = [0] + [sp.re(zeta[2 * i]).evalf(40) for i in range(n)] + [sp.re(zeta[2 * i + 1]).evalf(40) for i in range(n)]
    norms = _iterate(S, x, 60)
    rate = norms[-1] / norms[-2]
    assert abs(rate - _lambda1(moved, n)) < 1e-12  # it shrinks at the tangent-plane rate: not filtered out
    assert "n = 3" in str(result.counterexample)  # the smallest valence, computed for this scheme


def test_moved_scheme_eq_34_and_prop_5_1_agree_with_its_matrix():
    moved = scheme_from_text(MOVED)
    assert check_claim("Eq. 34", moved).status is Status.REFUTED
    assert check_claim("Proposition 5.1", moved).status is Status.PROVED  # certified range plus the exact tail bound
    n = 5
    with mpmath.workdps(30):
        eigs = sorted((abs(e) for e in mpmath.eig(mpmath.matrix(subdivision_matrix(moved, n).evalf(30).tolist()))[0]), reverse=True)
    lam1 = _lambda1(moved, n)
    # the largest eigenvalue after 1 is the derived lambda_1, twice (j = 1 and j = n - 1): Prop. 5.1
    assert abs(eigs[1] - lam1) < 1e-20 and abs(eigs[2] - lam1) < 1e-20 and eigs[3] < lam1 - 1e-3
    # the printed Eq. 34 value at j = 1 is not an eigenvalue of this matrix; the counterexample names both
    printed = sp.N(sp.Rational(1, 4) + sp.cos(sp.pi / n) ** 2 / 8 + sp.cos(sp.pi / n) / 4 * sp.sqrt(1 + sp.cos(sp.pi / n) ** 2 / 4), 30)
    assert min(abs(e - printed) for e in eigs) > 1e-3
    counterexample = str(check_claim("Eq. 34", moved).counterexample)
    assert str(sp.N(lam1, 12)) in counterexample and str(sp.N(printed, 12)) in counterexample


@pytest.mark.slow
def test_moved_scheme_eq_39_and_the_n4_finding_agree_with_its_matrix():
    moved = scheme_from_text(MOVED)
    n = 4
    S = subdivision_matrix(moved, n).evalf(40)
    # component j = 1 of the 2n-gon: after many steps B^1/A^1 settles to the ratio on the dominant eigenvector
    zeta = [sp.exp(sp.I * sp.pi * m / n).evalf(40) for m in range(2 * n)]
    x = sp.Matrix([0] + [zeta[2 * i] for i in range(n)] + [zeta[2 * i + 1] for i in range(n)])
    for _ in range(80):
        x = (S * x).evalf(40)
    ratio = sp.N(x[1 + n] / x[1], 20)  # b_0 / a_0
    result = check_claim("Eq. 39 (n = 4)", moved)
    assert result.status is Status.REFUTED
    derived = sp.N(sp.sympify(result.steps[0].expr), 20)
    assert abs(complex(ratio) - complex(derived)) < 1e-12 and abs(complex(ratio) - (1 + 1j)) > 1e-3
    # the n = 4 finding: with this scheme's weights mu != lambda_1^2 at n = 4 (eigenvalues of S itself)
    assert check_claim("Section 5.2: Catmull-Clark example", moved).status is Status.REFUTED
    with mpmath.workdps(30):
        eigs = sorted((abs(e) for e in mpmath.eig(mpmath.matrix(S.tolist()))[0]), reverse=True)
    lam1 = _lambda1(moved, n)
    assert min(abs(e - lam1**2) for e in eigs) > 1e-4


def test_the_claims_about_face_neighbours_are_set_aside_for_a_triangle_scheme_with_that_reason(capsys):
    """``claims --scheme loop`` runs (it used to refuse a triangle-mesh scheme): the claims about the quad 1-ring's
    face neighbours ``b_i`` declare that requirement, so for Loop they are not applicable with that reason (they
    raised on a scheme without a face rule), and for Catmull-Clark they are checked."""
    from symdecomp.claims.applicability import FACE_NEIGHBOURS
    from symdecomp.schemes.loop import loop
    from symdecomp.schemes.scheme import catmull_clark

    assert main(["claims", "--scheme", "loop", "--section", "3", "--json", "--no-progress"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    reason = str(FACE_NEIGHBOURS.unmet(loop()))
    assert "no face neighbours b_i" in reason and FACE_NEIGHBOURS.unmet(catmull_clark()) is None
    assert rows and all((r["status"], r["evidence"]) == (Status.NOT_APPLICABLE.value, reason) for r in rows)
    staged = [c.label for c in all_claims() if FACE_NEIGHBOURS in c.requires]
    assert {"Eq. 14-15", "Eq. 17-21", "Section 5.3: basis function"} <= set(staged)
    for label in staged:
        assert (check_claim(label, loop()).status, str(check_claim(label, loop()).evidence)) == (Status.NOT_APPLICABLE, reason)
    for label in ("Eq. 14-15", "Eq. 17-21"):  # the same claims on Catmull-Clark's quads are checked
        assert check_claim(label, catmull_clark()).status is Status.PROVED


@pytest.mark.slow  # 15-25 s: every claim for Loop
def test_a_triangle_mesh_scheme_gets_every_claim_checked_or_set_aside_with_its_reason(tmp_path, capsys):
    """``claims --scheme loop`` lists every claim: those whose checks read Loop's model (Section 2, C1, the
    curvature and sector claims) are checked, and those about the quad 1-ring's face neighbours ``b_i`` are not
    applicable with that reason; no check breaks on a scheme without a face rule."""
    from symdecomp.claims.applicability import FACE_NEIGHBOURS
    from symdecomp.schemes.loop import loop
    from symdecomp.schemes.scheme import catmull_clark

    assert main(["claims", "--scheme", "loop", "--json", "--no-progress"]) == 0
    rows = {r["label"]: r for r in json.loads(capsys.readouterr().out)["rows"]}
    assert list(rows) == [c.label for c in all_claims()]
    assert not [label for label, r in rows.items() if r["status"] == Status.ERROR.value]
    assert rows["Loop's vertex weight"]["status"] == rows["Curvature regime: Loop"]["status"] == Status.PROVED.value
    assert rows["C1 (Reif's test)"]["status"] == Status.PROVED.value and "loop" in rows["C1 (Reif's test)"]["evidence"]
    reason = str(FACE_NEIGHBOURS.unmet(loop()))
    staged = [c.label for c in all_claims() if FACE_NEIGHBOURS in c.requires]
    assert len(staged) >= 7
    for label in staged:  # each needs the face neighbours: set aside for Loop, checked for Catmull-Clark
        assert (rows[label]["status"], rows[label]["evidence"]) == (Status.NOT_APPLICABLE.value, reason)
        assert check_claim(label, catmull_clark()).status is not Status.NOT_APPLICABLE


#: Statements about the quad 1-ring's 2n-gon (a_i, b_i), its components A^j, B^j or the staged Catmull-Clark rules,
#: whose checks read no face rule (or only the vertex rule's weights) and so once ran on a triangle scheme too.
QUAD_RING_STATEMENTS = ("Eq. 10-11", "Eq. 12-13", "Eq. 16", "Eq. 22", "Eq. 23", "Eq. 24", "Eq. 25-30", "Eq. 40", "Eq. 41")


@pytest.mark.parametrize("name", ["loop", "loop-warren", "loop-blz"])
def test_statements_about_the_quad_2n_gon_are_no_verdict_about_a_triangle_scheme(name):
    """Before, these were proved (or, for Eq. 16, corrected with Loop's centre weight called "standard Catmull-Clark's")
    for Loop; a triangle 1-ring is the n-gon (a_i), so they are not applicable with the computed reason."""
    from symdecomp.claims.applicability import FACE_NEIGHBOURS
    from symdecomp.schemes.files import load_scheme
    from symdecomp.schemes.scheme import catmull_clark

    triangle = load_scheme(name)
    reason = FACE_NEIGHBOURS.unmet(triangle)
    assert reason is not None and repr(name) in str(reason)
    for label in QUAD_RING_STATEMENTS:
        result = check_claim(label, triangle)
        assert (result.status, str(result.evidence)) == (Status.NOT_APPLICABLE, str(reason)), label
        assert check_claim(label, catmull_clark()).status is EXPECTED[label]


def test_eq_16_names_the_vertex_weights_of_the_scheme_it_was_given():
    """A quad file whose vertex rule is not Catmull-Clark's: the evidence names the file and the weight on O computed
    from its own alpha = 1/(8n), beta = 1/(16n), 1 - n alpha - n beta = 13/16 (once it said "standard Catmull-Clark's")."""
    from symdecomp.symbols import n
    from tests.claims.test_one_model import OWN_REGULAR_VERTEX

    scheme = scheme_from_text(OWN_REGULAR_VERTEX)
    each_a, each_b = scheme.vertex_rule.each_a, scheme.vertex_rule.each_b
    assert sp.simplify(1 - n * (each_a + each_b) - sp.Rational(13, 16)) == 0
    evidence = str(check_claim("Eq. 16", scheme).evidence)
    assert "Catmull-Clark" not in evidence
    assert evidence.endswith(f"the vertex rule of the scheme {scheme.name!r} (alpha = 1/(8*n), beta = 1/(16*n)) gives O the "
                             "weight 13/16")
    assert str(check_claim("Eq. 16").evidence).endswith("the vertex rule of the scheme 'catmull-clark' (alpha = 3/(2*n**2), "
                                                        "beta = 1/(4*n**2)) gives O the weight 1 - 7/(4*n)")


def test_eq_16_counterexample_is_searched_where_the_schemes_weights_hide_the_error():
    """A vertex rule with alpha = beta = 0 at n = 3 satisfies the printed rule there; the counterexample moves to the
    first valence where the printed weights do not sum to one (n = 4, with the file's own weights), computed rather than
    a typed fallback."""
    from symdecomp.symbols import alpha, beta, n
    from tests.claims.test_one_model import OWN_REGULAR_VERTEX

    text = OWN_REGULAR_VERTEX.replace('a = "1/(8*n)"\nb = "1/(16*n)"', 'a = "(n - 3)/(8*n)"\nb = "(n - 3)/(16*n)"')
    scheme = scheme_from_text(text)
    assert scheme.vertex_rule.each_a.subs(n, 3) == 0 == scheme.vertex_rule.each_b.subs(n, 3)
    counterexample = check_claim("Eq. 16", scheme).counterexample
    exact = [p for p in counterexample.parts if isinstance(p, sp.Basic)]
    printed_sum = 1 + (n - 1) * (alpha + beta)  # 1 - alpha - beta + n alpha + n beta
    example = {n: 4, alpha: sp.Rational(1, 32), beta: sp.Rational(1, 64)}
    assert sp.Eq(n, 4) in exact and sp.Eq(alpha, example[alpha]) in exact and sp.Eq(beta, example[beta]) in exact
    assert printed_sum.subs(example) in exact and printed_sum.subs(example) == sp.Rational(73, 64)
