"""Limit masks of an extraordinary vertex: left eigenvectors of the subdivision matrix (interior, boundary, crease, corner, dart).

* The **position mask** is the left eigenvector for the eigenvalue 1, scaled so that its
  weights sum to 1: the limit position of ``O`` is ``w_O O + sum_i w_a a_i + sum_i w_b b_i``.
  It is constant on the ``a``'s and on the ``b``'s, so it comes from the left eigenvector
  ``(l_O, l_a, l_b)`` of the Eq. 43 matrix: ``w_O = l_O``, ``w_a = l_a/n``, ``w_b = l_b/n``.
* The two **tangent masks** are the real and imaginary parts of the left eigenvector for the
  subdominant eigenvalue ``lambda_1`` (dominant eigenvalue of ``M_1``, Eq. 34 at ``j = 1``).
  With the ansatz ``w_{a_i} = X omega^i``, ``w_{b_i} = Y omega^i`` (``omega = omega_n``) the
  left-eigenvector equations reduce to ``(X, Y) M(1/omega) = lambda_1 (X, Y)`` and ``w_O = 0``.

**Scaling of the tangent masks** (they are unnormalised): ``X = 1``, so the first tangent
mask has weight ``cos(2 pi i/n)`` on ``a_i`` and the second ``sin(2 pi i/n)``; the weights on
``b_i`` follow from the second column, ``Y = p_ab(1/omega)/(lambda_1 - m_22)``, i.e. for
Catmull-Clark ``(cos(2 pi i/n) + cos(2 pi (i+1)/n))/(16 lambda_1 - 4)`` (resp. ``sin``);
the weight on ``O`` is 0.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> m = limit_masks(catmull_clark())
>>> m.position
(n/(n + 5), 4/(n*(n + 5)), 1/(n*(n + 5)))
>>> m.tangent_b[0]
(cos(2*pi*i/n) + cos(2*pi*(i + 1)/n))/(4*(4*lambda_1 - 1))

**Any scheme and** ``K``**-ring** (:func:`ring_masks`, at a valence, certified): left eigenvectors of the
full ``K``-ring matrix ``S`` come from those of the frequency matrices (the transpose of Prop. 6.2):

* position (eigenvalue 1, frequency 0): if ``y E_0 = y`` then ``l_O = y_0`` and every vertex of
  class ``q`` gets ``y_q / n``; scaled so that the weights sum to 1;
* tangents (the subdominant eigenvalue ``lambda_1``, frequency 1): if ``y E(omega) = lambda_1 y``
  with ``omega = exp(2 pi i/n)``, then ``l`` with weight ``y_q omega^(-s)`` on the vertex of class
  ``q`` in sector ``s`` (0 on ``O``) is a complex left eigenvector; its real part and minus its
  imaginary part are the two tangent masks, scaled so that ``a_s`` (class ``(1, 0)``) has weight
  ``cos(2 pi s/n)``, resp. ``sin(2 pi s/n)``.

``y`` is computed in certified Arb arithmetic (a square linear solve with one coordinate fixed)
at the value's Arb ball, and checked: the residual ``|y (E - lambda I)|`` must be a ball around 0.

>>> from symdecomp.schemes.loop import loop
>>> m = ring_masks(loop(), 6, 1, digits=6)
>>> m["position"]["O"], m["position"]["a"][:2], m["subdominant"]
('0.5', ['0.0833333', '0.0833333'], '0.5')

**A boundary, crease, corner or dart vertex** (:func:`sharp_masks`, exact): the vertex's matrix is block
lower-triangular, the crease block then one block per sector, and its masks are exact left eigenvectors found part by
part (:mod:`symdecomp.analysis.triangular_masks`): the position, the boundary (or crease) curve's tangent from the
crease block, one cross tangent per sector, or the two largest eigenvalues after 1 where there is no block structure;
:attr:`SharpMasks.tangent_plane` says whether their eigenvalues are certified the two subdominant ones.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> sm = sharp_masks(catmull_clark(), SharpVertex.boundary(2, "quad"))
>>> [m.name for m in sm.tangents], sm.tangent_plane
(['boundary curve tangent', 'cross tangent'], True)
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any, cast

import flint
import mpmath
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.algebra.null_vector import null_vector
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.elliptic import recursion_left_eigenvector, tangent_lambda
from symdecomp.analysis.frequency import circulant_blocks, laurent_to_cos, per_frequency_matrix, ring_blocks
from symdecomp.analysis.hyperbolic import apply_rational_matrix
from symdecomp.analysis.spectrum import acb_text, format_value, ring_spectrum
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.analysis.triangular_eigen import merge
from symdecomp.analysis.triangular_masks import ONE, SharpMask, creased_masks, expanded, generic_masks, position_mask
from symdecomp.errors import InvalidSchemeError, NotApplicableError, SymdecompError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits, check_limit, check_valence

__all__ = ["INDEX", "LAMBDA1", "LimitMasks", "limit_masks", "MasksAtValence", "limit_masks_at", "check_masks_exactly", "ring_masks",
           "acb_matrix", "SharpMasks", "sharp_masks"]

#: The index ``i`` of ``a_i``, ``b_i`` in the closed forms.
INDEX = sp.Symbol("i", integer=True, nonnegative=True)
#: ``lambda_1`` as a symbol in the closed forms of the tangent masks.
LAMBDA1 = sp.Symbol("lambda_1", positive=True)


@dataclass(frozen=True)
class LimitMasks:
    """The limit masks of ``O`` in closed form in ``n`` and the index ``i`` (see the module docstring)."""

    #: ``(w_O, w_a, w_b)``: the position mask's weights on ``O``, on each ``a_i``, on each ``b_i``.
    position: tuple[sp.Expr, sp.Expr, sp.Expr]
    #: The two tangent masks' weights on ``a_i`` (``cos``, ``sin`` of ``2 pi i/n``).
    tangent_a: tuple[sp.Expr, sp.Expr]
    #: The two tangent masks' weights on ``b_i``, in ``n``, ``i`` and :data:`LAMBDA1`.
    tangent_b: tuple[sp.Expr, sp.Expr]
    #: ``lambda_1(n)``, to substitute for :data:`LAMBDA1`.
    subdominant: sp.Expr


@cached(scheme=check_scheme)
def limit_masks(scheme: Scheme) -> LimitMasks:
    """Derive the position and tangent masks of ``scheme`` for symbolic ``n``."""
    if scheme.parameters:
        raise InvalidSchemeError(f"scheme {scheme.name!r} has free parameters {scheme.parameters}; substitute them first")
    # the left eigenvector of the Eq. 43 matrix for eigenvalue 1: O's limit as a combination of O, abar, bbar
    left = recursion_left_eigenvector(scheme, 1)
    total = sum(left)
    l_O, l_a, l_b = (sp.factor(sp.cancel(x / total)) for x in left)
    position = (l_O, sp.factor(l_a / N), sp.factor(l_b / N))

    m22 = laurent_to_cos(per_frequency_matrix(scheme)[1, 1])
    if m22.has(sp.Symbol("s", real=True)):
        raise InvalidSchemeError("the face rule is not mirror symmetric; the tangent masks need m_22 real")
    m22 = m22.subs(cos_jtheta, sp.cos(sp.pi / N))
    ab = circulant_blocks(scheme).ab
    angle = lambda k: 2 * sp.pi * (INDEX - k) / N  # noqa: E731
    denominator = sp.expand(LAMBDA1 - m22)
    # w_{b_i} = sum_k c_k omega^(i - k) / (lambda_1 - m22): real and imaginary parts.
    b_cos = sp.Add(*[w * sp.cos(angle(k)) for k, w in ab.items()])
    b_sin = sp.Add(*[w * sp.sin(angle(k)) for k, w in ab.items()])
    return LimitMasks(
        position=position,
        tangent_a=(sp.cos(2 * sp.pi * INDEX / N), sp.sin(2 * sp.pi * INDEX / N)),
        tangent_b=(sp.together(b_cos / denominator), sp.together(b_sin / denominator)),
        subdominant=tangent_lambda(scheme, 1),
    )


@dataclass(frozen=True)
class MasksAtValence(NotebookDisplay):
    """The masks at one valence, exact (sympy), in the vertex order ``O, a_0.., b_0..``.

    The exact weights are built on first use (``4n`` exact trigonometric values: slow at large
    ``n``); :meth:`as_json` prints them from certified Arb balls of the closed forms and needs
    the exact values only where a ball contains 0 (a weight that may vanish exactly).
    """

    #: The valence.
    n: int
    #: The closed forms (:func:`limit_masks`) they are evaluated from.
    closed_forms: LimitMasks

    @cached_property
    def subdominant(self) -> sp.Expr:
        """``lambda_1``, the subdominant eigenvalue."""
        return self.closed_forms.subdominant.subs(N, self.n)

    @cached_property
    def position(self) -> tuple[sp.Expr, ...]:
        """The position mask, ``2n + 1`` weights summing to 1."""
        w = [x.subs(N, self.n) for x in self.closed_forms.position]
        return (w[0],) + (w[1],) * self.n + (w[2],) * self.n

    @cached_property
    def tangents(self) -> tuple[tuple[sp.Expr, ...], tuple[sp.Expr, ...]]:
        """The two tangent masks, each ``2n + 1`` weights (scaling in the module docstring)."""
        return tuple((sp.Integer(0),) + tuple(self._exact(w, i) for w in (a_w, b_w) for i in range(self.n))
                     for a_w, b_w in zip(self.closed_forms.tangent_a, self.closed_forms.tangent_b))

    def _exact(self, closed_form: sp.Expr, i: int) -> sp.Expr:
        return closed_form.subs({N: self.n, INDEX: i, LAMBDA1: self.subdominant})

    def as_json(self, digits: int = 20) -> dict:
        digits = check_digits(digits)

        def num(e):
            value = sp.N(e, digits + 10)
            with mpmath.workdps(digits + 10):
                v = mpmath.mpf(sp.Float(value, digits + 10)._mpf_) if value != 0 else mpmath.mpf(0)
                return format_value(v, digits)

        def split(mask):
            return {"O": num(mask[0]), "a": [num(w) for w in mask[1 : self.n + 1]], "b": [num(w) for w in mask[self.n + 1 :]]}

        position = [num(x.subs(N, self.n)) for x in self.closed_forms.position]
        return {
            "n": self.n,
            "position": {"O": position[0], "a": [position[1]] * self.n, "b": [position[2]] * self.n},
            "tangents": self._tangent_texts(digits, num),
            "subdominant": num(self.subdominant),
        }

    def _tangent_texts(self, digits: int, num) -> list[dict]:
        """The tangent masks as text, from Arb balls of the closed forms; an entry whose ball
        contains 0 is printed from its exact value (it may be exactly 0)."""
        from symdecomp.algebra.compile import compile_expression
        from symdecomp.analysis.spectrum import acb_text
        from symdecomp.errors import UnsupportedExpressionError

        n, cf = self.n, self.closed_forms
        try:
            lam = compile_expression(cf.subdominant, (N,), "arb")
            forms = [[compile_expression(w, (N, INDEX, LAMBDA1), "arb") for w in pair] for pair in zip(cf.tangent_a, cf.tangent_b)]
        except UnsupportedExpressionError:  # pragma: no cover - the closed forms use + * ** cos sin sqrt only
            return [{"O": num(t[0]), "a": [num(w) for w in t[1 : n + 1]], "b": [num(w) for w in t[n + 1 :]]} for t in self.tangents]
        out = []
        with flint.ctx.workprec(int((digits + 20) * 3.33) + 64):
            nn, tolerance = flint.acb(n), flint.arb(2) ** int(-3.33 * (digits + 12))
            lam1 = lam(nn)
            for pair, exact in zip(forms, zip(cf.tangent_a, cf.tangent_b)):
                texts = []
                for f, closed in zip(pair, exact):
                    row = []
                    for i in range(n):
                        z = f(nn, flint.acb(i), lam1)
                        certain = z.imag.contains(0) and not z.real.contains(0) and z.real.rad() < abs(z.real.mid()) * tolerance
                        row.append(acb_text(flint.acb(z.real), digits) if certain else num(self._exact(closed, i)))
                    texts.append(row)
                out.append({"O": num(sp.Integer(0)), "a": texts[0], "b": texts[1]})
        return out


def limit_masks_at(scheme: Scheme, n: int) -> MasksAtValence:
    """Evaluate :func:`limit_masks` at valence ``n`` (exact)."""
    n = check_scheme(scheme).fitting_valence(n)  # the stencils fit, and every weight is defined and real at n
    return MasksAtValence(n, limit_masks(scheme))


def check_masks_exactly(scheme: Scheme, n: int) -> tuple[bool, bool, bool]:
    """Check ``w^T S = lambda w^T`` exactly for the three masks at valence ``n``.

    The position mask is rational: checked in rational arithmetic. The tangent masks are
    multiplied by ``(lambda_1 - m_22)`` and checked in ``Q(zeta_4n)[L]/(L^2 - tr L + det)``, with
    ``L`` a root of the characteristic polynomial of ``M_1`` (exact, python-flint).
    Returns ``(position ok, first tangent ok, second tangent ok)``.
    """
    from symdecomp.schemes.scheme import subdivision_matrix

    n = check_valence(n)
    S = subdivision_matrix(scheme, n)
    masks = limit_masks_at(scheme, n)
    w = sp.Matrix([masks.position])
    position_ok = all(sp.simplify(x) == 0 for x in (w * S - w)) and sp.simplify(sum(w) - 1) == 0

    K = CyclotomicField(4 * n)
    ev = tangent_eigenvalues(scheme)
    c = (K.zeta(2) + K.zeta(-2)) / 2  # cos(pi/n) = cos(2 pi * 2/(4n))

    def cos(k):  # cos(2 pi k/(4n))
        return (K.zeta(k) + K.zeta(-k)) / 2

    def sin(k):
        return (K.zeta(k) - K.zeta(-k)) / (2 * K.i)

    def in_c(expr):
        poly = sp.Poly(sp.expand(expr), cos_jtheta)
        total = K(0)
        for (power,), coeff in poly.terms():
            total = total + K(sp.Rational(coeff)) * c**power
        return total

    trace, det = in_c(ev.trace), in_c(ev.determinant)
    m22 = in_c(laurent_to_cos(per_frequency_matrix(scheme)[1, 1]))
    ab = circulant_blocks(scheme).ab
    ST = S.T
    results = []
    for trig in (cos, sin):
        # (lambda_1 - m22) * mask, as pairs (p0, p1) meaning p0 + p1*L.
        zero = K(0)
        p0 = [zero] + [-m22 * trig(4 * i) for i in range(n)]
        p1 = [zero] + [trig(4 * i) for i in range(n)]
        p0 += [sum((trig(4 * (i - k)) * K(sp.Rational(wk)) for k, wk in ab.items()), zero) for i in range(n)]
        p1 += [zero] * n
        q0, q1 = apply_rational_matrix(ST, p0), apply_rational_matrix(ST, p1)
        # L*(p0 + p1 L) = -det*p1 + (p0 + tr*p1) L
        l0 = [-det * v for v in p1]
        l1 = [u + trace * v for u, v in zip(p0, p1)]
        results.append(all(a == b for a, b in zip(q0, l0)) and all(a == b for a, b in zip(q1, l1)))
    return position_ok, results[0], results[1]


def acb_matrix(M: sp.Matrix, variables, values):
    """The sympy matrix ``M`` as an Arb matrix, its entries compiled in ``variables`` and evaluated at ``values``."""
    return flint.acb_mat([[compile_expression(sp.sympify(M[r, c], strict=True), variables, "arb")(*values) for c in range(M.shape[1])]
                          for r in range(M.shape[0])])


def ring_masks(scheme: Scheme, n: int, rings: int = 1, *, digits: int = 20) -> dict:
    """The masks as JSON-ready decimal strings: ``{"n", "scheme", "rings", "subdominant", "position", "tangents"}``.

    Each mask is ``{"O": w, "classes": {"u,v": [weight per sector]}}`` plus ``"a"`` (class ``(1, 0)``)
    and, on quads, ``"b"`` (class ``(1, 1)``), the 1-ring names.
    """
    n = check_scheme(scheme).fitting_valence(check_limit(check_valence(n), "ring_masks(n)", "valence n"))
    digits = check_digits(digits)
    blocks = ring_blocks(scheme, rings)
    spectrum = ring_spectrum(scheme, n, rings, digits=digits, exact=False, jordan=False)
    balls = [cast(flint.acb, e.value) for e in spectrum.eigenvalues if 1 in e.frequencies]  # ring_spectrum's values are balls
    lam1 = max(balls, key=lambda b: float(b.abs_upper()))
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        E0 = sp.Matrix(blocks.frequency_zero_matrix(n))
        one = flint.acb_mat([[flint.acb(int(r == c)) for c in range(E0.shape[0])] for r in range(E0.shape[0])])
        A0 = acb_matrix(E0, (), ()) - one
        y0 = null_vector(A0.transpose(), first=0)  # a left null vector
        w = flint.acb(flint.arb(flint.fmpq(2, n))).exp_pi_i()
        E1 = acb_matrix(blocks.frequency_matrix().subs(N, n), (OMEGA,), (w,))  # an edge rule in n: at this valence
        K = blocks.class_count
        eye = flint.acb_mat([[flint.acb(int(r == c)) for c in range(K)] for r in range(K)])
        A1 = E1 - lam1 * eye
        y1 = null_vector(A1.transpose(), first=blocks.classes.index((1, 0)))
        if y0 is None or y1 is None:
            raise SymdecompError(f"n = {n}: no left eigenvector found for the masks (eigenvalue not simple?)")
        for y, A in ((y0, A0), (y1, A1)):
            residual = flint.acb_mat([y]) * A
            if not all(residual[0, c].contains(0) for c in range(A.ncols())):
                raise SymdecompError(f"n = {n}: the left eigenvector does not solve y (E - lambda I) = 0 (certified)")
        total = y0[0] + sum(y0[1:], flint.acb(0))
        position = [y / total for y in y0]
        scale = y1[blocks.classes.index((1, 0))]
        tangent = [y / scale for y in y1]
        text = lambda z: acb_text(z, digits)  # noqa: E731
        masks: dict[str, Any] = {"position": {"O": text(position[0]), "classes": {}},
                                 "tangents": [{"O": "0", "classes": {}}, {"O": "0", "classes": {}}]}
        for q, (u, v) in enumerate(blocks.classes):
            key = f"{u},{v}"
            masks["position"]["classes"][key] = [text(position[1 + q] / n)] * n
            rot = [tangent[q] * (flint.acb(flint.arb(flint.fmpq(-2 * s, n))).exp_pi_i()) for s in range(n)]
            masks["tangents"][0]["classes"][key] = [text(flint.acb(z.real)) for z in rot]
            masks["tangents"][1]["classes"][key] = [text(flint.acb(-z.imag)) for z in rot]
        for mask in [masks["position"], *masks["tangents"]]:
            for name, (u, v) in scheme.lattice.one_ring_classes:
                mask[name] = mask["classes"][f"{u},{v}"]
        return {"n": n, "scheme": scheme.name, "rings": rings, "subdominant": acb_text(lam1, digits), **masks}


@dataclass(frozen=True)
class SharpMasks:
    """The limit position and tangent masks of one sharp vertex."""

    scheme: str
    vertex: object
    #: The 1-ring points in matrix order (``O, a_0.., b_0..``).
    names: tuple[str, ...]
    position: SharpMask
    tangents: tuple[SharpMask, ...]
    #: The eigenvalue of largest modulus after 1 over the whole vertex (the subdominant one).
    subdominant: Eigenvalue
    #: Whether the tangents' eigenvalues are the two subdominant ones of each piece (certified).
    tangent_plane: bool
    #: Why they are, or are not.
    reason: str


def sharp_masks(scheme: Scheme, vertex, *, level: int = 0) -> SharpMasks:
    """The limit position and tangent masks of ``vertex`` (a :class:`~symdecomp.schemes.sector.SharpVertex`) at
    refinement ``level``, exact (:mod:`symdecomp.analysis.triangular_masks`). Raises :class:`~symdecomp.errors.NotApplicableError` when 1 is
    not a simple eigenvalue, or a mask is out of reach (there)."""
    from symdecomp.analysis.triangular_eigen import sharp_values

    scheme = check_scheme(scheme)
    S, parts, values = sharp_values(scheme, vertex, level=level)
    names = tuple(vertex.vertex_order())
    position = position_mask(S, values)
    rest = expanded([v for v in merge(values) if v.factor != ONE])
    if not rest:
        raise NotApplicableError("the matrix has no eigenvalue besides 1: no tangent masks")
    if parts[0].label == "whole":  # no block structure (a dart, a semi-sharp crease)
        tangents, reasons = generic_masks(S, values, names)
    else:
        tangents, reasons = creased_masks(S, parts, values, names)
    if reasons:
        reason = "; ".join(reasons)
    else:
        reason = "the tangents' eigenvalues are the two subdominant ones" + (" on each side" if len(parts) > 2 else "") + \
            ", real, and strictly larger in modulus than every other eigenvalue but 1 (certified)"
    shared = [t for t in tangents if t.name.startswith("cross") and t.eigenvalue.key == tangents[0].eigenvalue.key]
    if shared and not reasons:
        reason += (f"; the curve tangent and the cross tangent share the eigenvalue {acb_text(shared[0].eigenvalue.ball, 8)} "
                   "(non-defective): its eigenspace is the tangent plane, and the cross tangent, defined up to adding "
                   "the curve tangent, is given as the one with equal weights on the two crease neighbours")
    if not isinstance(S, flint.fmpq_mat):
        position, tangents = replace(position, generator=S.weight), [replace(m, generator=S.weight) for m in tangents]
    return SharpMasks(scheme.name, vertex, names, position, tuple(tangents), rest[0], not reasons, reason)
