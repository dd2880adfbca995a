"""Limit-position and tangent masks of a StencilScheme at valence ``n``, from its frequency blocks.

The left eigenvectors of the full matrix come from those of the blocks (:mod:`symdecomp.analysis.zoo_blocks`),
as :func:`symdecomp.analysis.masks.ring_masks` reads them for 1-ring schemes:

* position (eigenvalue 1, frequency 0): if ``z B_0 = z``, the centre gets ``z_O`` and every point of class
  ``c`` gets ``z_c / n``; scaled so that the weights sum to 1;
* tangents (the subdominant eigenvalue ``lambda_1`` at frequency 1): if ``y B(omega) = lambda_1 y`` with
  ``omega = exp(2 pi i/n)``, the point ``(s, c)`` gets ``y_c omega^(-s)`` (the centre 0); its real part and
  minus its imaginary part are the two tangent masks, scaled so that class 0 in sector ``s`` has
  ``cos(2 pi s/n)``, resp. ``sin(2 pi s/n)``.

The vectors are solved in certified Arb arithmetic at the eigenvalue's ball, and checked: the residual
must be a ball around 0. A face-centred neighbourhood (a dual scheme) has no centre point: its limit point
is the limit of the centre face, and the masks weigh the face's corners and the rings around it.

>>> import sympy as sp
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> m = zoo_masks(ds, 4, digits=6)
>>> m["subdominant"], m["position"]["classes"]["0"][:2]          # at a knot, the corners' average
('0.5', ['0.25', '0.25'])
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import flint
import sympy as sp

from symdecomp.algebra.null_vector import null_vector
from symdecomp.analysis.masks import acb_matrix
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.zoo_blocks import ZooBlocks, zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks
from symdecomp.analysis.zoo_structure import READ_AT
from symdecomp.errors import SymdecompError
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits

__all__ = ["zoo_masks"]


def _identity(size: int) -> flint.acb_mat:
    return flint.acb_mat([[flint.acb(int(r == c)) for c in range(size)] for r in range(size)])


def _not_simple(blocks: ZooBlocks, lam: flint.acb, frequency: int, mesh: str, depth: int) -> str:
    """Why ``y (B_k - lambda I) = 0`` has no single solution at frequency ``k``: the eigenvalue's multiplicity and
    Jordan blocks in the whole spectrum (decided exactly, :func:`~symdecomp.analysis.zoo_jordan.with_jordan`)."""
    from symdecomp.analysis.zoo_jordan import with_jordan

    spectrum = with_jordan(blocks, spectrum_of_blocks(blocks, exact=True, depth=depth, mesh=mesh))
    for e in spectrum.eigenvalues:
        if frequency in e.frequencies and e.value.overlaps(lam):
            shown = e.text if e.exact is None else sp.sstr(e.exact)
            blocks_text = ("Jordan blocks of sizes " + "+".join(map(str, e.jordan)) if e.jordan and max(e.jordan) > 1
                           else "no Jordan block larger than 1" if e.jordan else "Jordan blocks not decided")
            return (f"the eigenvalue {shown} has multiplicity {e.multiplicity} (frequencies "
                    f"{', '.join(map(str, e.frequencies))}) with {blocks_text}, so its left eigenvector at frequency "
                    f"{frequency} is not one mask")
    return f"the eigenvalue {acb_text(lam, 10)} is not isolated from the frequency-{frequency} block's others at this precision"


def _checked(y: list[flint.acb] | None, A: flint.acb_mat, n: int, why: Callable[[], str]) -> list[flint.acb]:
    if y is None:
        raise SymdecompError(f"n = {n}: no masks: {why()}")
    residual = flint.acb_mat([y]) * A
    if not all(residual[0, c].contains(0) for c in range(A.ncols())):
        raise SymdecompError(f"n = {n}: the left eigenvector does not solve y (B - lambda I) = 0 (certified)")
    return y


def _isolated_largest(B1: flint.acb_mat) -> flint.acb | None:
    """The frequency-1 block's eigenvalue of largest modulus, certified, when it is strictly apart in modulus from the
    block's other eigenvalues; else ``None``.

    Only this one eigenvalue is needed: the whole spectrum (every frequency's block factored symbolically) is the
    cost of ``masks`` at large n (most of a minute at n = 64), and the largest at frequency 1 is what it is read for.
    Arb's enclosures of the K x K block's eigenvalues (multiple ones allowed) decide it; when they cannot (no
    convergence, or another eigenvalue's modulus as large), the caller takes the whole spectrum, which orders equal
    moduli as it always has. Up to the valences where the spectrum itself stays explicit (n <= 19), the caller takes
    the whole spectrum anyway: it is cheap there, and a mask entry whose ball contains 0 prints its midpoint, which
    depends on the eigenvalue's ball, so the printed masks stay those of ``spectrum`` and ``ring_masks`` digit for digit.
    """
    try:
        values = sorted(B1.eig(multiple=True), key=lambda z: -float(z.abs_upper()))
    except ValueError:
        return None
    top = flint.acb(values[0])
    if all(z.abs_upper() < top.abs_lower() for z in values[1:]):
        return top
    return None


def _largest_of_spectrum(blocks: ZooBlocks, digits: int, depth: int, mesh: str) -> flint.acb:
    """The largest eigenvalue in modulus at frequency 1, read from the whole spectrum (every block factored)."""
    spectrum = spectrum_of_blocks(blocks, digits=digits, exact=False, depth=depth, mesh=mesh)
    first = [e for e in spectrum.eigenvalues if 1 in e.frequencies]
    value = max(first, key=lambda e: float(e.value.abs_upper())).value  # balls are flint.acb
    assert isinstance(value, flint.acb)
    return value


def zoo_masks(scheme: StencilScheme, n: int, depth: int | None = None, *, digits: int = 20) -> dict[str, Any]:
    """The masks as JSON-ready decimal strings: ``{"n", "scheme", "rings", "steps", "subdominant", "position", "tangents"}``.

    Each mask is ``{"O": w, "classes": {"c": [weight per sector s]}}`` (no ``"O"`` around a centre face); class
    ``c`` is the ``c``-th orbit of the neighbourhood's labelling (:mod:`symdecomp.schemes.neighbourhood`).
    """
    digits = check_digits(digits)
    zm = zoo_matrix(scheme, n, depth)
    n = zm.n  # checked: an int
    blocks = zoo_blocks(zm)
    K, centre = blocks.class_count, int(blocks.has_centre)
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        w = flint.acb(flint.arb(flint.fmpq(2, n))).exp_pi_i()
        B1 = acb_matrix(blocks.frequency_matrix(), (OMEGA,), (w,))
        found = _isolated_largest(B1) if n > READ_AT + 3 else None  # where zoo_spectrum leaves the explicit route too
    lam1 = found if found is not None else _largest_of_spectrum(blocks, digits, zm.depth, scheme.lattice)
    with flint.ctx.workprec(prec):
        B0 = sp.Matrix(blocks.frequency_zero_matrix())
        A0 = acb_matrix(B0, (), ()) - _identity(B0.shape[0])
        def why(lam: flint.acb, k: int) -> Callable[[], str]:
            return lambda: _not_simple(blocks, lam, k, scheme.lattice, zm.depth)

        y0 = _checked(null_vector(A0.transpose(), first=0), A0, n, why(flint.acb(1), 0))
        A1 = B1 - lam1 * _identity(K)
        y1 = _checked(null_vector(A1.transpose(), first=0), A1, n, why(lam1, 1))
        total = sum(y0, flint.acb(0))
        position = [y / total for y in y0]
        tangent = [y / y1[0] for y in y1]

        def text(z: flint.acb) -> str:
            return acb_text(z, digits)

        masks: dict[str, Any] = {"position": {"classes": {}}, "tangents": [{"classes": {}}, {"classes": {}}]}
        if centre:
            masks["position"]["O"] = text(position[0])
            masks["tangents"][0]["O"] = masks["tangents"][1]["O"] = "0"
        for c in range(K):
            masks["position"]["classes"][str(c)] = [text(position[centre + c] / n)] * n
            rot = [tangent[c] * flint.acb(flint.arb(flint.fmpq(-2 * s, n))).exp_pi_i() for s in range(n)]
            masks["tangents"][0]["classes"][str(c)] = [text(flint.acb(z.real)) for z in rot]
            masks["tangents"][1]["classes"][str(c)] = [text(flint.acb(-z.imag)) for z in rot]
    return {"n": n, "scheme": scheme.name, "rings": zm.depth, "steps": scheme.steps, "subdominant": acb_text(lam1, digits), **masks}
