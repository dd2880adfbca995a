"""Beyond the paper: boundary and crease vertices (the toolkit's own claims, section B.2; issue 20, item 2).

A sector of ``k`` faces between two sharp edges has the mirror symmetry ``i -> k - i`` in place of the rotation:
its 1-ring matrix is block lower-triangular, a crease block ``C`` (``O`` and the two sharp-edge points, the
B-spline curve rules) and the interior, which the discrete sine polylines split into blocks ``M(pi j/k)``
(:mod:`symdecomp.analysis.mirror`, :mod:`symdecomp.analysis.mirror_threshold`). These claims state the
decomposition, the crease block's eigenvalues, where the first sine eigenvalue passes the boundary curve's,
and what Biermann-Levin-Zorin's modified rules do to it.

Source: H. Biermann, A. Levin, D. Zorin, *Piecewise smooth subdivision surfaces with normal control*, SIGGRAPH
2000. What could be read of it here is its abstract ("improved rules for Catmull-Clark and Loop subdivision that
overcome several problems with the original schemes, namely, lack of smoothness at extraordinary boundary vertices
and folds near concave corners"); its sections and equations could not be read, so the modified rule is stated
below as it is usually quoted (the weight ``gamma`` on the far end of a smooth edge at a crease vertex, ``3/4 -
gamma`` on the crease vertex, ``gamma = 3/8 - cos(theta_k)/4`` for Catmull-Clark and ``1/2 - cos(theta_k)/4`` for
Loop, ``theta_k = pi/k``), and each check computes from that printed weight, so another weight changes the status.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.mirror import THETA, THETA_K, crease_block, sine_block, sine_identity, with_near_edge
from symdecomp.analysis.mirror_threshold import C, X, charpoly_check, first_exceeding
from symdecomp.claims.applicability import NO_FREE_PARAMETERS
from symdecomp.claims.registry import CheckResult, Status, Step, Text, Verbatim, claim
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.sharp import standard_sharp_rules

#: As printed: the crease block's eigenvalues (the cubic B-spline curve's 1, 1/2, 1/4).
CREASE_EIGENVALUES = (sp.Integer(1), sp.Rational(1, 2), sp.Rational(1, 4))
#: As printed: from which k the first sine eigenvalue exceeds the boundary curve's 1/2, per kind of regular patch (the lattice's).
FIRST_K = {BICUBIC: 3, BOX_SPLINE: 4}
#: As printed (BLZ 2000, as quoted): the modified smooth edge rule at a crease vertex, ``(on the crease vertex, on the
#: far end)`` in the sector angle ``theta_k``, per kind of regular patch (the lattice's).
BLZ_RULE = {BICUBIC: (sp.Rational(3, 8) + sp.cos(THETA_K) / 4, sp.Rational(3, 8) - sp.cos(THETA_K) / 4),
            BOX_SPLINE: (sp.Rational(1, 4) + sp.cos(THETA_K) / 4, sp.Rational(1, 2) - sp.cos(THETA_K) / 4)}
#: The sector sizes of the cross-check with the assembled matrix.
SECTORS = (1, 12)


@claim(
    "Sector: sine decomposition",
    parameter="k",
    section="B.2",
    title="The sine polylines split a sector's interior into $2 \\times 2$ blocks, for every $k$",
    statement=r"In a sector of $k$ faces between two sharp edges, with mirror-symmetric smooth stencils, the polylines "
    r"$a_i = A \sin(i\theta)$, $b_i = B \sin((i + \frac12)\theta)$ with $\theta = \pi j/k$ vanish on $O$ and on the sharp "
    r"edges and are mapped to themselves by $(A, B) \mapsto M(\theta)(A, B)$, for $j = 1, \dots, k - 1$ (on triangles "
    r"$a_i = A \sin(i\theta)$ and $1 \times 1$ blocks); with the crease block and the face rule's weight ($j = k$) this "
    r"is the whole spectrum of the sector.",
)
def _sine(scheme: Scheme) -> CheckResult:
    residual, boundary = sine_identity(scheme)
    M = sine_block(scheme)
    steps = (Step("The block $M(\\theta)$ read from the smooth stencils", M),
             Step("Each interior stencil applied to the polylines minus $M(\\theta)$ times them (symbolic index $i$)", residual),
             Step("The polylines on the sharp edges $a_0$, $a_k$ at $\\theta = \\pi j/k$", boundary))
    if any(r != 0 for r in residual) or any(b != 0 for b in boundary):
        what = Text("for ", Verbatim(scheme.name), " the residual is ", residual)
        return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)
    return CheckResult(Status.PROVED, Text("for ", Verbatim(scheme.name), ", the residual reduces to 0 identically in the "
                                           "index and in theta, and the polylines vanish on the sharp edges for every k"),
                       steps=steps)


def check_crease(scheme: Scheme, printed=None) -> CheckResult:
    """The crease block's eigenvalues (the same for every ``k``) against ``printed`` (default :data:`CREASE_EIGENVALUES`)."""
    printed = CREASE_EIGENVALUES if printed is None else printed
    Cb = crease_block(scheme)
    x = sp.Symbol("x")
    computed = sp.factor(Cb.charpoly(x).as_expr())
    expected = sp.expand(sp.prod([x - v for v in printed]))
    steps = (Step("The crease block (rows O, a_0, a_k)", Cb), Step("Its characteristic polynomial", computed))
    if sp.expand(computed - expected) == 0:
        return CheckResult(Status.PROVED, Text("the characteristic polynomial of the crease block is ", computed,
                                               ", for every k (the block does not depend on k)"), steps=steps)
    eigen = sp.FiniteSet(*Cb.eigenvals())
    what = Text("the crease block's eigenvalues are ", eigen, " (characteristic polynomial ", computed, "), not ",
                sp.FiniteSet(*printed))
    return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)


@claim(
    "Sector: crease block",
    parameter="k",
    section="B.2",
    title="The crease block has the boundary curve's eigenvalues $1, \\frac12, \\frac14$",
    statement=r"$O$ and its two sharp-edge neighbours move by the crease rules alone (a block $C$ of the matrix, for "
    r"every $k$), and the eigenvalues of $C$ are those of the cubic B-spline curve: $1$, $\frac12$ (on $a_0 - a_k$, the "
    r"boundary curve's tangent) and $\frac14$.",
)
def _crease(scheme: Scheme) -> CheckResult:
    return check_crease(scheme)


def _both_lattices(scheme: Scheme, check) -> CheckResult:
    """A statement about Catmull-Clark and Loop: ``check`` on ``scheme``, then on the other lattice's reference scheme."""
    results = []
    for subject in (scheme, *(x.reference() for x in scheme.lattice.others())):
        results.append(check(subject))
        if results[-1].status is not Status.PROVED:
            return results[-1]
    evidence = [part for r in results for part in ("; and ", r.evidence)][1:]
    return CheckResult(Status.PROVED, Text(*evidence), steps=sum((r.steps for r in results), ()))


def _table(th) -> sp.Matrix:
    return sp.Matrix([[sp.Symbol("k"), sp.Symbol("relation")]] + [[k, sp.Symbol(r)] for k, r in sorted(th.table.items())])


def check_first_k(scheme: Scheme, printed=None, rules=None) -> CheckResult:
    """From which ``k`` the first sine eigenvalue exceeds the boundary curve's, for every ``k``, against ``printed``."""
    printed = scheme.lattice.select(FIRST_K, "the printed first k") if printed is None else printed
    th = first_exceeding(scheme, rules)
    steps = (Step("$g(c) = \\det(M - \\lambda) $ (or $M - \\lambda$), $c = \\cos(\\pi/k)$", th.g),
             Step("$t(c) = \\mathrm{tr}\\,M - 2\\lambda$", th.t),
             Step("The largest eigenvalue of $M(\\pi/k)$ against the boundary curve's, up to the last root of $g t$", _table(th)))
    if th.first == printed:
        return CheckResult(Status.PROVED, Text("for ", Verbatim(scheme.name), ": the first sine eigenvalue is above ", th.value,
                                               f" for every k >= {th.first} (exact signs up to k = {max(th.table)}; beyond, "
                                               "c = cos(pi/k) is past the last root of g t below 1)"), steps=steps)
    what = Text("for ", Verbatim(scheme.name), f": the statement says from k = {printed}; computed: ",
                f"from k = {th.first}" if th.first else "never from some k on", f" (relation {th.beyond} for large k)")
    return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)


@claim(
    "Sector: standard rules' subdominant eigenvalue",
    parameter="k",
    section="B.2",
    title="With the standard rules the first sine eigenvalue exceeds $\\frac12$ from $k = 3$ (Catmull-Clark), $k = 4$ (Loop)",
    statement=r"With the standard boundary rules the largest eigenvalue of $M(\pi/k)$ exceeds the boundary curve's "
    r"$\frac12$ for every $k \ge 3$ on Catmull-Clark surfaces and every $k \ge 4$ on Loop surfaces (it equals "
    r"$\frac12$ at the regular $k = 2$, resp. $k = 3$): the subdominant eigenvector is then a sine polyline that "
    r"vanishes on the boundary, which is why the standard rules lack smoothness at extraordinary boundary vertices "
    r"(Biermann, Levin, Zorin, SIGGRAPH 2000, abstract).",
    requires=(NO_FREE_PARAMETERS,),
)
def _first_k(scheme: Scheme) -> CheckResult:
    # the statement's hypothesis is the standard boundary rules: a scheme's own sharp rules (BLZ's modified edge rule in
    # loop-blz, catmull-clark-blz) are another statement ("Sector: modified rules"), so its smooth rules meet the standard ones
    return _both_lattices(scheme, lambda subject: check_first_k(subject, rules=standard_sharp_rules()))


def check_blz(scheme: Scheme, printed=None) -> CheckResult:
    """BLZ's modified rule (``printed``: ``(centre, end)`` in ``theta_k``) makes ``1/2`` an eigenvalue of ``M(pi/k)``."""
    centre, end = scheme.lattice.select(BLZ_RULE, "BLZ's printed rule") if printed is None else printed
    rules = with_near_edge(scheme, centre, end)
    th = first_exceeding(scheme, rules)
    M1 = sine_block(scheme, rules).subs(THETA_K, THETA)
    steps = (Step("$M(\\theta)$ with the modified rule, $\\theta_k = \\theta$ (the block j = 1)", M1),
             Step("$g(c) = \\det(M - \\frac12)$ (or $M - \\frac12$)", th.g), Step("$t(c)$", th.t))
    if th.identically:
        return CheckResult(Status.PROVED, Text("for ", Verbatim(scheme.name), " with the modified rule, ", th.value,
                                               " is an eigenvalue of M(pi/k) identically in c = cos(pi/k): every k"),
                           steps=steps)
    k = next(k for k in range(2, 65) if sp.simplify(th.g.subs(C, sp.cos(sp.pi / k))) != 0)
    what = Text("for ", Verbatim(scheme.name), f" at k = {k}: g = ", sp.simplify(th.g.subs(C, sp.cos(sp.pi / k))), ", not 0")
    return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)


@claim(
    "Sector: modified rules (BLZ 2000)",
    parameter="k",
    section="B.2",
    title="Biermann-Levin-Zorin's modified edge rule puts the first sine eigenvalue at $\\frac12$ for every $k$",
    statement=r"With the modified rule for a smooth edge at a crease vertex (weight $\gamma$ on its far end, "
    r"$\frac34 - \gamma$ on the crease vertex; $\gamma = \frac38 - \frac14\cos\theta_k$ for Catmull-Clark, "
    r"$\gamma = \frac12 - \frac14\cos\theta_k$ for Loop, $\theta_k = \pi/k$), the block $M(\pi/k)$ has the eigenvalue "
    r"$\frac12$ of the boundary curve for every $k$ (Biermann, Levin, Zorin, SIGGRAPH 2000).",
    requires=(NO_FREE_PARAMETERS,),
)
def _blz(scheme: Scheme) -> CheckResult:
    return _both_lattices(scheme, check_blz)


def _as_expr(poly) -> sp.Expr:
    return sum((sp.Rational(int(c.p), int(c.q)) * X**i for i, c in enumerate(poly.coeffs())), sp.Integer(0))


def check_against_matrix(scheme: Scheme, sectors: tuple[int, int] = SECTORS) -> CheckResult:
    """The blocks' characteristic polynomials against the 1-ring matrix's, exactly, for boundary sectors of k faces."""
    lo, hi = sectors
    for k in range(lo, hi + 1):
        equal, full, blocks = charpoly_check(scheme, k)
        if not equal:
            what = Text("for ", Verbatim(scheme.name), f" at k = {k} the matrix's characteristic polynomial is ",
                        _as_expr(full), " and the blocks' ", _as_expr(blocks))
            return CheckResult(Status.REFUTED, what, counterexample=what)
    last = charpoly_check(scheme, lo)[1]
    steps = (Step(f"The characteristic polynomial at k = {lo}", sp.factor(_as_expr(last))),)
    return CheckResult(Status.VERIFIED, Text("for ", Verbatim(scheme.name), f": the characteristic polynomial of the 1-ring "
                                             f"matrix by refinement equals the product of the blocks' for every k = {lo}..{hi} (FLINT rationals)"),
                       steps=steps, valences=(lo, hi))


@claim(
    "Sector: the blocks are the spectrum",
    parameter="k",
    section="B.2",
    title="The crease and sine blocks give the characteristic polynomial of the boundary 1-ring",
    statement=r"For a boundary vertex with $k = 1, \dots, 12$ faces the characteristic polynomial of the 1-ring matrix "
    r"(by exact refinement of the tagged mesh, which knows nothing of the blocks) is "
    r"that of the crease block times $\mathrm{Res}_c(U_{k-1}(c), \det(x - M(c)))$ (the sine blocks at the roots "
    r"$\cos(\pi j/k)$ of the Chebyshev polynomial $U_{k-1}$) times $x - h_0$ (the face rule's weight, quads).",
    requires=(NO_FREE_PARAMETERS,),
)
def _against_matrix(scheme: Scheme) -> CheckResult:
    return check_against_matrix(scheme)


#: As printed: the frequency of the boundary tangent's continuation into the sector, per kind of regular patch (the lattice's).
TANGENT_FREQUENCY = {BICUBIC: sp.pi / 2, BOX_SPLINE: sp.pi / 3}


def check_tangent(scheme: Scheme, printed=None) -> CheckResult:
    """The eigenvector of the boundary curve's eigenvalue continues as ``sin(phi (i - k/2))``: ``det(M(phi) - 1/2) = 0``."""
    phi = scheme.lattice.select(TANGENT_FREQUENCY, "the printed tangent frequency") if printed is None else printed
    residual, _ = sine_identity(scheme)
    th = first_exceeding(scheme)
    at = sp.simplify(th.g.subs(C, sp.cos(phi)))
    M = sine_block(scheme).subs(THETA, phi)
    steps = (Step("$g(c) = \\det(M(\\phi) - \\frac12)$ (or $M(\\phi) - \\frac12$), $c = \\cos\\phi$", th.g),
             Step("$g$ at the printed frequency", at), Step("$M(\\phi)$ there", M.applyfunc(sp.simplify)))
    if at == 0 and all(r == 0 for r in residual):
        return CheckResult(Status.PROVED, Text("for ", Verbatim(scheme.name), ": g(cos(phi)) = 0 at phi = ", phi, ", and the "
                                               "sine identity holds at every phase, so a_i = sin(phi (i - k/2)) (with O = 0 and "
                                               "the sharp-edge values it gives) is an eigenvector of ", th.value, " for every k "
                                               "where sin(phi k/2) is not 0"), steps=steps)
    what = Text("for ", Verbatim(scheme.name), ": g(cos(phi)) at phi = ", phi, " is ", at, ", not 0")
    return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)


@claim(
    "Sector: the boundary tangent's continuation",
    parameter="k",
    section="B.2",
    title="The boundary tangent continues into the sector as a sine of frequency $\\pi/2$ (Catmull-Clark), $\\pi/3$ (Loop)",
    statement=r"The eigenvector of the crease block's $\frac12$ ($O = 0$, $a_0 = -a_k$) continues into a sector of $k$ "
    r"faces as the antisymmetric polyline $a_i = A \sin(\phi (i - \frac k2))$, $b_i = B \sin(\phi (i + \frac12 - "
    r"\frac k2))$ with $\phi = \pi/2$ on Catmull-Clark surfaces and $\phi = \pi/3$ on Loop surfaces, for every $k$ with "
    r"$\sin(\phi k/2) \ne 0$; where $\phi = \pi j/k$ (even $k$, resp. $k$ a multiple of 3) $\frac12$ is also a sine "
    r"eigenvalue.",
    requires=(NO_FREE_PARAMETERS,),
)
def _tangent(scheme: Scheme) -> CheckResult:
    return _both_lattices(scheme, check_tangent)
