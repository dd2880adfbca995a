"""Reif's spectral conditions on the functions a four-direction neighbourhood can make (Midedge at a triangle).

The four-direction patch's translates are linearly dependent (on the regular grid the alternating net gives the zero
function, :attr:`~symdecomp.schemes.four_direction.FourDirectionPatch.dependent_translates`), so a vector of control
points may give the zero function near the centre, and then its eigenvalue does not count. This module computes which
vectors vanish and redoes the spectral conditions on what remains, exactly (FLINT's rationals):

* **The function of a vector.** On the ring of patches (:func:`~symdecomp.verify.c1_dual.ring_patches`) the surface
  of control values ``c`` is, per triangle, a quadratic whose six Bernstein-Bezier coefficients are linear in ``c``
  (:attr:`~symdecomp.schemes.four_direction.FourDirectionPatch.coefficients`): one rational matrix ``E``
  (:func:`ring_evaluation`). The ring ``m`` steps in is the same patches of ``S^m c``, so ``c`` gives the zero
  function near the centre exactly when ``E S^m c = 0`` for every ``m``: the vanishing space ``V``, the null space
  of ``E, E S, ..., E S^(K-1)`` (Cayley-Hamilton stops it at ``K``, the matrix's size), the largest ``S``-invariant
  subspace in the null space of ``E``. An eigenvector (or a generalized one) counts exactly when it is not in ``V``.
* **The quotient.** ``S`` and the rotation ``R`` by one sector keep ``V`` (the ring is rotated onto itself), so both
  act on ``Q = R^K / V`` (:func:`quotient_operators`); the eigenvalues of ``S`` on ``Q`` are those with nonzero
  functions. The frequencies are read without complex numbers: the frequency class ``d`` (the frequencies ``j``
  with ``n / gcd(j, n) = d``) is the null space of the ``d``-th cyclotomic polynomial of ``R``, rational.
* **The conditions on the quotient.** ``1`` simple in class 1 (frequency 0); the subdominant eigenvalue ``lambda``
  (largest modulus after 1, strictly) rational, in one class ``d`` with two frequencies (``j, n - j``), with two
  eigenvectors and no Jordan block. Then the characteristic map is ``(x, R x - cos(2 pi/d) x)`` for an eigenvector
  ``x`` (the real and imaginary parts of the complex one, up to a positive scale of the second) and Reif's test runs
  on it (:func:`~symdecomp.verify.c1_four_direction.certify_four_direction_ring`). Otherwise the Jordan structure of
  ``lambda`` by class is the reason; where the Jordan blocks of largest size ``p`` at ``lambda`` give a two
  dimensional space of chain eigenvectors (``e = (S - lambda)^(p-1) g``, the image of the generalized eigenspace) in
  one such class, the rings grow as ``m^(p-1) lambda^m`` on those ``e``, and the map of that pair is certified; the
  outcome keeps the chain ``(g, e)``, and :mod:`symdecomp.verify.c1_four_direction_jordan` reads the verdict from it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from math import gcd
from typing import Any

import flint
import sympy as sp

from symdecomp.schemes.four_direction import OFFSETS, FourDirectionPatch
from symdecomp.verify.c1_dual import DualNeighbourhood, RingCertificate, ring_patches
from symdecomp.verify.c1_four_direction import certify_four_direction_ring

__all__ = ["JordanCount", "QuotientSpectrum", "ring_evaluation", "vanishing_space", "quotient_operators",
           "frequency_classes", "jordan_counts", "quotient_spectrum", "planar_points",
           "null_space", "rotation_matrix", "QuotientOutcome", "quotient_test"]

_Vector = list[flint.fmpq]


@dataclass(frozen=True)
class JordanCount:
    """The structure of one eigenvalue on the quotient within one frequency class."""

    #: The frequency class ``d`` (the frequencies ``j`` with ``n / gcd(j, n) = d``).
    frequency_class: int
    #: The frequencies of the class.
    frequencies: tuple[int, ...]
    #: ``dims[p - 1]``: the dimension of the null space of ``(S - lambda)^p`` in the class (real dimensions).
    dims: tuple[int, ...]

    @property
    def eigenvectors(self) -> int:
        """The geometric multiplicity in the class (real dimension)."""
        return self.dims[0]

    @property
    def algebraic(self) -> int:
        """The algebraic multiplicity in the class (real dimension)."""
        return self.dims[-1]

    @property
    def largest_block(self) -> int:
        """The size of the largest Jordan block in the class."""
        return len(self.dims)

    def text(self) -> str:
        each = len(self.frequencies)
        sizes = _block_sizes(self.dims)
        blocks = ", ".join(f"{count // each} of size {size}" for size, count in sizes if count)
        return (f"frequenc{'y' if each == 1 else 'ies'} {', '.join(map(str, self.frequencies))}: "
                f"{self.eigenvectors // each} eigenvector{'s' if self.eigenvectors // each != 1 else ''} "
                f"and {self.algebraic // each} in all{'' if each == 1 else ' each'} (Jordan blocks: {blocks})")


def _block_sizes(dims: tuple[int, ...]) -> list[tuple[int, int]]:
    """``(size, how many)`` of the Jordan blocks from the kernel dimensions of the powers."""
    full = (0, *dims, dims[-1])
    steps = [full[p] - full[p - 1] for p in range(1, len(full))]  # blocks of size >= p
    return [(p, steps[p - 1] - steps[p]) for p in range(len(dims), 0, -1)]


@dataclass(frozen=True)
class QuotientSpectrum:
    """The spectrum of the subdivision matrix on the functions the four-direction ring can make."""

    #: The number of control points ``K``.
    size: int
    #: The rank of the ring's evaluation ``E`` (``K``: no single vector gives the zero function on the ring).
    evaluation_rank: int
    #: A basis of the vanishing space ``V`` (module docstring), exact.
    vanishing: tuple[tuple[flint.fmpq, ...], ...]
    #: The factors of the characteristic polynomial of ``S`` on the quotient, ``(factor, multiplicity)``.
    factors: tuple[tuple[flint.fmpq_poly, int], ...]
    #: The subdominant eigenvalue on the quotient when it is rational and strictly dominant, else ``None``.
    subdominant: Fraction | None
    #: Why ``subdominant`` is ``None`` (else ``""``).
    problem: str
    #: The structure of ``subdominant`` by frequency class (classes where it occurs).
    jordan: tuple[JordanCount, ...]


def _matrix(rows: Sequence[Sequence[Any]], cols: int) -> flint.fmpq_mat:
    return flint.fmpq_mat(len(rows), cols, [flint.fmpq(x) if isinstance(x, int) else x for r in rows for x in r])


def _to_fmpq(x: Any) -> flint.fmpq:
    r = sp.Rational(x)
    return flint.fmpq(int(r.p), int(r.q))


def ring_evaluation(mesh: DualNeighbourhood, order: Sequence[Any], patch: FourDirectionPatch) -> flint.fmpq_mat:
    """``E``: the Bernstein-Bezier coefficients of every triangle of the ring (patch by patch, triangle ``k``, coefficient
    ``i``) as rows of linear forms in the control values in ``order``."""
    index = {v: i for i, v in enumerate(order)}
    rows = []
    for ring_patch in ring_patches(mesh):
        for k in range(4):
            for i in range(6):
                row = [flint.fmpq(0)] * len(order)
                for m, b in enumerate(OFFSETS):
                    c = patch.coefficients[k][m][i]
                    if c:
                        row[index[ring_patch.grid[1 + b[0]][1 + b[1]]]] += flint.fmpq(c.numerator, c.denominator)
                rows.append(row)
    return _matrix(rows, len(order))


def null_space(matrix: flint.fmpq_mat) -> list[_Vector]:
    """A basis of the rational null space (exact elimination)."""
    reduced, rank = matrix.rref()
    cols = matrix.ncols()
    pivots = [next(c for c in range(cols) if reduced[r, c] != 0) for r in range(rank)]
    basis = []
    for free in (c for c in range(cols) if c not in pivots):
        vector = [flint.fmpq(0)] * cols
        vector[free] = flint.fmpq(1)
        for r, c in enumerate(pivots):
            vector[c] = -reduced[r, free]
        basis.append(vector)
    return basis


def _stack(blocks: Sequence[flint.fmpq_mat]) -> flint.fmpq_mat:
    cols = blocks[0].ncols()
    return flint.fmpq_mat(sum(b.nrows() for b in blocks), cols,
                          [b[i, j] for b in blocks for i in range(b.nrows()) for j in range(cols)])


def vanishing_space(evaluation: flint.fmpq_mat, matrix: flint.fmpq_mat) -> list[_Vector]:
    """The vectors whose function vanishes on every ring: the null space of ``E S^m``, ``m = 0..K-1``."""
    blocks, power = [], evaluation
    for _ in range(matrix.nrows()):
        blocks.append(power)
        power = power * matrix
    return null_space(_stack(blocks))


def quotient_operators(vanishing: Sequence[_Vector], operators: Sequence[flint.fmpq_mat]) -> tuple[
        flint.fmpq_mat, list[flint.fmpq_mat]]:
    """A basis ``B`` of ``R^K`` starting with ``vanishing`` (completed by unit vectors), and each operator (which keeps
    the vanishing space) on the quotient: the lower-right block of ``B^-1 A B``. The quotient's vectors lift to
    ``R^K`` as the last columns of ``B``."""
    size = operators[0].nrows()
    columns = [list(v) for v in vanishing]
    rank = len(columns)
    for unit in range(size):
        e = [flint.fmpq(int(i == unit)) for i in range(size)]
        trial = _matrix([*columns, e], size)
        if trial.rank() > rank:
            columns.append(e)
            rank += 1
    basis = _matrix(columns, size).transpose()
    inverse, d = basis.inv(), len(vanishing)
    out = []
    for op in operators:
        t = inverse * op * basis
        out.append(_matrix([[t[i, j] for j in range(d, size)] for i in range(d, size)], size - d))
    return basis, out


def _polynomial_of(matrix: flint.fmpq_mat, coefficients: Sequence[int]) -> flint.fmpq_mat:
    """``p(matrix)`` by Horner's rule (``coefficients`` from the constant term up)."""
    size = matrix.nrows()
    identity = _identity(size)
    out = flint.fmpq_mat(size, size)
    for c in reversed(coefficients):
        out = out * matrix + identity * flint.fmpq(c)
    return out


def _identity(size: int) -> flint.fmpq_mat:
    return flint.fmpq_mat(size, size, [int(i == j) for i in range(size) for j in range(size)])


def frequency_classes(n: int) -> list[tuple[int, tuple[int, ...]]]:
    """The frequency classes ``d | n`` with their frequencies ``j`` (``n / gcd(j, n) = d``)."""
    return [(d, tuple(j for j in range(n) if n // gcd(j, n) == d)) for d in range(1, n + 1) if n % d == 0]


def _class_projector(rotation: flint.fmpq_mat, d: int) -> flint.fmpq_mat:
    """``Phi_d(R)``, whose null space is the frequency class ``d``."""
    return _polynomial_of(rotation, [int(c) for c in flint.fmpz_poly.cyclotomic(d).coeffs()])


def jordan_counts(matrix: flint.fmpq_mat, rotation: flint.fmpq_mat, value: Fraction, n: int) -> list[JordanCount]:
    """The Jordan structure of the rational eigenvalue ``value`` of ``matrix`` in each frequency class where it occurs."""
    size = matrix.nrows()
    shifted = matrix - _identity(size) * flint.fmpq(value.numerator, value.denominator)
    out = []
    for d, frequencies in frequency_classes(n):
        phi = _class_projector(rotation, d)
        dims: list[int] = []
        power = shifted
        while True:
            dim = size - _stack([power, phi]).rank()
            if dims and dim == dims[-1]:
                break
            if not dims and dim == 0:
                break
            dims.append(dim)
            power = power * shifted
        if dims:
            out.append(JordanCount(d, frequencies, tuple(dims)))
    return out


def _roots(polynomial: flint.fmpq_poly) -> list[flint.acb]:
    """The complex roots as balls (FLINT returns ``(root, multiplicity)`` pairs; its stubs say roots)."""
    pairs: list[Any] = list(polynomial.complex_roots())
    return [pair[0] for pair in pairs]


def _subdominant(factors: Sequence[tuple[flint.fmpq_poly, int]]) -> tuple[Fraction | None, str]:
    """The subdominant eigenvalue from the factored characteristic polynomial (without the factor ``x - 1``), if it is
    rational and strictly larger in modulus than every other eigenvalue."""
    one = flint.fmpq_poly([-1, 1])
    moduli = [(abs(z), f) for f, _ in factors if f != one for z in _roots(f)]
    if not moduli:
        return None, "no eigenvalue other than 1 gives a nonzero function"
    top = max(moduli, key=lambda t: float(t[0].upper()))
    if top[1].degree() != 1:
        return None, f"the largest eigenvalue after 1 is a root of {top[1]}, not rational (not analysed here)"
    if any(not top[0] > m for m, f in moduli if f != top[1]):
        return None, "the largest eigenvalue after 1 is not shown strictly larger in modulus than the others"
    root = -top[1][0] / top[1][1]
    return Fraction(int(root.p), int(root.q)), ""


def quotient_spectrum(mesh: DualNeighbourhood, order: Sequence[Any], matrix: Any, patch: FourDirectionPatch,
                      rotation: flint.fmpq_mat, n: int) -> tuple[QuotientSpectrum, flint.fmpq_mat, list[flint.fmpq_mat]]:
    """The spectrum on the quotient by the vanishing space (module docstring), with the basis and the quotient's
    ``(S, R, E)``. ``matrix``: the exact subdivision matrix (rows and columns in ``order``)."""
    size = len(order)
    S = _matrix([[_to_fmpq(matrix[i, j]) for j in range(size)] for i in range(size)], size)
    E = ring_evaluation(mesh, order, patch)
    vanishing = vanishing_space(E, S)
    basis, (Sq, Rq) = quotient_operators(vanishing, [S, rotation])
    d = len(vanishing)
    lift = _matrix([[basis[i, j] for j in range(d, size)] for i in range(size)], size - d)
    factors = tuple((f, m) for f, m in Sq.charpoly().factor()[1])
    value, problem = _subdominant(factors)
    jordan = tuple(jordan_counts(Sq, Rq, value, n)) if value is not None else ()
    spectrum = QuotientSpectrum(size, E.rank(), tuple(tuple(v) for v in vanishing), factors, value, problem, jordan)
    return spectrum, lift, [Sq, Rq, E * lift]


def planar_points(vector: Sequence[flint.fmpq], rotation: flint.fmpq_mat, d: int, order: Sequence[Any],
                  lift: flint.fmpq_mat) -> dict[Any, tuple[Fraction, Fraction]]:
    """The planar map ``(x, R x - cos(2 pi/d) x)`` of a quotient vector ``x`` in class ``d`` (``cos(2 pi/d)`` is
    rational for the classes with two frequencies, ``d = 3, 4, 6``), lifted to the control points in ``order``."""
    cosine = {3: Fraction(-1, 2), 4: Fraction(0), 6: Fraction(1, 2)}[d]
    x = _matrix([[c] for c in vector], 1)
    y = rotation * x - x * flint.fmpq(cosine.numerator, cosine.denominator)
    X, Y = lift * x, lift * y
    return {v: (_fraction(X[i, 0]), _fraction(Y[i, 0])) for i, v in enumerate(order)}


def _fraction(q: flint.fmpq) -> Fraction:
    return Fraction(int(q.p), int(q.q))


def rotation_matrix(labels: Mapping[Any, tuple[int, int]], order: Sequence[Any], n: int) -> flint.fmpq_mat:
    """The rotation by one sector on the control values in ``order``: the value at ``(s, c)`` moves to ``(s + 1, c)``."""
    position = {labels[v]: i for i, v in enumerate(order)}
    rotation = flint.fmpq_mat(len(order), len(order))
    for i, v in enumerate(order):
        s, c = labels[v]
        rotation[position[((s + 1) % n, c)], i] = 1
    return rotation


@dataclass(frozen=True)
class QuotientOutcome:
    """What the quotient shows at one valence: the spectrum, whether Reif's conditions hold there, and a ring."""

    spectrum: QuotientSpectrum
    #: Whether Reif's spectral conditions hold on the quotient (then ``ring`` is the characteristic map's).
    conditions_hold: bool
    #: The spectral finding in words (the vanishing space, the Jordan structure of the subdominant eigenvalue).
    reason: str
    #: The ring certificate of the characteristic map (conditions hold) or of the top of the Jordan chains (evidence).
    ring: RingCertificate | None = None
    #: The frequency ``j`` of the map certified (the smaller of its pair).
    frequency: int | None = None
    #: ``True`` when the reason shows a failure of the spectral conditions with no Jordan block (not C1).
    refuted: bool = False
    #: Where the largest Jordan blocks at the subdominant eigenvalue (size ``p >= 2``) are one pair of frequencies: a
    #: chain's start ``g`` and its eigenvector ``e = (S - lambda)^(p-1) g``, on the control points (``order``), exact;
    #: the certified ``ring`` is the map of ``e``.
    chain: tuple[tuple[Fraction, ...], tuple[Fraction, ...]] | None = None
    #: ``p``, the size of those blocks (1 when there is no chain).
    chain_length: int = 1


def _vanishing_text(spectrum: QuotientSpectrum) -> str:
    if not spectrum.vanishing:
        return (f"no vector gives the zero function near the centre (the ring's {spectrum.size} control values map "
                f"injectively to its Bezier coefficients: rank {spectrum.evaluation_rank}), so every eigenvector counts")
    return (f"the vectors giving the zero function near the centre span {len(spectrum.vanishing)} of {spectrum.size} "
            "dimensions (their eigenvalues do not count)")


def quotient_test(mesh: DualNeighbourhood, order: Sequence[Any], matrix: Any, patch: FourDirectionPatch, n: int, *,
                  max_depth: int = 6, prec: int = 64) -> QuotientOutcome:
    """Reif's spectral conditions on the quotient by the vanishing space and the ring of what they select (module
    docstring). ``mesh.labels`` must label every vertex of ``order``."""
    rotation = rotation_matrix(mesh.labels, order, n)
    spectrum, lift, (Sq, Rq, _) = quotient_spectrum(mesh, order, matrix, patch, rotation, n)
    head = _vanishing_text(spectrum)
    one = jordan_counts(Sq, Rq, Fraction(1), n)
    if [(c.frequency_class, c.dims) for c in one] != [(1, (1,))]:
        return QuotientOutcome(spectrum, False, f"{head}; 1 is not a simple eigenvalue of frequency 0 there")
    value = spectrum.subdominant
    if value is None:
        return QuotientOutcome(spectrum, False, f"{head}; {spectrum.problem}")
    jordan = spectrum.jordan
    found = f"{head}; the subdominant eigenvalue {value} has, with nonzero functions, " + "; ".join(c.text() for c in jordan)
    top = max(c.largest_block for c in jordan)
    tops = [c for c in jordan if c.largest_block == top]
    pair = tops[0] if len(tops) == 1 and len(tops[0].frequencies) == 2 and _blocks_of(tops[0], top) == 2 else None
    if value <= 0:
        return QuotientOutcome(spectrum, False, f"{found}: it is not positive, and Reif's test here needs a positive "
                               "subdominant eigenvalue")
    if top == 1 and len(jordan) == 1 and pair is not None:
        ring, _ = _ring(mesh, order, patch, Sq, Rq, lift, value, pair, 1, max_depth, prec)
        return QuotientOutcome(spectrum, True, f"{found}: Reif's spectral conditions hold on the quotient", ring,
                               pair.frequencies[0])
    if top == 1:
        return QuotientOutcome(spectrum, False, f"{found}: not a real double eigenvalue of one pair of frequencies j, "
                               "n - j, and no Jordan block: its eigenvectors' functions, independent, are not two, so "
                               "Reif's spectral conditions fail on the functions", refuted=True)
    if pair is None:
        return QuotientOutcome(spectrum, False, f"{found}: its largest Jordan blocks (size {top}) are not one pair of "
                               "frequencies j, n - j, so no characteristic map is defined; Reif's test does not apply")
    ring, chain = _ring(mesh, order, patch, Sq, Rq, lift, value, pair, top, max_depth, prec)
    growth = f"m^{top - 1}" if top > 2 else "m"
    return QuotientOutcome(spectrum, False, f"{found}: the rings grow as {growth} ({value})^m on the eigenvectors e = "
                           f"(S - {value}){'' if top == 2 else f'^{top - 1}'} g of its longest Jordan chains (frequencies "
                           f"{', '.join(map(str, pair.frequencies))})", ring, pair.frequencies[0], chain=chain,
                           chain_length=top)


def _blocks_of(count: JordanCount, size: int) -> int:
    """How many Jordan blocks of ``size`` the class has (real count)."""
    return dict(_block_sizes(count.dims)).get(size, 0)


def _ring(mesh: DualNeighbourhood, order: Sequence[Any], patch: FourDirectionPatch, Sq: flint.fmpq_mat,
          Rq: flint.fmpq_mat, lift: flint.fmpq_mat, value: Fraction, pair: JordanCount, size: int, max_depth: int,
          prec: int) -> tuple[RingCertificate, tuple[tuple[Fraction, ...], tuple[Fraction, ...]]]:
    """The ring of the planar map of ``e = (S - lambda)^(size-1) g`` for a generalized eigenvector ``g`` of the class
    that starts a chain of ``size`` (for ``size`` 1: an eigenvector, ``e = g``), with ``(g, e)`` on the control points:
    ``e`` is what ``S^m`` multiplies by ``binomial(m, size - 1)`` (the leading term)."""
    shifted = Sq - _identity(Sq.nrows()) * flint.fmpq(value.numerator, value.denominator)
    phi = _class_projector(Rq, pair.frequency_class)
    lifted = shifted ** (size - 1)
    starts = (_matrix([[c] for c in g], 1) for g in null_space(_stack([shifted ** size, phi])))
    g, e = next((g, lifted * g) for g in starts if any(x != 0 for x in (lifted * g).entries()))  # g starts a chain of size
    points = planar_points([e[i, 0] for i in range(e.nrows())], Rq, pair.frequency_class, order, lift)
    chain = tuple(tuple(_fraction(x) for x in (lift * v).entries()) for v in (g, e))
    with flint.ctx.workprec(prec):
        return certify_four_direction_ring(mesh, points, patch, max_depth=max_depth), (chain[0], chain[1])
