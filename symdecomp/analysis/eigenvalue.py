"""A distinct eigenvalue with its multiplicity: the one type of every spectrum of the toolkit.

The closed-form spectrum (:mod:`symdecomp.analysis.spectrum`), the ``K``-ring's factored spectrum
(:mod:`symdecomp.analysis.ring_spectrum`) and the numeric cross-checks (:mod:`symdecomp.verify.numeric`)
all speak of the same thing: a value of the subdivision matrix's spectrum, how many times it occurs,
and where it comes from (the n-gon frequencies whose blocks give it, the closed forms, the factor of
the characteristic polynomial, its Jordan blocks). Each fills the fields it knows; the others keep
their defaults ("not known here").

>>> import mpmath
>>> e = Eigenvalue(mpmath.mpf(1) / 2, "0.5", 2, frequencies=(1, 3))
>>> e.as_json()
{'value': '0.5', 'multiplicity': 2, 'frequencies': [1, 3]}
>>> e.as_json(exact=True)
{'value': '0.5', 'multiplicity': 2, 'frequencies': [1, 3], 'exact': None, 'jordan_blocks': None}
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = ["Eigenvalue", "ClosedFormLabel"]


@dataclass(frozen=True)
class ClosedFormLabel:
    """Where one closed-form eigenvalue comes from."""

    #: The n-gon frequency ``k`` (``0`` is the block of Eq. 43).
    frequency: int
    #: Which closed form: ``"Eq. 43 root i"``, ``"Eq. 34 dominant"`` or ``"Eq. 34 subdominant"``.
    label: str


@dataclass(frozen=True)
class Eigenvalue:
    """One distinct eigenvalue of a subdivision matrix at a valence, with its multiplicity."""

    #: The value: an mpmath number at the working precision, or a certified ball (``flint.acb``).
    value: object
    #: The value as decimal text with the requested number of significant digits.
    text: str
    #: Algebraic multiplicity (how many eigenvalues, counted with repetition, coincide with it).
    multiplicity: int
    #: The n-gon frequencies ``k`` whose blocks contribute it (``0`` is the block of Eq. 43); empty if not known.
    frequencies: tuple[int, ...] = ()
    #: The closed forms it comes from, one per unit of multiplicity; empty if not known.
    labels: tuple[ClosedFormLabel, ...] = ()
    #: An exact expression (closed-form roots), or ``None`` when not computed (or a root of a factor of degree > 2).
    exact: sp.Expr | None = None
    #: The factor (a polynomial in ``lambda``) it is a root of, at its first frequency, or ``None``.
    factor: sp.Expr | None = None
    #: Sizes of its Jordan blocks when known (all 1: not defective), else ``None``.
    jordan: tuple[int, ...] | None = None
    #: The roots in its cluster, ``(frequency k, factor index, root index)``, one per unit of multiplicity
    #: (the factor's exponent repeats a root); for certificates of multiplicities.
    members: tuple[tuple[int, int, int], ...] = ()
    #: A ball holding every root of its cluster (``value`` holds the first), or ``None``.
    hull: object = None

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
