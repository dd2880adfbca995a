"""Artifacts for a scheme of the zoo (a StencilScheme): density and the curvature regime, from the engine's spectrum.

Everything is read from the certified spectrum by frequency (:func:`symdecomp.analysis.zoo_spectrum.zoo_spectrum`,
over the steps that return the lattice to itself: two for sqrt(3)), on the neighbourhood of the given depth. The
default is the neighbourhood the C1 test reads (:data:`~symdecomp.verify.zoo_characteristic.C1_DEPTH` rings: the
characteristic map's ring and the control points it depends on), or the smallest invariant one if that is larger: a
smaller invariant neighbourhood misses eigenvalues of points the surface near the centre depends on (sqrt(3)'s 1-ring
is invariant over two steps, but at n = 3 its second ring adds ``2/81 + sqrt(7)/162``, larger than
``lambda_1^2 = 1/81``: the curvature is unbounded there, not bounded as the 1-ring alone says):

* ``lambda_1``: the eigenvalue of largest modulus after ``1``; the test applies when ``1`` is simple, ``lambda_1`` is
  real, double, at frequencies ``1`` and ``n - 1``, and strictly dominant in modulus (Reif's spectral conditions),
  otherwise the regime is *not applicable*, saying which condition fails.
* **Density**: ``lambda_1`` against the regular lattice's, which is the same engine's ``lambda_1`` at the regular
  valence (derived from the scheme's rules, never typed in): below it the refined mesh packs densely around the
  element, above it sparsely (:mod:`symdecomp.verify.artifacts`).
* **Curvature regime**: every other eigenvalue's modulus against ``lambda_1^2``, in Arb; a tie is shown exactly where
  both are exact numbers (the difference's minimal polynomial is ``x``). ``mu`` is the largest modulus after ``lambda_1``;
  the regime is :func:`~symdecomp.analysis.curvature_regime.curvature_regime` of the largest sign (its definitions).
  A tie with a Jordan block is unbounded. Where the engine leaves the Jordan structure unknown (block entries with
  radicals, which its cyclotomic ranks do not read), a tied ``mu`` that is a simple root at each of its frequencies has
  none; otherwise its null space is counted at each frequency by an exact rank over ``Q(zeta_4n)`` (sympy's
  ``DomainMatrix`` over the algebraic field), and a value whose entries are not numbers of that field stays undecided.

What 1-ring primal schemes also get (negative mask weights, the characteristic map's ring spacing, the shape class of
the central surface) needs their patch and masks: :data:`NOT_COMPUTED` says so in one line.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> a = zoo_artifacts(load_zoo("modified-butterfly"), 3)
>>> a.regime.value, str(a.lambda1.exact), str(a.lambda1_squared), [str(m.eigenvalue.exact) for m in a.mu]
('bounded', '1/2', '1/4', ['1/4'])
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass

import flint
import sympy as sp
from sympy import QQ
from sympy.polys.matrices import DomainMatrix

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, cyclotomic_value, to_acb
from symdecomp.analysis.charpoly import COSK
from symdecomp.analysis.curvature_regime import REGIME_TEXT, CurvatureRegime, curvature_regime, frequency_kind
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.zoo_blocks import ZooBlocks, zoo_blocks
from symdecomp.analysis.zoo_jordan import jordan_by_frequency, with_jordan
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_roots import cosine_form, real_cosine_form
from symdecomp.analysis.zoo_spectrum import COSINE_FORM_UP_TO, spectrum_of_blocks, zoo_spectrum
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_type, check_valence
from symdecomp.verify.zoo_characteristic import C1_DEPTH

__all__ = ["NOT_COMPUTED", "ZooMu", "ZooArtifacts", "zoo_artifacts", "exact_sign"]

#: What the zoo's artifacts do not include, and why (one line).
NOT_COMPUTED = ("not computed for a scheme of the zoo: negative mask weights, ring spacing and the shape class (they need "
                "the 1-ring primal scheme's masks and spline patch)")

_X = sp.Dummy("x")


def _is_root(e: Eigenvalue, c: sp.Expr, n: int) -> bool:
    """Whether ``e`` is exactly ``c``: ``c``'s Arb enclosure lies in ``e``'s ball, an isolating ball of one root of ``e``'s
    factor at one of its frequencies, and ``c`` is a root of that factor at each of them (then that root is ``c``)."""
    free = e.factor.free_symbols - {LAM} if e.factor is not None else {OMEGA}
    if e.factor is None or not isinstance(e.value, flint.acb) or not free <= {OMEGA, COSK}:
        return False
    with flint.ctx.workprec(256):
        if not e.value.contains(flint.acb(compile_expression(c, (), "arb")())):
            return False
    ks = [k for k in e.frequencies if k > 0] if free else [0]
    for k in ks:
        at = {OMEGA: sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)), COSK: sp.cos(2 * sp.pi * sp.Rational(k, n))}
        factor = e.factor.xreplace(at)
        decided = _root_at_square_root(factor, c, n)
        if decided is None:
            decided = _exact_zero(factor.xreplace({LAM: c}), (n,))  # in a cyclotomic field where it is one's number
        if not decided:
            return False
    return bool(ks)


def _cyclotomic(values: list[sp.Expr], n: int) -> list[Cyclotomic] | None:
    """``values`` in one cyclotomic field (the radicals sympy wrote cosines with read back), or ``None``."""
    forms = [cosine_form(sp.expand(v), n) if n <= COSINE_FORM_UP_TO else sp.expand(v) for v in values]
    try:
        order = math.lcm(*(cyclotomic_value(f).field.N for f in forms))
        field = CyclotomicField(order)
        return [cyclotomic_value(f, field=field) for f in forms]
    except ValueError:
        return None


def _root_at_square_root(factor: sp.Expr, c: sp.Expr, n: int) -> bool | None:
    """Whether ``c = s sqrt(q)`` (``s = +-1``, ``q`` a number of a cyclotomic field) is a root of ``factor`` in
    ``lambda``, decided in that field: with ``f(lambda) = E(lambda^2) + lambda O(lambda^2)``, ``f(c) = E(q) + c O(q)``
    is 0 exactly when ``O(q) = E(q) = 0``, or ``r = -E(q)/O(q)`` has ``r^2 = q`` and the sign ``s`` (then ``r = c``).
    ``None`` when ``c`` is not of that form or a number is not of the field (the caller decides otherwise)."""
    sign, root = (-1, -c) if c.could_extract_minus_sign() else (1, c)
    if not (root.is_Pow and root.exp == sp.Rational(1, 2)):
        return None
    coeffs = sp.Poly(factor, LAM).all_coeffs()[::-1]  # a_0, a_1, ...
    q = root.base
    even = sum((a * q ** (i // 2) for i, a in enumerate(coeffs) if i % 2 == 0), sp.Integer(0))
    odd = sum((a * q ** (i // 2) for i, a in enumerate(coeffs) if i % 2 == 1), sp.Integer(0))
    values = _cyclotomic([even, odd, q], n)
    if values is None:
        return None
    E, O, Q = values
    if not O.poly:
        return not E.poly
    r = -E / O
    if (r * r - Q).poly:
        return False
    ball = to_acb(r, 128)
    return bool(ball.real > 0) if sign > 0 else bool(ball.real < 0)


def _real_sign(ball: flint.acb) -> int | None:
    return 1 if ball.real > 0 else -1 if ball.real < 0 else None


def _exact_zero(d: sp.Expr, valences: tuple[int, ...]) -> bool:
    """Whether the number ``d`` is exactly 0: in a cyclotomic field when it is one's (the radicals sympy wrote
    cosines with read back, :func:`~symdecomp.analysis.zoo_roots.cosine_form`), else by its minimal polynomial."""
    d = sp.expand(d)
    if d == 0:
        return True
    form = d
    for n in dict.fromkeys(valences):
        form = cosine_form(form, n) if n <= COSINE_FORM_UP_TO else form
    try:
        return not cyclotomic_value(form).poly
    except ValueError:
        return bool(sp.Poly(sp.minimal_polynomial(d, _X), _X) == sp.Poly(_X, _X))


def exact_sign(a: Eigenvalue | None, b: Eigenvalue | None, n: int, *, square: bool = False, n_b: int | None = None) -> int | None:
    """The sign of ``|a| - |b|`` (``|b|^2`` with ``square``) from the certified balls; a tie shown exactly where both
    values are exact and real (the difference's minimal polynomial is ``x``), or where one is exact and the value it
    asks of the other is a root of the other's factor in its ball (:func:`_is_root`); ``None``: not decided.
    ``n``: ``a``'s valence, and ``b``'s unless ``n_b`` is given."""
    if a is None or b is None:
        return None
    with flint.ctx.workprec(256):
        u, v = a.value, b.value
        assert isinstance(u, flint.acb) and isinstance(v, flint.acb)  # the engine's certified balls
        x, y = u.abs_lower(), u.abs_upper()
        lo, hi = v.abs_lower(), v.abs_upper()
        if square:
            lo, hi = lo * lo, hi * hi
        if x > hi:
            return 1
        if y < lo:
            return -1
    p, q = a.exact, b.exact
    real = [p is not None and p.is_real, q is not None and q.is_real]
    if p is not None and q is not None and real == [True, True]:
        signs = [_real_sign(u), _real_sign(v)]
        if None not in signs:  # |p| and |q| without Abs: the balls give the signs
            d = signs[0] * p - (q ** 2 if square else signs[1] * q)
            return 0 if _exact_zero(d, (n, n if n_b is None else n_b)) else None
        d = sp.Abs(p) - (q ** 2 if square else sp.Abs(q))
        return 0 if sp.Poly(sp.minimal_polynomial(d, _X), _X) == sp.Poly(_X, _X) else None
    if p is not None and real[0] and (v.real > 0 or v.real < 0):  # |b| (or |b|^2) = |a|: b is sqrt(|a|) (or |a|), b's sign
        target = sp.sqrt(sp.Abs(p)) if square else sp.Abs(p)
        return 0 if _is_root(b, target if v.real > 0 else -target, n if n_b is None else n_b) else None
    if q is not None and real[1] and (u.real > 0 or u.real < 0):  # |a| = |b|^2 (or |b|): a is that, with a's sign
        target = q ** 2 if square else sp.Abs(q)
        return 0 if _is_root(a, target if u.real > 0 else -target, n) else None
    return None


@dataclass(frozen=True)
class ZooMu:
    """An eigenvalue after ``1`` and ``lambda_1``, compared with ``lambda_1^2``."""

    eigenvalue: Eigenvalue
    #: The sign of ``|value| - lambda_1^2`` (``None``: not decided).
    comparison: int | None
    #: The paper's names of its frequencies (elliptic, tangent, hyperbolic, ...).
    kinds: tuple[str, ...]

    def as_json(self) -> dict[str, object]:
        e = self.eigenvalue
        return {"value": e.text, "exact": None if e.exact is None else str(e.exact), "frequencies": list(e.frequencies),
                "multiplicity": e.multiplicity, "kind": ", ".join(self.kinds), "comparison": self.comparison,
                "jordan_blocks": None if e.jordan is None else list(e.jordan)}


@dataclass(frozen=True)
class ZooArtifacts:
    """Density and the curvature regime of a zoo scheme at one valence (module docstring)."""

    n: int
    scheme: str
    #: The steps analysed (the lattice returns after that many) and the neighbourhood's depth.
    steps: int
    depth: int
    regime: CurvatureRegime
    #: One line: which eigenvalue decides, and how (or why the test does not apply).
    reason: str
    lambda1: Eigenvalue | None = None
    #: ``lambda_1^2`` exactly (``None``: ``lambda_1`` has no exact form).
    lambda1_squared: sp.Expr | None = None
    #: The eigenvalues of largest modulus after ``lambda_1`` (several when they are not separated).
    mu: tuple[ZooMu, ...] = ()
    #: The regular valence's ``lambda_1`` and the sign of ``lambda_1 -`` it (``-1`` dense, ``0`` regular, ``1`` sparse).
    regular_lambda1: Eigenvalue | None = None
    density: int | None = None
    #: ``lambda_1^2`` as decimal text (the certified ball squared), as ``lambda_1`` is shown; empty when not applicable.
    lambda1_squared_text: str = ""

    @property
    def density_text(self) -> str:
        return "not applicable" if self.lambda1 is None else {-1: "dense", 0: "regular", 1: "sparse", None: "undecided"}[self.density]

    def as_json(self) -> dict[str, object]:
        lam, reg = self.lambda1, self.regular_lambda1
        return {
            "n": self.n, "steps": self.steps, "rings": self.depth, "density": self.density_text,
            "regular_lambda1": None if reg is None else reg.text, "not_computed": NOT_COMPUTED,
            "curvature": {
                "regime": self.regime.value, "reason": self.reason, "cause": ", ".join(dict.fromkeys(k for m in self.mu for k in m.kinds)),
                "lambda1": None if lam is None else lam.text, "lambda1_exact": None if lam is None or lam.exact is None else str(lam.exact),
                "lambda1_squared": None if self.lambda1_squared is None else str(self.lambda1_squared),
                "lambda1_squared_value": self.lambda1_squared_text or None,
                "mu": [m.as_json() for m in self.mu]},
        }


def _lambda1(n: int, values: tuple[Eigenvalue, ...]) -> tuple[Eigenvalue | None, str]:
    """``lambda_1`` when Reif's spectral conditions hold, else ``None`` and the condition that fails."""
    if len(values) < 3 or values[0].exact != 1 or values[0].multiplicity != 1:
        return None, "the eigenvalue 1 is not simple and dominant"
    lam = values[1]
    if exact_sign(lam, values[2], n) != 1:
        return None, f"lambda_1 = {lam.text} is not strictly dominant in modulus after 1"
    if lam.multiplicity != 2 or set(lam.frequencies) != {1 % n, (n - 1) % n} or lam.value.imag != 0:
        return None, f"lambda_1 = {lam.text} is not real and double at frequencies 1 and n - 1"
    return lam, ""


def _defective(blocks: ZooBlocks, e: Eigenvalue) -> tuple[int, ...] | None:
    """The frequencies at which ``e`` has a Jordan block (empty: none): at each frequency where it is a multiple root, its
    null vectors (an exact rank over ``Q(zeta_4n)``) against its multiplicity there; ``None`` when that is not decided (``e``
    or an entry is not a number of that field), unless the engine's Jordan structure says there is no block."""
    if e.jordan is not None and max(e.jordan) == 1:
        return ()
    exact = jordan_by_frequency(blocks, e)  # the engine's cyclotomic ranks, frequency by frequency
    if exact is not None:
        return tuple(k for k, sizes in exact.items() if max(sizes) > 1)
    n, by_k = blocks.n, Counter(k for k, _, _ in e.members)
    if e.exact is None or not by_k:
        return None
    field = QQ.algebraic_field(sp.exp(2 * sp.pi * sp.I / (4 * n)))
    found: list[int] = []
    for k, m in sorted(by_k.items()):
        if m == 1:
            continue  # a simple root at its frequency: no Jordan block there
        B = blocks.frequency_zero_matrix() if k == 0 else blocks.frequency_matrix(sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)))
        A = sp.Matrix(B) - e.exact * sp.eye(B.shape[0])
        try:
            D = DomainMatrix([[field.from_sympy(sp.expand(x)) for x in row] for row in A.tolist()], A.shape, field)
        except (sp.polys.polyerrors.CoercionFailed, NotImplementedError, ValueError):
            return None
        if B.shape[0] - D.rank() < m:
            found.append(k)
    if e.jordan is not None and not found:  # pragma: no cover - the engine's ranks and these agree
        return None
    return tuple(found)


def _decide(n: int, lam: Eigenvalue, others: tuple[Eigenvalue, ...], blocks: ZooBlocks) -> tuple[CurvatureRegime, str, tuple[ZooMu, ...]]:
    rows = [ZooMu(e, exact_sign(e, lam, n, square=True), tuple(dict.fromkeys(frequency_kind(k, n) for k in sorted(e.frequencies)))) for e in others]
    top = rows[0]
    mu = tuple(r for r in rows if r is top or exact_sign(r.eigenvalue, top.eigenvalue, n) is None
               or exact_sign(r.eigenvalue, top.eigenvalue, n) == 0)
    signs = [r.comparison for r in rows]
    if 1 in signs:
        worst = next(r for r in rows if r.comparison == 1)
        return CurvatureRegime.UNBOUNDED, f"|{worst.eigenvalue.text}| > lambda_1^2 ({', '.join(worst.kinds)})", mu
    if None in signs:
        return CurvatureRegime.UNDECIDED, "an eigenvalue's modulus is not separated from lambda_1^2 and no exact tie was shown", mu
    if 0 not in signs:
        return curvature_regime(-1), f"|mu| = {top.eigenvalue.text} < lambda_1^2", mu
    defective = [_defective(blocks, r.eigenvalue) for r in rows if r.comparison == 0]
    at = sorted({k for d in defective if d for k in d})
    if at:
        kinds = ", ".join(dict.fromkeys(frequency_kind(k, n) for k in at))
        where = f"k = {', '.join(map(str, at))} ({kinds})"
        return curvature_regime(0, defective=True), f"|mu| = lambda_1^2 exactly, with a Jordan block at frequencies {where}", mu
    if None not in defective:
        return curvature_regime(0), "|mu| = lambda_1^2 exactly, no Jordan block", mu
    return CurvatureRegime.UNDECIDED, "|mu| = lambda_1^2 exactly; its Jordan structure is not decided", mu


def zoo_artifacts(scheme: StencilScheme, n: int, depth: int | None = None) -> ZooArtifacts:
    """Density and the curvature regime of ``scheme`` at valence ``n`` (module docstring)."""
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    n = check_valence(n)
    zm = zoo_matrix(scheme, n, depth)
    if depth is None and zm.depth < C1_DEPTH:  # the points the surface near the centre depends on (module docstring)
        zm = zoo_matrix(scheme, n, C1_DEPTH)
    blocks = zoo_blocks(zm)
    spectrum = with_jordan(blocks, spectrum_of_blocks(blocks, depth=zm.depth, mesh=scheme.lattice))
    values = spectrum.eigenvalues
    lam, why = _lambda1(n, values)
    if lam is None:
        return ZooArtifacts(n, scheme.name, scheme.steps, spectrum.rings, CurvatureRegime.NOT_APPLICABLE,
                            f"{REGIME_TEXT[CurvatureRegime.NOT_APPLICABLE]}: {why}")
    regime, reason, mu = _decide(n, lam, values[2:], blocks)
    square = None if lam.exact is None else _square(lam.exact, n)
    regular, density = _density(scheme, zm.neighbourhood.regular_valence, lam, n, spectrum.rings)
    with flint.ctx.workprec(4 * spectrum.digits + 64):  # the ball's own precision decides the digits shown
        square_text = acb_text(lam.value * lam.value, spectrum.digits)
    return ZooArtifacts(n, scheme.name, scheme.steps, spectrum.rings, regime, reason, lam, square, mu, regular, density,
                        square_text)


def _square(value: sp.Expr, n: int) -> sp.Expr:
    """``value^2`` expanded, or as rational multiples of cosines where that is shorter
    (:func:`~symdecomp.analysis.zoo_roots.real_cosine_form`: the products of cosines reduced in the real subfield)."""
    square = sp.expand(value ** 2)
    try:
        x = cyclotomic_value(cosine_form(square, n) if n <= COSINE_FORM_UP_TO else square)
    except ValueError:
        return square
    form = real_cosine_form(x)
    return form if form is not None and sp.count_ops(form) < sp.count_ops(square) else square


def _density(scheme: StencilScheme, regular_n: int, lam: Eigenvalue, n: int, depth: int) -> tuple[Eigenvalue | None, int | None]:
    """The ``lambda_1`` of the same engine at the neighbourhood's regular valence, and the sign of ``lambda_1 -`` it."""
    if n == regular_n:
        return lam, 0  # the regular valence: the same eigenvalue
    reg, _ = _lambda1(regular_n, zoo_spectrum(scheme, regular_n, depth, jordan=False).eigenvalues)
    return reg, exact_sign(lam, reg, n, n_b=regular_n)
