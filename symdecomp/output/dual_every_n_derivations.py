"""Doo-Sabin's "C1 for every n" in the derivations (``c1-every-n.tex``), from the proof for dual schemes.

The proposition and its proof are typeset from :func:`~symdecomp.verify.c1_dual_every_n.c1_dual_every_n` the way
:mod:`symdecomp.output.every_n_derivations` typesets Catmull-Clark's and Loop's: the ``n``-gon's eigenvalues as the
symbol of its weights (closed forms in ``t = cos(2 pi/n)`` or in ``n``), the outer blocks' characteristic polynomial
and eigenvalues, each spectral step with its sign and how it was decided, the valences certified one by one (the
report's range, :data:`symdecomp.output.report_every_n.CERTIFIED`, which keeps ``symdecomp derive`` quick), and the
characteristic map for every ``n`` from the valence the blocks are read at: the Jacobian's Bezier coefficients
(polynomials in ``t``, their real roots in the interval counted by Sturm sequences, the first few factored) and the
wedge argument. The statement is :func:`~symdecomp.output.every_n_derivations.c1_statement` of the outcome.
"""

from __future__ import annotations

from collections import Counter

import flint
import sympy as sp

from symdecomp.claims import Verbatim
from symdecomp.output.every_n_derivations import EXAMPLES, c1_statement, step_where
from symdecomp.output.latex import display_math, text_latex
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import cached, check_valence
from symdecomp.verify.c1_every_n import EveryNResult, EveryNStep

__all__ = ["DUAL_CERTIFIED", "dual_every_n_proof", "dual_every_n_latex"]

#: The valences the dual test certifies one by one here: the report's range (about ten seconds; the command's 64 take
#: about two minutes), enough for the map's proof, which starts where the outer blocks are read.
DUAL_CERTIFIED = 16

_T = sp.Symbol("t", real=True)


def dual_every_n_proof(scheme: StencilScheme, certified: int = DUAL_CERTIFIED) -> EveryNResult:
    """C1 for every valence of a dual scheme (the dual test at ``3..certified``); cached, as the report asks it too."""
    return _dual_every_n_proof(scheme, certified)


def _check_stencil(value: object) -> StencilScheme:
    from symdecomp.validate import check_type

    return check_type(value, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('doo-sabin')")


@cached(4, scheme=_check_stencil, certified=lambda value: check_valence(value, argument="certified"))
def _dual_every_n_proof(scheme: StencilScheme, certified: int) -> EveryNResult:
    from symdecomp.verify.c1_dual_every_n import c1_dual_every_n

    return c1_dual_every_n(scheme, last=certified)


def _in_t(expr: sp.Expr) -> sp.Expr:
    """A value of the symbol with ``cos(2 pi p/n)`` as a polynomial in ``t`` (as the proof reads it), else as it is."""
    from symdecomp.verify.c1_dual_every_n import in_t as read_in_t

    found = read_in_t(expr)
    return expr if found is None else found.subs(sp.Symbol("t"), _T)


def _symbol_details(scheme: StencilScheme) -> str:
    """The ``n``-gon's eigenvalues by frequency and the outer blocks' characteristic polynomial and eigenvalues."""
    from symdecomp.verify.c1_dual_every_n import X, ngon_spectrum

    spectrum = ngon_spectrum(scheme)
    rows: dict[str, object] = {r"\sigma(0)": _in_t(spectrum.zero), r"\sigma(\pm 1)": _in_t(spectrum.first)}
    rows.update({rf"\sigma(k)\ (\text{{{k}}})": _in_t(v) for k, v in spectrum.others})
    poly = sp.Poly(spectrum.outer, X)
    roots = ", ".join(sp.latex(r) for r in sorted(set(poly.all_roots()), key=sp.default_sort_key)) \
        if not poly.free_symbols - {X} else ""
    text = text_latex(f"The $n$-gon's eigenvalues are the symbol $\\sigma(k) = \\sum_j w(n, j)\\, \\omega^{{jk}}$ of its "
                      f"weights, summed in closed form for every $n \\ge {spectrum.start}$ (in $t = \\cos(2\\pi/n)$ where "
                      "a value depends on it):") + "\n" + display_math(rows)
    text += text_latex(f"The outer blocks (the regular rules, every $n \\ge {spectrum.outer_start}$) have the "
                       "characteristic polynomial below" + (f", with the eigenvalues ${roots}$." if roots else ".")) + "\n"
    return text + display_math(spectrum.outer, r"\det(x I - B_S)")


def _jacobian_coefficients(scheme: StencilScheme, result: EveryNResult) -> list[flint.fmpq_poly]:
    """The Jacobian's Bezier coefficients of sector 0's patches, polynomials in ``t`` (as the map's proof forms them)."""
    from symdecomp.verify.c1_dual_every_n import ngon_spectrum
    from symdecomp.verify.c1_dual_uniform import dual_ring, jacobian_coefficients

    assert result.uniform is not None  # asked only of a proved map step
    return jacobian_coefficients(dual_ring(scheme, ngon_spectrum(scheme).first, result.uniform.first))


def _expr(q: flint.fmpq_poly) -> sp.Expr:
    """A FLINT polynomial in ``t`` as a sympy expression (exact rational coefficients)."""
    return sp.Add(*(sp.Rational(int(c.p), int(c.q)) * _T**k for k, c in enumerate(q.coeffs())))


def _regular_details(scheme: StencilScheme, result: EveryNResult) -> str:
    from symdecomp.algebra.interval_signs import count_roots

    assert result.uniform is not None
    low = result.uniform.t_low
    coefficients = _jacobian_coefficients(scheme, result)
    counts = Counter(count_roots(c, low, 1) for c in coefficients)
    tally = "; ".join(f"{k} with {r} real roots" for r, k in sorted(counts.items()))
    at_one = "each is" if all(c(1) > 0 for c in coefficients) else "not each is"
    shown = {f"J_{{{k}}}": sp.factor(_expr(c)) for k, c in enumerate(coefficients[:EXAMPLES])}
    return (text_latex(f"There are {len(coefficients)} coefficients; their real roots in $[{sp.latex(low)}, 1]$ (Sturm "
                       f"counts): {tally}, and {at_one} positive at $t = 1$. The first {min(EXAMPLES, len(coefficients))}, "
                       "factored:") + "\n" + display_math(shown))


#: What each named step shows, in words (its computed objects follow it).
_PROSE = {
    "real-distinct": r"The eigenvalue at frequency 1 is $\sigma(1)$, equal to $\sigma(-1)$ and real (exact "
    r"simplification): $\lambda_1 = \sigma(1)$ is a double eigenvalue (frequencies $1$ and $n - 1$):",
    "frequency-zero": r"The eigenvalue at frequency 0 is $\sigma(0) = 1$ for every $n$ (the weights sum to 1; the "
    "difference is identically zero):",
    "dominant": r"$\lambda_1 > 0$ and $\lambda_1^2 - |\sigma(k)|^2 > 0$ at every other frequency $k$: each a constant "
    r"(an exact sign), a rational function of $n$ (Sturm sequences on $[n_0, \infty)$) or a polynomial in $t$ (Sturm "
    "sequences on the interval of $t$):",
    "bounds": r"$\lambda_1 < 1$, and $\lambda_1$ exceeds $\rho_S$, a rational bound on the moduli of the outer blocks' "
    "eigenvalues, decided the same way:",
    "reif-per-valence": "The dual test (Reif's test on the ring of biquadratic patches) is certified at each valence of "
    "the range, one by one: the spectral conditions and a regular, injective characteristic map (Arb balls; exact at "
    "frequency 0). The range is the report's; symdecomp c1 --every-n certifies to 64.",
    "map-scale": r"The characteristic map for every $n$ at once: with $\lambda_1$ a rational constant, the frequency-1 "
    r"eigenvector is the $n$-gon's Fourier mode and $(\lambda_1 I - B(\omega))^{-1} C(\omega)$ on the outer classes, "
    r"Laurent polynomials in $\omega$ since $\det(\lambda_1 I - B(\omega))$ is the nonzero constant below:",
    "map-regular": r"Sector 0's biquadratic patches, raised to bicubic and stretched by $1/\sin(2\pi/n)$, give the "
    r"Jacobian's Bezier coefficients as polynomials in $t$; each is positive on the interval of $t$, decided by Sturm "
    "sequences: the map is regular.",
    "map-injective": r"Sector 0's inner boundary runs from a point $A$ on the ray of the $n$-gon's corner 0 to "
    r"$\omega A$ (exact identities), and its control points $(x, y)$ lie in the closed wedge $y \ge 0$, $x - t y \ge 0$ "
    r"between the rays of corners 0 and 1, none at the origin, for every $t$ in the interval: each sector's piece sweeps "
    r"$2\pi/n$, the boundary winds once, and with the positive Jacobian the map is injective.",
}


def _map_details(step: EveryNStep, scheme: StencilScheme, result: EveryNResult) -> str:
    u = result.uniform
    if step.status != "proved" or u is None:
        return ""
    if step.name == "map-scale":
        from symdecomp.verify.c1_dual_every_n import ngon_spectrum
        from symdecomp.verify.c1_dual_uniform import dual_ring

        scale = dual_ring(scheme, ngon_spectrum(scheme).first, u.first).scale
        return display_math(scale, r"\det(\lambda_1 I - B(\omega))")
    if step.name == "map-regular":
        return _regular_details(scheme, result)
    if step.name == "map-injective":
        from symdecomp.algebra.algebraic_sign import exact_sign

        points = u.coefficients - len(_jacobian_coefficients(scheme, result))
        below = "<" if exact_sign(sp.cos(2 * sp.pi / u.first) - u.t_low) > 0 else "\\ge"
        return text_latex(f"The boundary has {points} control points, each with the three signs decided on "
                          f"$[{sp.latex(u.t_low)}, 1]$, $t_0 {below} \\cos(2\\pi/{u.first})$ (exact sign).") + "\n"
    return ""


def _words(lhs: str) -> str:
    """A formula's name with its words in parentheses (``\\ (every other k)``) set as text."""
    head, sep, words = lhs.partition(r"\ (")
    return head + r"\ (\text{" + words[:-1] + "})" if sep and words.endswith(")") else lhs


def _step_latex(step: EveryNStep, scheme: StencilScheme, result: EveryNResult) -> str:
    head = "\\item[%s] %s, %s. " % (step.name or "step", step.status, step_where(step))
    prose = _PROSE.get(step.name)
    if step.status in ("proved", "verified") and prose:
        body = text_latex(prose) + "\n"
    else:  # an open or failed step says what was not shown, in the verify layer's words
        body = text_latex(Verbatim(step.text)) + "\n"
    if step.formulas:
        body += display_math({_words(lhs): _in_t(sp.sympify(v, strict=True)) for lhs, v in step.formulas})
    if step.name == "real-distinct":
        body += _symbol_details(scheme)
    return head + body + _map_details(step, scheme, result)


def dual_every_n_latex(scheme: StencilScheme, number: int = 1) -> str:
    """The subsection of one dual scheme: the proposition C1 for every n (numbered ``number``) and its proof."""
    result = dual_every_n_proof(scheme)
    lo, hi = result.certified
    out = "\\subsection*{%s}\n" % text_latex(Verbatim(scheme.name))
    out += f"\\paragraph{{Proposition {number}}} ($C^1$ for every $n \\ge 3$). \\emph{{{c1_statement(result, 'face')}}}\n\n"
    out += text_latex(f"The extraordinary element is an $n$-sided face. The valences certified one by one are "
                      f"$n = {lo}, \\dots, {hi}$, the report's range (symdecomp c1 --every-n goes to 64).") + "\n\n"
    out += "\\textit{Proof.}\n\\begin{description}\n" + "\n".join(_step_latex(s, scheme, result) for s in result.steps)
    return out + "\\end{description}\n\\hfill$\\square$\n"
