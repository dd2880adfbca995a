"""C1 for every valence of a dual scheme whose regular part is the biquadratic B-spline (Doo-Sabin and its variants).

The extraordinary element is an ``n``-gon. Where the scheme's corner rule stays inside the face (it reads only the
face's corners: :func:`~symdecomp.verify.c1_zoo.corner_weights`), the ``n``-gon's new points are the circulant of the
rule's weights ``w(n, j)`` applied to its old corners, for every ``n`` (the ``n``-gon's vertices have the regular
valence, so the rule chosen is the same at every ``n``). The matrix is block triangular with that circulant as a
diagonal block, and its eigenvalue at frequency ``k`` is the *symbol* ``sigma(k) = sum_j w(n, j) omega^(jk)``,
summed in closed form for every ``n`` (:mod:`symdecomp.analysis.zoo_symbols`: a value at the exceptional frequencies
``0, +-p`` and one value at every other frequency). The other eigenvalues are the outer classes' blocks in the
structural form of the matrix (:mod:`symdecomp.analysis.zoo_structure`, every ``n`` from its :attr:`valid_from`).

Reif's spectral conditions then read, for every ``n`` from the symbol's first valence (``lambda_1 = sigma(1)``):

* ``real-distinct``: ``sigma(1) = sigma(-1)``, real: ``lambda_1`` is a double eigenvalue (frequencies ``1, n - 1``);
* ``dominant``: ``lambda_1 > 0`` and ``lambda_1^2 - |sigma(k)|^2 > 0`` at every other frequency ``k != 0, +-1``;
* ``frequency-zero``: ``sigma(0) = 1`` identically (the eigenvalue 1, simple by the bounds);
* ``bounds``: ``lambda_1 < 1``, and ``lambda_1`` above the outer blocks' eigenvalues (a polynomial free of ``omega``
  and ``n``: constants of the regular rule), from the structural form's first valence.

Each sign is exact for every ``n``: a rational function of ``n`` by Sturm sequences on ``[n_0, oo)``
(:func:`~symdecomp.algebra.valence_signs.positive_from`), or a polynomial in ``t = cos(2 pi/n)`` on ``[t_0, 1]``
(:func:`~symdecomp.algebra.valence_signs.sign_on_interval`); where a condition fails, the first valence where it fails
is computed (a threshold), and where a value is neither (``n`` and ``t`` mixed, a weight that is no trigonometric
polynomial in ``j``) the step says so and the verdict stops at the valences tested one by one.

The characteristic map is certified per valence by the dual test (:func:`~symdecomp.verify.c1_zoo.c1_zoo`, Reif's test on
the ring of biquadratic patches) at ``n = 3..last``, and for every ``n`` from the valence the blocks are read at by
exact signs in ``t = cos(2 pi/n)`` (:mod:`symdecomp.verify.c1_dual_uniform`); where that argument does not close (or
``last`` stops short of it) the map is open beyond ``last`` and the verdict is at most ``verified``
(:func:`~symdecomp.verify.c1_every_n.c1_every_n`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign, rational_between
from symdecomp.algebra.valence_signs import positive_from, sign_on_interval
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.validate import check_int, check_type
from symdecomp.verify.c1_every_n import EveryNResult, EveryNStep, T, c1_every_n
from symdecomp.verify.c1_uniform import UniformMapResult, t_lower_bound

__all__ = ["NgonSpectrum", "ngon_spectrum", "dual_spectral_every_n", "c1_dual_every_n", "in_t"]


@dataclass(frozen=True)
class NgonSpectrum:
    """The ``n``-gon's eigenvalues by frequency for every ``n``, and the outer blocks' characteristic polynomial."""

    #: ``sigma(1)``, ``sigma(-1)``, ``sigma(0)``: expressions in ``n``.
    first: sp.Expr
    first_conjugate: sp.Expr
    zero: sp.Expr
    #: ``(frequency in words, value)`` at every other frequency: the exceptional ones, then ``"other"``.
    others: tuple[tuple[str, sp.Expr], ...]
    #: The first valence the closed forms hold at (the exceptional frequencies distinct).
    start: int
    #: ``det(x I - B_outer)`` in ``x`` (it may hold ``omega`` and ``n``), and the valence the structural form holds from.
    outer: sp.Expr
    outer_start: int


X = sp.Symbol("x")


def ngon_spectrum(scheme: StencilScheme) -> NgonSpectrum:
    """The ``n``-gon's symbol and the outer blocks for every ``n`` (module docstring); :class:`NotApplicableError` (one line)
    where the scheme is not a dual scheme with the biquadratic regular part or its ``n``-gon rule has no symbol."""
    from symdecomp.analysis.zoo_structure import READ_AT, zoo_structure
    from symdecomp.verify.c1_zoo import corner_weights, spline_route

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('doo-sabin')")
    reason = spline_route(scheme)
    if reason is not None:
        raise NotApplicableError(f"scheme {scheme.name!r}: {reason.split('; ')[0]}")
    inside = corner_weights(scheme, READ_AT, lattice(scheme.lattice).regular_valence)
    if isinstance(inside, str):
        raise NotApplicableError(f"scheme {scheme.name!r}: the n-gon's rule is not a circulant of its corners: {inside}")
    st = zoo_structure(scheme)
    entry = sp.sympify(st.block[0, 0], strict=True)
    if any(e != 0 for e in st.block[0, 1:]) or entry.has(sp.Symbol("omega")) or not entry.free_symbols <= {*st.sigma, N}:
        raise NotApplicableError(f"scheme {scheme.name!r}: the n-gon's block is not the symbol of its weights alone ({entry})")
    symbols = dict(zip(st.sigma, st.symbols))
    exceptional = sorted({k for s in st.symbols for k in s.at}, key=lambda k: (abs(k), k))

    def value(k: int | None) -> sp.Expr:
        subs = {sig: (s.otherwise if k is None else s.value(k)).subs(s.size, N) for sig, s in symbols.items()}
        return sp.simplify(entry.xreplace(subs))

    others = tuple((f"k = {k}", value(k)) for k in exceptional if k not in (0, 1, -1)) + (("every other k", value(None)),)
    start = max([3] + [s.valid_from for s in st.symbols])
    outer = sp.Matrix(st.block)[1:, 1:]
    return NgonSpectrum(value(1), value(-1), value(0), others, start, sp.factor(outer.charpoly(X).as_expr()), st.valid_from)


def in_t(expr: sp.Expr) -> sp.Expr | None:
    """``expr`` with ``cos(2 pi p/n)`` as ``T_p(t)``: a rational function of ``n`` alone, or of ``t`` alone, else ``None``."""
    expr = sp.sympify(expr, strict=True).rewrite(sp.cos)
    subs = {}
    for c in expr.atoms(sp.cos):
        p = sp.simplify(c.args[0] * N / (2 * sp.pi))
        if not p.is_Integer:
            return None
        subs[c] = sp.chebyshevt(abs(int(p)), T)
    out = sp.cancel(expr.xreplace(subs))
    return None if out.has(N) and out.has(T) or out.has(sp.sin) or out.has(sp.I) else out


def _positive(expr: sp.Expr, start: int) -> bool | None:
    """Whether ``expr`` is positive at every valence ``n >= start``; ``None`` where that is not decidable here."""
    e = in_t(expr)
    if e is None:
        return None
    if not e.free_symbols:
        return exact_sign(e) > 0
    try:
        if e.has(N):
            return positive_from(e, N, start)
        numerator, denominator = sp.fraction(e)
        if denominator.has(T):
            return None
        return bool(sign_on_interval(numerator * sp.sign(denominator), T, t_lower_bound(start), 1))
    except InvalidInputError:
        return None


def _first_failure(expr: sp.Expr, start: int) -> int | None:
    """The first valence ``n >= start`` where ``expr`` (a rational function of ``n``) is not positive, exactly."""
    e = in_t(expr)
    if e is None or e.has(T):
        return None
    if not e.has(N):
        return start if exact_sign(e) <= 0 else None
    numerator, denominator = (sp.Poly(p, N) for p in sp.fraction(sp.together(e)))
    roots = [r for p in (numerator, denominator) if p.degree() > 0 for r in p.real_roots()]
    candidates = sorted({start} | {int(sp.floor(r)) + d for r in roots for d in (0, 1) if sp.floor(r) + d >= start})
    return next((k for k in candidates if denominator.eval(k) == 0 or exact_sign(e.subs(N, k)) <= 0), None)


def _step(name: str, text: str, facts: list[sp.Expr], start: int, formulas: tuple[tuple[str, object], ...]) -> EveryNStep:
    """A step that holds when every fact is positive for ``n >= start``; failed with the first valence that breaks one
    (computed), open where none is found."""
    shown = [_positive(f, start) for f in facts]
    if all(s is True for s in shown):
        return EveryNStep(text, "proved", (start, None), name, formulas)
    if any(s is None for s in shown):
        which = next(f for f, s in zip(facts, shown) if s is None)
        return EveryNStep(f"{text}: not decided for every n ({which} is neither a rational function of n nor a polynomial "
                          "in t = cos(2 pi/n)); the valences are tested one by one", "open", (start, None), name, formulas)
    failures = sorted((k, f) for f, s in zip(facts, shown) if s is False for k in [_first_failure(f, start)] if k is not None)
    if not failures:
        # a sign not shown with no valence where it fails computed: nothing is disproved
        return EveryNStep(f"{text}: not shown for every n >= {start}", "open", (start, None), name, formulas)
    first, fact = failures[0]
    beyond = _positive(-fact, first + 1) is True  # negative at every valence after the first failure
    where = f"it fails at n = {first}" + (" and at every n after it" if beyond else "")
    return EveryNStep(f"{text}: {where}", "failed", (first, None if beyond else first), name, formulas)


def _outer_radius(spectrum: NgonSpectrum) -> sp.Expr | None:
    """A rational above the largest modulus of the outer blocks' eigenvalues (constants), or ``None`` if they vary."""
    poly = sp.Poly(spectrum.outer, X)
    if poly.free_symbols - {X}:
        return None
    radius = max((abs(r) for r in poly.all_roots()), key=lambda r: float(r), default=sp.Integer(0))
    return radius if radius.is_Rational else rational_between(radius, radius + sp.Rational(1, 10**6))


def dual_spectral_every_n(scheme: StencilScheme) -> tuple[EveryNStep, ...]:
    """Reif's spectral conditions for every ``n`` from the ``n``-gon's symbol (module docstring)."""
    sp_ = ngon_spectrum(scheme)
    lam, start = sp_.first, sp_.start
    formulas = ((r"\lambda_1 = \sigma(1)", lam), (r"\sigma(-1)", sp_.first_conjugate), (r"\sigma(0)", sp_.zero))
    equal = sp.simplify(lam - sp_.first_conjugate) == 0 and sp.simplify(sp.im(lam)) == 0
    steps = [EveryNStep(f"the n-gon's eigenvalue at frequency 1 is its weights' symbol sigma(1) = {lam}, equal to sigma(-1) "
                        "and real: lambda_1 is a double eigenvalue (frequencies 1, n - 1)" if equal else
                        f"sigma(1) = {lam} and sigma(-1) = {sp_.first_conjugate} are not one real value: the frequency-1 "
                        "eigenvalue is not real and double", "proved" if equal else "failed", (start, None), "real-distinct",
                        formulas)]
    zero = sp.simplify(sp_.zero - 1)
    steps.append(EveryNStep("the n-gon's eigenvalue at frequency 0 is sigma(0) = 1 for every n (the weights sum to 1)"
                            if zero == 0 else f"sigma(0) = {sp_.zero} is not 1: the weights do not sum to 1",
                            "proved" if zero == 0 else "failed", (start, None), "frequency-zero", ((r"\sigma(0) - 1", zero),)))
    if not equal:
        return tuple(steps) + tuple(EveryNStep(f"{what}: not asked, lambda_1 is not real", "open", (start, None), name)
                                    for name, what in (("dominant", "lambda_1 above the other frequencies"),
                                                       ("bounds", "lambda_1 < 1 and above the outer blocks")))
    squares = [sp.expand(lam**2 - sp.re(v) ** 2 - sp.im(v) ** 2) for _, v in sp_.others]
    listed = ", ".join(f"{k}: {v}" for k, v in sp_.others)
    steps.append(_step("dominant", f"lambda_1 = {lam} is positive and larger in modulus than the n-gon's eigenvalue at every "
                       f"other frequency ({listed})", [lam, *squares], start,
                       tuple((rf"\lambda_1^2 - |\sigma|^2\ ({k})", s) for (k, _), s in zip(sp_.others, squares))))
    radius = _outer_radius(sp_)
    first = max(start, sp_.outer_start)
    if radius is None:
        steps.append(EveryNStep(f"the outer blocks' eigenvalues depend on the frequency (det(x I - B) = {sp_.outer}): no "
                                "bound for every n here", "open", (first, None), "bounds"))
    else:
        steps.append(_step("bounds", f"lambda_1 < 1 and lambda_1 > {radius} (above the outer blocks' eigenvalues, roots of "
                           f"{sp_.outer})", [1 - lam, lam - radius], first,
                           ((r"1 - \lambda_1", 1 - lam), (r"\lambda_1 - \rho_S", lam - radius))))
    return tuple(steps)


def _uniform_map(scheme: StencilScheme) -> UniformMapResult:
    """The map for every ``n`` from the valence the blocks are read at (:mod:`symdecomp.verify.c1_dual_uniform`); asked
    only once the spectral conditions are proved, so the valences below it are certified one by one."""
    from symdecomp.analysis.zoo_structure import READ_AT
    from symdecomp.verify.c1_dual_uniform import dual_uniform_map

    return dual_uniform_map(scheme, ngon_spectrum(scheme).first, READ_AT)


def c1_dual_every_n(scheme: StencilScheme, last: int = 64, *, progress: Callable[[int], None] | None = None,
                    certify: Callable[[int], object] | None = None, max_depth: int = 6) -> EveryNResult:
    """C1 for every valence (module docstring): the spectral conditions for every ``n``, the dual test at ``3..last``
    (``certify(n)``: a :class:`~symdecomp.verify.c1_zoo.ZooC1Result`; by default :func:`~symdecomp.verify.c1_zoo.c1_zoo`)."""
    from symdecomp.verify.c1_zoo import c1_zoo
    from symdecomp.verify.zoo_characteristic import engine_neighbourhood

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('doo-sabin')")
    last = check_int(last, "last", minimum=3)

    def spectral() -> tuple[EveryNStep, ...]:
        return dual_spectral_every_n(scheme)

    certify = certify or (lambda k: c1_zoo(scheme, k, neighbourhood=engine_neighbourhood, max_depth=max_depth))
    return c1_every_n(scheme, last, progress=progress, certify=certify, spectral_steps=spectral,
                      map_every_n=lambda lo, last: _uniform_map(scheme),
                      first=3)
