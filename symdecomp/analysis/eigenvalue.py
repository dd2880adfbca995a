"""A distinct eigenvalue with its multiplicity: the one type of every spectrum of the toolkit.

The closed-form spectrum (:mod:`symdecomp.analysis.spectrum`), the ``K``-ring's factored spectrum
(:func:`symdecomp.analysis.spectrum.ring_spectrum`), the exact eigenvalues of a boundary, crease, corner or dart
vertex (part by part, :mod:`symdecomp.analysis.triangular_eigen`; by the mirror decomposition's blocks,
:mod:`symdecomp.analysis.block_values` and :func:`~symdecomp.analysis.mirror.sector_spectrum`; named
by block, :func:`symdecomp.analysis.spectrum.sharp_spectrum`) and the numeric cross-checks
(:mod:`symdecomp.verify.numeric`) all speak of the same thing: a value of the subdivision matrix's
spectrum, how many times it occurs, and where it comes from (the n-gon frequencies or the mirror
blocks that give it, the closed forms, the factor of the characteristic polynomial and which of its
roots, the part of a block-triangular matrix, its Jordan blocks). Each fills the fields it knows; the
others keep their defaults ("not known here").

>>> import mpmath
>>> e = Eigenvalue(mpmath.mpf(1) / 2, "0.5", 2, frequencies=(1, 3))
>>> e.as_json()
{'value': '0.5', 'multiplicity': 2, 'frequencies': [1, 3]}
>>> e.as_json(exact=True)
{'value': '0.5', 'multiplicity': 2, 'frequencies': [1, 3], 'exact': None, 'jordan_blocks': None}
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import sympy as sp

from symdecomp.errors import NotApplicableError

if TYPE_CHECKING:
    from symdecomp.schemes.sector import SharpVertex

__all__ = ["Eigenvalue", "ClosedFormLabel", "MirrorBlock", "pi_multiple"]


@dataclass(frozen=True)
class ClosedFormLabel:
    """Where one closed-form eigenvalue comes from."""

    #: The n-gon frequency ``k`` (``0`` is the block of Eq. 43).
    frequency: int
    #: Which closed form: ``"Eq. 43 root i"``, ``"Eq. 34 dominant"`` or ``"Eq. 34 subdominant"``.
    label: str


@dataclass(frozen=True)
class MirrorBlock:
    """Where an eigenvalue of a boundary, crease, corner or dart vertex comes from in its mirror decomposition
    (:func:`~symdecomp.analysis.mirror.sector_decomposition`)."""

    #: ``"crease"``, ``"cosine"`` (a dart's symmetric part), ``"sine"`` or ``"face"`` (a sector's last mode).
    block: str
    #: The sector (``0``, ``1``, ...) of a sine or face block, else ``None``.
    sector: int | None = None
    #: The sine block's ``j`` (``theta = pi j/k``), or ``k`` for the last mode, else ``None``.
    j: int | None = None

    def name(self, vertex: SharpVertex) -> str:
        """The block as a spectrum prints it at ``vertex`` (a :class:`~symdecomp.schemes.sector.SharpVertex`):
        ``"crease"``, ``"cosine (symmetric part)"``, ``"sine j=1 (theta = pi/5), sector 2"``, ``"last mode j=5 ..."``.

        >>> from symdecomp.schemes.sector import SharpVertex
        >>> MirrorBlock("sine", 0, 2).name(SharpVertex.boundary(5, "quad"))
        'sine j=2 (theta = 2*pi/5)'
        """
        if self.block in ("crease", "cosine"):
            return "crease" if self.block == "crease" else "cosine (symmetric part)"
        assert self.sector is not None and self.j is not None  # a sine or face block names both
        k = vertex.sectors[self.sector]
        where = f", sector {self.sector + 1}" if len(vertex.sectors) > 1 else ""
        if self.block == "face":
            return f"last mode j={self.j} (b_i = (-1)^i){where}"
        theta = pi_multiple(Fraction(self.j * (2 if vertex.closed and len(vertex.sectors) == 1 else 1), k))
        return f"sine j={self.j} (theta = {theta}){where}"


def pi_multiple(q: Fraction) -> str:
    """``q pi`` as sympy prints it (``pi/5``, ``2*pi/5``, ``pi``), without building the expression (20,000 names at a
    vertex of 10,000 faces)."""
    head = "pi" if q.numerator == 1 else f"{q.numerator}*pi"
    return head if q.denominator == 1 else f"{head}/{q.denominator}"


@dataclass(frozen=True)
class Eigenvalue:
    """One distinct eigenvalue of a subdivision matrix at a valence, with its multiplicity."""

    #: The value: an mpmath number at the working precision, a certified ball (``flint.acb``), or an exact
    #: sympy number (the mirror blocks' closed forms, :func:`~symdecomp.analysis.mirror.sector_spectrum`); typed ``Any``, as
    #: ``exact`` below: the readers know which route they read (the C1 test's block roots are ``flint.acb`` balls).
    value: Any
    #: The value as decimal text with the requested number of significant digits; empty where none was asked
    #: for (an exact route's values before a spectrum prints them).
    text: str
    #: Algebraic multiplicity (how many eigenvalues, counted with repetition, coincide with it).
    multiplicity: int
    #: The n-gon frequencies ``k`` whose blocks contribute it (``0`` is the block of Eq. 43); empty if not known.
    frequencies: tuple[int, ...] = ()
    #: The closed forms it comes from, one per unit of multiplicity; empty if not known.
    labels: tuple[ClosedFormLabel, ...] = ()
    #: An exact expression (closed-form roots; a ``CRootOf`` for a root of a rational factor of degree > 2), or its
    #: text where it is built as text (the structural route of a sharp vertex, a spectrum's printed form), or ``None``
    #: when not computed (typed ``Any``: sympy has no type information, and the readers know which route they read).
    exact: Any = None
    #: The factor it is a root of: a polynomial in ``lambda`` (at its first frequency), or the monic irreducible
    #: rational factor (``flint.fmpq_poly``) of an exact route; ``None`` if not known.
    factor: Any = None
    #: Sizes of its Jordan blocks when known (all 1: not defective), else ``None``.
    jordan: tuple[int, ...] | None = None
    #: The roots in its cluster, ``(frequency k, factor index, root index)``, one per unit of multiplicity
    #: (the factor's exponent repeats a root); for certificates of multiplicities.
    members: tuple[tuple[int, int, int], ...] = ()
    #: A ball holding every root of its cluster (``value`` holds the first), or ``None``.
    hull: object = None
    #: Its index among the roots of ``factor`` in sympy's order (real ascending, then complex), or among the two roots of
    #: its frequency block (``0``: the larger in modulus; the C1 test's blocks, :mod:`symdecomp.verify.c1_spectrum`), or ``None``.
    index: int | None = None
    #: The part(s) of a block-triangular matrix it comes from (``"crease"``, ``"crease, sector 1"``, ``"whole"``), or ``""``.
    part: str = ""
    #: The blocks of a mirror decomposition that have it: :class:`MirrorBlock` items, or their names as text in a
    #: printed spectrum (:class:`~symdecomp.analysis.spectrum.SharpSpectrum`); empty if not known.
    blocks: tuple[object, ...] = ()
    #: Equal keys, equal values (and conversely) among the values of one exact computation, or ``None``.
    key: tuple[object, ...] | None = None
    #: While an exact route joins equal values, what decides equality exactly and gives the value's ball (the route's own
    #: object: :mod:`symdecomp.analysis.block_values`); ``None`` in every result.
    witness: Any = field(default=None, compare=False, repr=False)
    #: One of two complex conjugate roots of the same real block (real trace and determinant), so of equal moduli.
    conjugate: bool = False
    #: A double root of its frequency block, shown exactly (discriminant 0 in the cyclotomic field); ``multiplicity``
    #: counts both roots.
    double: bool = False

    @property
    def frequency(self) -> int | None:
        """The frequency of the block it is a root of (the first of ``frequencies``), or ``None`` if not known."""
        return self.frequencies[0] if self.frequencies else None

    @property
    def defective(self) -> bool:
        """Whether a Jordan block of size above 1 is known (``jordan``)."""
        return self.jordan is not None and max(self.jordan) > 1

    @property
    def ball(self) -> object:
        """The value, where it is a certified ball (the exact routes' values are)."""
        return self.value

    @property
    def is_real(self) -> bool:
        """Whether the value is real, decided on its exact form (a closed form or a ``CRootOf``)."""
        if not isinstance(self.exact, sp.Expr):
            raise NotApplicableError(f"eigenvalue {self.text or self.exact}: no exact form to decide whether it is real")
        return bool(self.exact.is_real)

    def as_json(self, *, exact: bool = False) -> dict[str, object]:
        """Value, multiplicity and frequencies; with ``exact``, the exact form and the Jordan blocks too."""
        out: dict[str, object] = {"value": self.text, "multiplicity": self.multiplicity, "frequencies": list(self.frequencies)}
        if exact:
            out["exact"] = None if self.exact is None else str(self.exact)
            out["jordan_blocks"] = None if self.jordan is None else list(self.jordan)
        return out

    def describe(self) -> str:
        """The text with where it comes from, for messages: ``"0.5 (Eq. 34 dominant; k = 1, 3; multiplicity 2)"``."""
        ks = sorted({lab.frequency for lab in self.labels} or set(self.frequencies))
        kinds = sorted({lab.label for lab in self.labels})
        where = "; ".join(kinds + [f"k = {', '.join(map(str, ks))}"])
        return f"{self.text} ({where}; multiplicity {self.multiplicity})"
