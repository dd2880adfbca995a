"""Artifacts for a scheme of the zoo (a StencilScheme): density and the curvature regime, from the engine's spectrum.

Everything is read from the certified spectrum by frequency (:func:`symdecomp.analysis.zoo_spectrum.zoo_spectrum`,
over the steps that return the lattice to itself: two for sqrt(3)), on the neighbourhood of the given depth (default:
the smallest invariant one):

* ``lambda_1``: the eigenvalue of largest modulus after ``1``; the test applies when ``1`` is simple, ``lambda_1`` is
  real, double, at frequencies ``1`` and ``n - 1``, and strictly dominant in modulus (Reif's spectral conditions),
  otherwise the regime is *not applicable*, saying which condition fails.
* **Density**: ``lambda_1`` against the regular lattice's, which is the same engine's ``lambda_1`` at the regular
  valence (derived from the scheme's rules, never typed in): below it the refined mesh packs densely around the
  element, above it sparsely (:mod:`symdecomp.verify.artifacts`).
* **Curvature regime**: every other eigenvalue's modulus against ``lambda_1^2``, in Arb; a tie is shown exactly where
  both are exact numbers (the difference's minimal polynomial is ``x``). ``mu`` is the largest modulus after ``lambda_1``;
  the regime is :func:`~symdecomp.analysis.curvature_regime.curvature_regime` of the largest sign (its definitions).
  A tie with a Jordan block is unbounded; a tie whose Jordan structure the engine leaves unknown is undecided, unless
  ``mu`` is a simple root at each of its frequencies (then it has no Jordan block).

What 1-ring primal schemes also get (negative mask weights, the characteristic map's ring spacing, the shape class of
the central surface) needs their patch and masks: :data:`NOT_COMPUTED` says so in one line.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> a = zoo_artifacts(load_zoo("modified-butterfly"), 3)
>>> a.regime.value, str(a.lambda1.exact), str(a.lambda1_squared), [str(m.eigenvalue.exact) for m in a.mu]
('zero', '1/2', '1/4', ['1/4'])
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.analysis.curvature_regime import REGIME_TEXT, CurvatureRegime, curvature_regime, frequency_kind
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import check_type, check_valence

__all__ = ["NOT_COMPUTED", "ZooMu", "ZooArtifacts", "zoo_artifacts", "exact_sign"]

#: What the zoo's artifacts do not include, and why (one line).
NOT_COMPUTED = ("not computed for a scheme of the zoo: negative mask weights, ring spacing and the shape class (they need "
                "the 1-ring primal scheme's masks and spline patch)")

_X = sp.Dummy("x")


def exact_sign(a: Eigenvalue | None, b: Eigenvalue | None, *, square: bool = False) -> int | None:
    """The sign of ``|a| - |b|`` (``|b|^2`` with ``square``) from the certified balls; a tie shown exactly where both
    values are exact and real (the difference's minimal polynomial is ``x``); ``None``: not decided."""
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
    if a.exact is None or b.exact is None or not (a.exact.is_real and b.exact.is_real):
        return None
    d = sp.Abs(a.exact) - (b.exact ** 2 if square else sp.Abs(b.exact))
    if sp.Poly(sp.minimal_polynomial(d, _X), _X) == sp.Poly(_X, _X):
        return 0
    return None  # pragma: no cover - balls at 256 bits separate distinct numbers of this size


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
                "mu": [m.as_json() for m in self.mu]},
        }


def _lambda1(n: int, values: tuple[Eigenvalue, ...]) -> tuple[Eigenvalue | None, str]:
    """``lambda_1`` when Reif's spectral conditions hold, else ``None`` and the condition that fails."""
    if len(values) < 3 or values[0].exact != 1 or values[0].multiplicity != 1:
        return None, "the eigenvalue 1 is not simple and dominant"
    lam = values[1]
    if exact_sign(lam, values[2]) != 1:
        return None, f"lambda_1 = {lam.text} is not strictly dominant in modulus after 1"
    if lam.multiplicity != 2 or set(lam.frequencies) != {1 % n, (n - 1) % n} or lam.value.imag != 0:  # type: ignore[attr-defined]
        return None, f"lambda_1 = {lam.text} is not real and double at frequencies 1 and n - 1"
    return lam, ""


def _simple_at_each(e: Eigenvalue) -> bool:
    """Whether ``e`` is a simple root at each of its frequencies (then it has no Jordan block)."""
    ks = [k for k, _, _ in e.members]
    return bool(ks) and len(ks) == len(set(ks))


def _decide(n: int, lam: Eigenvalue, others: tuple[Eigenvalue, ...]) -> tuple[CurvatureRegime, str, tuple[ZooMu, ...]]:
    rows = [ZooMu(e, exact_sign(e, lam, square=True), tuple(dict.fromkeys(frequency_kind(k, n) for k in sorted(e.frequencies)))) for e in others]
    top = rows[0]
    mu = tuple(r for r in rows if r is top or exact_sign(r.eigenvalue, top.eigenvalue) is None
               or exact_sign(r.eigenvalue, top.eigenvalue) == 0)
    signs = [r.comparison for r in rows]
    if 1 in signs:
        worst = next(r for r in rows if r.comparison == 1)
        return CurvatureRegime.UNBOUNDED, f"|{worst.eigenvalue.text}| > lambda_1^2 ({', '.join(worst.kinds)})", mu
    if None in signs:
        return CurvatureRegime.UNDECIDED, "an eigenvalue's modulus is not separated from lambda_1^2 and no exact tie was shown", mu
    if 0 not in signs:
        return curvature_regime(-1), f"|mu| = {top.eigenvalue.text} < lambda_1^2", mu
    ties = [r.eigenvalue for r in rows if r.comparison == 0]
    if any(e.jordan is not None and max(e.jordan) > 1 for e in ties):
        return curvature_regime(0, defective=True), "|mu| = lambda_1^2 exactly, with a Jordan block", mu
    if all((e.jordan is not None) or _simple_at_each(e) for e in ties):
        return curvature_regime(0), "|mu| = lambda_1^2 exactly, no Jordan block", mu
    return CurvatureRegime.UNDECIDED, "|mu| = lambda_1^2 exactly; its Jordan structure is not decided by the engine", mu


def zoo_artifacts(scheme: StencilScheme, n: int, depth: int | None = None) -> ZooArtifacts:
    """Density and the curvature regime of ``scheme`` at valence ``n`` (module docstring)."""
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    n = check_valence(n)
    spectrum = zoo_spectrum(scheme, n, depth)
    values = spectrum.eigenvalues
    lam, why = _lambda1(n, values)
    if lam is None:
        return ZooArtifacts(n, scheme.name, scheme.steps, spectrum.rings, CurvatureRegime.NOT_APPLICABLE,
                            f"{REGIME_TEXT[CurvatureRegime.NOT_APPLICABLE]}: {why}")
    regime, reason, mu = _decide(n, lam, values[2:])
    square = None if lam.exact is None else sp.expand(lam.exact ** 2)
    regular, density = _density(scheme, lam, spectrum.rings)
    return ZooArtifacts(n, scheme.name, scheme.steps, spectrum.rings, regime, reason, lam, square, mu, regular, density)


def _density(scheme: StencilScheme, lam: Eigenvalue, depth: int) -> tuple[Eigenvalue | None, int | None]:
    """The regular valence's ``lambda_1`` (the same engine at the neighbourhood's regular valence) and the sign against it."""
    from symdecomp.analysis.zoo_matrix import zoo_matrix

    regular_n = zoo_matrix(scheme, 3, depth).neighbourhood.regular_valence
    reg, _ = _lambda1(regular_n, zoo_spectrum(scheme, regular_n, depth, jordan=False).eigenvalues)
    return reg, exact_sign(lam, reg)
