"""Checking many claims at once on the toolkit's one pool of worker processes (:mod:`symdecomp.parallel`).

The claims are independent checks of one scheme, so they are handed to the workers one by one (the costliest first,
by the time each took in the last run of this process's kind: :data:`COST_HINTS`), except the claims that share a
costly computation (:data:`GROUPS`), which go to one worker together; the results come back in the claims' order
(each checked under its own time budget in its worker, whose main thread holds the budget's timer). A result
computed in a worker travels as its words: its evidence, counterexample and correction rendered to text there
(sympy would evaluate an unevaluated ``Eq`` or ``>=`` again when it is unpickled, turning the words into ``True``),
its status and scope as computed, and without its derivation steps (:func:`~symdecomp.claims.registry.check_claim`
gives those, and ``derive`` prints them).
"""

from __future__ import annotations

import copy
from collections.abc import Iterable, Iterator

from symdecomp.claims.guards import DEFAULT_BUDGET
from symdecomp.claims.registry import CheckResult, Text, check_claim, get_claim

__all__ = ["check_claims", "COST_HINTS", "GROUPS", "work_items"]

#: Seconds of one core the costliest claims take on Catmull-Clark (measured one after the other in one process, as
#: ``claims --jobs 1`` runs them, on a loaded two-core machine, steps unbuilt: what counts is their order), handed out first
#: so that no worker is left with a long check at the end; the others (under 0.25 s) count as cheap (0.1). A group of
#: :data:`GROUPS` costs the sum.
COST_HINTS = {
    "C1 (Reif's test)": 1.25, "Curvature regime: Catmull-Clark": 0.95, "Shape: the valence decides": 0.65,
    "Section 3: Catmull-Clark support": 0.55, "Eq. 1": 0.6, "Eq. 50": 0.6, "Eq. 46": 0.55, "Spectrum (Eq. 34, Eq. 43)": 0.5,
    "Section 5.2: Catmull-Clark example": 0.3, "Remark 6.1": 0.45, "Eq. 51": 0.45, "Proposition 6.2": 0.45, "Eq. 48": 0.4,
    "1-ring suffices (after Eq. 51)": 0.4, "Section 3: symmetry": 0.4, "Section 5.3: smaller eigenvalues": 0.35, "Eq. 40": 0.35,
    "Section 3: boundary influence": 0.3, "Remark 5.2": 0.3, "S' (after Eq. 51)": 0.3, "Proposition 5.1": 0.3,
    "Proposition 2.1": 0.3, "Proposition 4.1": 0.25, "Curvature regime: Loop": 0.25, "Sector: the blocks are the spectrum": 0.25,
}


#: Claims that share costly cached computations (the characteristic map's ring layout at Catmull-Clark's and Loop's
#: valences, the Loop patch's box-spline terms, the K-ring blocks, of which the 3-ring blocks of Catmull-Clark are the
#: ring layout's too; the sine identity of the mirror blocks): each group is checked by one worker, one claim after the
#: other, so that each computation is made once instead of once per worker that meets it. Measured (Catmull-Clark, CPU
#: seconds, sympy's imports made first): the first group's seven claims one after the other in one process 3.45, each
#: in a fresh process 7.0 in all (C1 1.38, the Catmull-Clark regime 1.46, Shape 2.17, 1-ring suffices 0.74, ...), so
#: together they save about 3.5 s of one core.
GROUPS = (
    ("C1 (Reif's test)", "Curvature regime: Catmull-Clark", "Curvature regime: Loop", "Shape: the valence decides",
     "Curvature at the regular valence", "1-ring suffices (after Eq. 51)", "Larger neighbourhoods (after Eq. 51)"),
    ("Sector: sine decomposition", "Sector: the boundary tangent's continuation"),
)


def _check(labels: tuple[str, ...], *, scheme, budget) -> list[CheckResult]:
    return [_as_words(check_claim(label, scheme, budget=budget)) for label in labels]


def work_items(labels: list[str]) -> list[tuple[str, ...]]:
    """``labels`` as the pool's items: the claims of a group of :data:`GROUPS` together (at the first one's place),
    every other claim alone.

    >>> work_items(["Eq. 34", "Curvature regime: Loop", "Eq. 1", "C1 (Reif's test)"])
    [('Eq. 34',), ('Curvature regime: Loop', "C1 (Reif's test)"), ('Eq. 1',)]
    """
    group_of = {label: group for group in GROUPS for label in group}
    items: list[tuple[str, ...]] = []
    placed: set[str] = set()
    for label in labels:
        if label in placed:
            continue
        together = tuple(x for x in labels if x in group_of[label]) if label in group_of else (label,)
        items.append(together)
        placed.update(together)
    return items


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
    from symdecomp.schemes.stencils import StencilScheme

    labels = [get_claim(label).label for label in labels]
    scheme = catmull_clark() if scheme is None else scheme if isinstance(scheme, StencilScheme) else check_scheme(scheme)
    if jobs == 1 or isinstance(scheme, StencilScheme):  # a zoo scheme's rows are read from its model: no pool
        yield from (check_claim(label, scheme, budget=budget) for label in labels)
        return
    items = work_items(labels)
    done: dict[str, CheckResult] = {}
    position = 0
    for item, results in zip(items, ordered_map(_check, items, shared={"scheme": scheme, "budget": budget}, jobs=jobs,
                                                executor=executor, cost=lambda item: sum(COST_HINTS.get(x, 0.1) for x in item))):
        done.update(zip(item, results))
        while position < len(labels) and labels[position] in done:  # in the claims' order, as soon as each is known
            yield done.pop(labels[position])
            position += 1
