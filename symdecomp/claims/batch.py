"""Checking many claims at once on the toolkit's one pool of worker processes (:mod:`symdecomp.parallel`).

The claims are independent checks of one scheme, so they are handed to the workers one by one (the costliest
first, by the time each took in the last run of this process's kind: :data:`COST_HINTS`), and the results come
back in the claims' order (each checked under its own time budget in its worker, whose main thread holds the
budget's timer). A result computed in a worker travels as its words: its evidence, counterexample and correction
rendered to text there (sympy would evaluate an unevaluated ``Eq`` or ``>=`` again when it is unpickled, turning the
words into ``True``), its status and scope as computed, and without its derivation steps
(:func:`~symdecomp.claims.registry.check_claim` gives those, and ``derive`` prints them).
"""

from __future__ import annotations

import copy
from collections.abc import Iterable, Iterator

from symdecomp.claims.guards import DEFAULT_BUDGET
from symdecomp.claims.registry import CheckResult, Text, check_claim, get_claim

__all__ = ["check_claims", "COST_HINTS"]

#: Claims that take a second or more of one core on Catmull-Clark (measured), handed out first so that no
#: worker is left with a long check at the end; the others count as cheap.
COST_HINTS = {
    "Section 5.2: Catmull-Clark example": 1.8, "Remark 6.1": 1.6, "Eq. 51": 1.4,
    "Tuning and multiplicities (after Eq. 51)": 1.2, "C1 (Reif's test)": 1.1, "Eq. 41": 1.0, "Eq. 1": 0.8,
    "Remark 5.2": 0.8, "Shape: the valence decides": 0.5, "Eq. 50": 0.5, "Section 3: Catmull-Clark support": 0.5,
}


def _check(label: str, *, scheme, budget) -> CheckResult:
    return _as_words(check_claim(label, scheme, budget=budget))


def _as_words(result: CheckResult) -> CheckResult:
    """``result`` with its prose rendered to text and no steps (module docstring); status and scope kept as computed."""
    out = copy.copy(result)  # not dataclasses.replace: the scope was computed from the objects, not from their words
    for name in ("evidence", "counterexample", "correction"):
        value = getattr(result, name)
        if isinstance(value, Text):
            object.__setattr__(out, name, Text(str(value)))
    object.__setattr__(out, "steps", ())
    return out


def check_claims(labels: Iterable[str], scheme=None, *, budget: float | None = DEFAULT_BUDGET, jobs: int = 1,
                 executor="local") -> Iterator[CheckResult]:
    """:func:`~symdecomp.claims.registry.check_claim` for each label, in order, on at most ``jobs`` processes."""
    from symdecomp.parallel import ordered_map
    from symdecomp.schemes.scheme import catmull_clark, check_scheme

    labels = [get_claim(label).label for label in labels]
    scheme = catmull_clark() if scheme is None else check_scheme(scheme)
    if jobs == 1:
        yield from (check_claim(label, scheme, budget=budget) for label in labels)
        return
    yield from ordered_map(_check, labels, shared={"scheme": scheme, "budget": budget}, jobs=jobs, executor=executor,
                           cost=lambda label: COST_HINTS.get(label, 0.1))
