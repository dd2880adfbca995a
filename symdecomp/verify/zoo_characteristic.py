"""What the zoo's engine gives the C1 test at one valence: the local mesh, Reif's spectral conditions, the characteristic map.

For a scheme of the zoo at valence ``n`` (:mod:`symdecomp.verify.c1_zoo` decides which schemes have a test), the
engine's matrix on the neighbourhood of depth :data:`C1_DEPTH` (:func:`~symdecomp.analysis.zoo_matrix.zoo_matrix`:
for a dual scheme the centre ``n``-gon and two rings of faces, enough for the biquadratic patches one face from the
centre and their 3 x 3 control points) gives

* Reif's spectral conditions, from the certified spectrum by frequency
  (:func:`~symdecomp.analysis.zoo_spectrum.zoo_spectrum`): ``1`` simple, at frequency 0; the subdominant
  eigenvalue real, double, from one pair of frequencies ``j, n - j``, strictly larger in modulus than every other
  eigenvalue (the gap a certified lower bound);
* the characteristic map: with ``B_j x = lambda x`` in the frequency-``j`` block
  (:class:`~symdecomp.analysis.zoo_blocks.ZooBlocks`, ``A_d[c, c']`` the weight of point ``(s + d, c')`` in the new
  point ``(s, c)``), the vector ``X(s, c) = zeta^(j s) x_c`` (``zeta = e^(2 pi i/n)``) is an eigenvector of the whole
  matrix, and its real and imaginary parts are the two real eigenvectors of ``lambda``: the control points
  ``(Re X, Im X)`` of the map, as complex balls (``x`` solved in Arb from the block).
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.null_vector import null_vector
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.masks import acb_matrix
from symdecomp.analysis.spectrum import RingSpectrum
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import ZooMatrix, zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.schemes.neighbourhood import Neighbourhood
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.c1_dual import DualNeighbourhood
from symdecomp.verify.c1_spectrum import SpectralResult, block_root, float_down
from symdecomp.verify.c1_zoo import ZooNeighbourhood
from symdecomp.verify.result import C1Verdict

__all__ = ["C1_DEPTH", "engine_neighbourhood", "spectral_conditions", "real_matrix", "characteristic_points"]

#: The ring depth of the neighbourhood the C1 test reads (the patches one face from the centre and their control points).
C1_DEPTH = 2
#: The working precision of the characteristic map's control points (bits).
EIGENVECTOR_BITS = 128


def _ball(e: Eigenvalue) -> flint.acb:
    """The eigenvalue's certified ball (a spectrum by frequency holds ``flint.acb`` values)."""
    assert isinstance(e.value, flint.acb)
    return e.value


def spectral_conditions(spectrum: RingSpectrum, n: int, *, real_matrix: bool = False) -> SpectralResult:
    """Reif's spectral conditions from a certified spectrum by frequency (one eigenvalue type: ``Eigenvalue``).

    ``1`` must be exactly an eigenvalue (its exact form is 1), simple, at frequency 0; the subdominant eigenvalue
    exactly real, of multiplicity 2 from one pair of frequencies ``j, n - j``, with a certified gap to the rest.
    Real: its exact form's imaginary part is 0 as sympy writes it, or (``real_matrix``: the matrix is real) its
    conjugate, an eigenvalue of the same modulus, is no other eigenvalue (the certified gap): it is itself.
    """
    values = list(spectrum.eigenvalues)
    ones = [e for e in values if e.exact is not None and e.exact == 1]
    if len(ones) != 1 or ones[0].multiplicity != 1 or tuple(ones[0].frequencies) != (0,):
        verdict = C1Verdict.NOT_C1 if len(ones) == 1 else C1Verdict.UNDECIDED
        return SpectralResult(n, verdict, "1 is not a simple eigenvalue of the frequency-0 block", one_simple=False)
    rest = [e for e in values if e is not ones[0]]
    lam = max(rest, key=lambda e: float(abs(_ball(e)).mid()))
    others = [e for e in rest if e is not lam]
    bound = max((abs(_ball(e)).upper() for e in others), default=flint.arb(0))
    gap, pair = abs(_ball(lam)).lower() - bound, sorted(lam.frequencies)
    if not gap > 0:
        return SpectralResult(n, C1Verdict.UNDECIDED, f"the subdominant eigenvalue {lam.text} is not shown strictly dominant "
                              "(its modulus and the next one's overlap)", second=float(bound))
    if lam.exact is None and lam.multiplicity == 2 and len(pair) == 2 and pair[0] + pair[1] == n:
        return SpectralResult(n, C1Verdict.UNDECIDED, f"the subdominant eigenvalue {lam.text} has no exact form here, so it "
                              "is not shown real (nor is the eigenvector solved with it)", second=float(bound))
    real = lam.exact is not None and (sp.im(lam.exact) == 0 or real_matrix and _ball(lam).imag.contains(0))
    if lam.multiplicity == 2 and len(pair) == 2 and pair[0] + pair[1] == n and not real and _ball(lam).imag.contains(0):
        return SpectralResult(n, C1Verdict.UNDECIDED, f"the subdominant eigenvalue {lam.text} is not shown real: its exact "
                              "form does not reduce to a real number here, and its ball meets the real axis", second=float(bound))
    if lam.multiplicity != 2 or len(pair) != 2 or pair[0] + pair[1] != n or not real:
        return SpectralResult(n, C1Verdict.NOT_C1, f"the subdominant eigenvalue {lam.text} is not a real double eigenvalue "
                              f"of one pair of frequencies j, n - j (its frequencies: {', '.join(map(str, pair))})",
                              second=float(bound))
    # a root of a block with omega = exp(2 pi i j/n) in it has exp(i pi q) in its exact form, which the compiler takes as
    # cos + i sin; the value is real (above), so the real part of its ball is the ball of the value
    exact = sp.re(lam.exact.rewrite(sp.cos) if lam.exact.has(sp.exp) else lam.exact)
    with flint.ctx.workprec(EIGENVECTOR_BITS):  # the exact value as a narrow ball: the eigenvector is solved with it
        value = compile_expression(exact, (), "arb")()
        eigen = block_root(flint.acb(value.real if isinstance(value, flint.acb) else value), pair[0], 2, n)
    return SpectralResult(n, C1Verdict.C1, "spectral conditions hold", eigen, float_down(gap), float(bound))


def real_matrix(zm: ZooMatrix) -> bool:
    """Whether every entry of the engine's matrix is real (then the conjugate of an eigenvalue is one: the
    ``real_matrix`` argument of :func:`spectral_conditions`)."""
    return all(e.is_real for e in set(zm.matrix))


def _centre_face(nb: Neighbourhood) -> tuple[int, ...]:
    """The centre ``n``-gon: the one face of ``n`` points of one class (the rotation permutes its corners)."""
    for face in nb.mesh.faces:
        classes = {nb.labels.get(v, (None, None))[1] for v in face}
        if len(face) == nb.n and len(classes) == 1 and None not in classes:
            return tuple(face)
    raise AssertionError("a face-centred neighbourhood has its centre face")  # pragma: no cover - built that way


def engine_neighbourhood(scheme: StencilScheme, n: int) -> ZooNeighbourhood:
    """The local mesh with its orbit labels, the spectral conditions and the characteristic map at valence ``n``."""
    zm = zoo_matrix(scheme, n, C1_DEPTH)
    nb = zm.neighbourhood
    spectral = spectral_conditions(zoo_spectrum(scheme, n, C1_DEPTH, jordan=False), n, real_matrix=real_matrix(zm))
    labelled = set(nb.order)
    faces = tuple(tuple(f) for f in nb.mesh.faces if set(f) <= labelled)
    mesh = DualNeighbourhood(faces, _centre_face(nb), dict(nb.labels))
    if spectral.status is not C1Verdict.C1 or spectral.subdominant is None:
        return ZooNeighbourhood(mesh, {}, spectral, tuple(nb.order), zm.matrix)
    points = characteristic_points(zm, spectral.subdominant)
    if points is None:
        return ZooNeighbourhood(mesh, {}, SpectralResult(n, C1Verdict.UNDECIDED, "the subdominant eigenvector could not be "
                                                         "solved in the frequency block at this precision"))
    return ZooNeighbourhood(mesh, points, spectral, tuple(nb.order), zm.matrix)


def characteristic_points(zm: ZooMatrix, subdominant: Eigenvalue) -> dict[int, flint.acb] | None:
    """The characteristic map's control points on ``zm``'s neighbourhood, ``vertex -> complex ball`` (``X(s, c) =
    zeta^(j s) x_c``, module docstring; ``0`` at a centre vertex), or ``None`` if the eigenvector is not solved at this
    precision."""
    n, labels = zm.n, zm.neighbourhood.labels
    j, lam = subdominant.frequencies[0], subdominant.value
    with flint.ctx.workprec(EIGENVECTOR_BITS):  # the control points as narrow balls (the Jacobian's signs are decided on them)
        zeta = [flint.acb(flint.fmpq(2 * j * s, n)).exp_pi_i() for s in range(n)]
        block = zoo_blocks(zm).frequency_matrix()
        K = block.shape[0]
        A = acb_matrix(block, (OMEGA,), (zeta[1],)) - flint.acb_mat([[lam if r == c else 0 for c in range(K)] for r in range(K)])
        x = null_vector(A)
        if x is None:
            return None
        points = {v: zeta[s % n] * x[c] for v, (s, c) in labels.items()}
    if zm.neighbourhood.centre is not None:  # the rotation fixes the centre vertex: X = zeta^j X there, so X = 0
        points[zm.neighbourhood.centre] = flint.acb(0)
    return points
