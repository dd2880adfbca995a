"""Doo-Sabin's C1 for every n in the derivations (issue 30): the proposition follows the computed verdict, and the proof
shows the computed objects (the n-gon's symbol, the outer eigenvalues, the Jacobian's coefficients and root counts)."""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.output.dual_every_n_derivations import DUAL_CERTIFIED, dual_every_n_latex, dual_every_n_proof
from symdecomp.output.every_n_derivations import EVERY_N_FILE, every_n_files
from symdecomp.output.report_every_n import CERTIFIED as REPORT_CERTIFIED
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text
from symdecomp.verify.c1_dual_every_n import X, ngon_spectrum

DOO_SABIN = "KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m)"


def variant(extra: str) -> str:
    """A Doo-Sabin file whose n-gon weights get ``extra`` (as in tests/verify/test_c1_dual_every_n.py)."""
    return ('name = "variant"\nmesh = "quad"\ntopology = "dual"\n\n[[corner]]\n'
            f'terms = [{{walk = "", weight = "{DOO_SABIN} + {extra}", over = "face"}}]\n')


def _flat(tex: str) -> str:
    return " ".join(tex.split())


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_doo_sabin_is_typeset_c1_for_every_n_from_the_proof():
    ds = load_zoo("doo-sabin")
    result = dual_every_n_proof(ds)
    assert DUAL_CERTIFIED == REPORT_CERTIFIED and result.certified == (3, DUAL_CERTIFIED)
    tex = _flat(dual_every_n_latex(ds, 5))
    assert result.status == "proved"
    assert "\\emph{The surface is $C^1$ at an extraordinary face of every valence $n \\ge 3$.}" in tex
    # every step of the proof, in its order, with its status and valences
    heads = [f"\\item[{s.name}] {s.status}," for s in result.steps]
    assert [tex.index(h) for h in heads] == sorted(tex.index(h) for h in heads)
    # the symbol's values and the outer blocks' eigenvalues are the computed ones (1/2 double, 1/4; 1/4, 1/8, 1/16)
    spectrum = ngon_spectrum(ds)
    assert f"\\sigma(\\pm 1) = {sp.latex(spectrum.first)}" in tex and spectrum.first == sp.Rational(1, 2)
    roots = sorted(set(sp.Poly(spectrum.outer, X).all_roots()))
    assert "with the eigenvalues $" + ", ".join(sp.latex(r) for r in roots) + "$" in tex
    assert max(roots) < spectrum.first
    # the Jacobian's coefficients: as many as the map's proof decided (less the boundary's points), none with a root
    points = int(tex.split("The boundary has ")[1].split()[0])
    assert result.uniform is not None
    total = result.uniform.coefficients - points
    assert f"There are {total} coefficients" in tex and f"{total} with 0 real roots" in tex


@pytest.mark.slow
def test_the_shown_coefficients_are_positive_on_the_interval():
    """J_0.. as typeset are polynomials in t, positive at the interval's ends and with no root inside (Sturm)."""
    from symdecomp.algebra.interval_signs import count_roots

    ds = load_zoo("doo-sabin")
    low = dual_every_n_proof(ds).uniform.t_low
    tex = dual_every_n_latex(ds, 5)
    t = sp.Symbol("t", real=True)
    shown = [line.split(" = ", 1)[1] for line in tex.splitlines() if line.startswith("J_{")]
    assert len(shown) == 3
    for text in shown:  # the factored forms are linear here: a t + b over c
        num, den = text.removeprefix("\\frac{").removesuffix("}").split("}{") if text.startswith("\\frac") else (text, "1")
        expr = sp.sympify(num.replace(" t", "*t"), locals={"t": t}) / sp.Integer(den)
        poly = flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in reversed(sp.Poly(expr, t).all_coeffs())])
        assert expr.subs(t, 1) > 0 and expr.subs(t, low) > 0 and count_roots(poly, low, 1) == 0


@pytest.mark.slow
def test_a_variant_that_fails_dominance_gets_the_failing_statement():
    """sigma(+-2) reaches lambda_1 = 1/2 at n = 6 (computed): not C1 there, and the failed step in the verify layer's words."""
    s = stencil_scheme_from_text(variant("(m - 4)*cos(4*pi*j/m)/(4*m)"))
    result = dual_every_n_proof(s)
    assert result.status == "refuted" and result.failure == 6
    tex = _flat(dual_every_n_latex(s, 1))
    assert "\\emph{The surface is not $C^1$ at an extraordinary face of valence $n = 6$.}" in tex
    assert "\\item[dominant] failed, $n \\ge 6$." in tex and "it fails at n = 6 and at every n after it" in tex


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_the_derivations_file_ends_with_doo_sabin_after_the_primal_schemes():
    text = every_n_files()[EVERY_N_FILE]
    assert text.index("\\subsection*{loop}") < text.index("\\subsection*{doo-sabin}")
    assert _flat(text).endswith(_flat(dual_every_n_latex(load_zoo("doo-sabin"), 5)))


def _report_section(scheme):
    from symdecomp.output.report_every_n import DUAL_TITLE
    from symdecomp.output.report_zoo import build_zoo_report

    [section] = [s for s in build_zoo_report(scheme, [4]).sections if s.title == DUAL_TITLE]
    return section


def test_the_zoo_report_has_doo_sabins_section_with_the_proofs_steps():
    from symdecomp.output.report_every_n import CERTIFIED

    ds = load_zoo("doo-sabin")
    section = _report_section(ds)
    result = dual_every_n_proof(ds, CERTIFIED)
    assert "at an extraordinary face of every valence $n \\ge 3$." in section.blocks[0].parts[1]
    assert [(str(r[0]), r[1]) for r in section.blocks[1].rows] == [(s.name, s.status) for s in result.steps]


def test_the_report_of_a_failing_variant_states_the_failure():
    section = _report_section(stencil_scheme_from_text(variant("(m - 4)*cos(4*pi*j/m)/(4*m)")))
    assert section.blocks[0].parts[1] == "The surface is not $C^1$ at an extraordinary face of valence $n = 6$."
    assert ("dominant", "failed", "$n \\ge 6$") in [(str(r[0]), r[1], r[2]) for r in section.blocks[1].rows]


def test_the_report_of_a_primal_zoo_scheme_says_why_not():
    section = _report_section(load_zoo("sqrt3"))
    assert str(section.blocks[0].parts[0]) == "Not applicable: " and "sqrt3" in str(section.blocks[0].parts[1])
