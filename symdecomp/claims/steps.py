"""A claim's derivation as displayed steps (:class:`Step`), built at once or the first time they are read
(:class:`LazySteps`): what ``derive`` typesets and a notebook shows, never what a verdict rests on."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any

__all__ = ["Step", "LazySteps"]


@dataclass(frozen=True)
class Step:
    """One displayed step of a derivation: a sentence and, optionally, a sympy object."""

    #: What the step says, in words (may contain inline LaTeX between ``$``).
    text: str
    #: The object computed at this step (an expression, an equation, a matrix), or ``None``.
    expr: object = None
    #: Optional left-hand side, displayed as ``lhs = expr``.
    lhs: object = None


class LazySteps(Sequence[Step]):
    """Derivation steps built the first time they are read, for steps whose expressions cost more than the check.

    ``CheckResult(..., steps=LazySteps(lambda: (Step(...), ...)))``: ``build`` is called once, when the steps are first
    read (``derive``, a notebook), and never when only the verdict is (``claims`` on the pool drops the steps unread,
    :mod:`symdecomp.claims.batch`); so ``build`` may compute only what is displayed, never what the verdict rests on. It
    reads as the tuple it builds (compared, added and pickled as that tuple; pickling builds it: a closure does not pickle).
    """

    __slots__ = ("_build", "_steps")

    def __init__(self, build: Callable[[], Iterable[Step]]):
        self._build: Callable[[], Iterable[Step]] | None = build
        self._steps: tuple[Step, ...] | None = None

    @property
    def built(self) -> bool:
        """Whether the steps have been built (read) yet."""
        return self._steps is not None

    def _tuple(self) -> tuple[Step, ...]:
        if self._steps is None:
            assert self._build is not None
            self._steps, self._build = tuple(self._build()), None
        return self._steps

    def __getitem__(self, index: Any) -> Any:  # Sequence's overloads: an int gives a Step, a slice a tuple
        return self._tuple()[index]

    def __len__(self) -> int:
        return len(self._tuple())

    def __iter__(self) -> Iterator[Step]:
        return iter(self._tuple())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, (tuple, LazySteps)) and self._tuple() == tuple(other)

    def __hash__(self) -> int:
        return hash(self._tuple())

    def __add__(self, other: Iterable[Step]) -> tuple[Step, ...]:
        return self._tuple() + tuple(other)

    def __radd__(self, other: Iterable[Step]) -> tuple[Step, ...]:
        return tuple(other) + self._tuple()

    def __reduce__(self) -> tuple[type[tuple[Step, ...]], tuple[tuple[Step, ...]]]:
        return tuple, (self._tuple(),)

    def __repr__(self) -> str:
        return f"LazySteps({self._steps!r})" if self.built else "LazySteps(<not built>)"
