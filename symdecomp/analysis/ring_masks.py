"""Limit-position and tangent masks of the centre for any scheme and K-ring, from the frequency matrices.

Left eigenvectors of the full ``K``-ring matrix ``S`` come from those of the frequency matrices
(the transpose of Prop. 6.2):

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
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.null_vector import null_vector
from symdecomp.analysis.ring_blocks import ring_blocks
from symdecomp.analysis.ring_spectrum import acb_text, ring_spectrum
from symdecomp.errors import SymdecompError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_limit, check_valence

__all__ = ["ring_masks"]


def _acb_matrix(M: sp.Matrix, variables, values):
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
    first = [e for e in spectrum.eigenvalues if 1 in e.frequencies]
    lam1 = max(first, key=lambda e: float(e.value.abs_upper())).value
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        E0 = sp.Matrix(blocks.frequency_zero_matrix(n))
        one = flint.acb_mat([[flint.acb(int(r == c)) for c in range(E0.shape[0])] for r in range(E0.shape[0])])
        A0 = _acb_matrix(E0, (), ()) - one
        y0 = null_vector(A0.transpose(), first=0)  # a left null vector
        w = flint.acb(flint.arb(flint.fmpq(2, n))).exp_pi_i()
        E1 = _acb_matrix(blocks.frequency_matrix().subs(N, n), (OMEGA,), (w,))  # an edge rule in n: at this valence
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
        masks = {"position": {"O": text(position[0]), "classes": {}}, "tangents": [{"O": "0", "classes": {}}, {"O": "0", "classes": {}}]}
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
