"""Clusters of enclosures: which certified values may be one and the same number.

A ball (or a disc) encloses a number; two enclosures that are certainly apart hold different
numbers, two that may overlap cannot be told apart at this precision. :func:`overlap_groups`
returns the connected components of the "may overlap" graph, so that a cluster is what the
precision cannot split (transitively: a chain of overlapping balls is one cluster).

>>> import flint
>>> balls = [flint.arb(1, 0.1), flint.arb(1.15, 0.1), flint.arb(3, 0.1)]
>>> overlap_groups(balls, lambda a, b: a.overlaps(b))
[[0, 1], [2]]
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

__all__ = ["overlap_groups"]


def overlap_groups(items: Sequence, may_overlap: Callable, *, key: Callable | None = None,
                   beyond: Callable | None = None) -> list[list[int]]:
    """The indices of ``items`` grouped into the connected components of ``may_overlap(a, b)``.

    Groups list their indices in increasing order, and the groups come in the order of their
    smallest index. ``key`` and ``beyond`` prune the pairs: with the items sorted by ``key``,
    ``beyond(a, b)`` must be true only when ``b`` and every item after it cannot overlap ``a``
    (balls sorted by the lower end of the real part: ``b`` starts above ``a``'s upper end).
    """
    order = sorted(range(len(items)), key=lambda i: key(items[i])) if key else list(range(len(items)))
    parent = list(range(len(items)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for pos, i in enumerate(order):
        for j in order[pos + 1:]:
            if beyond is not None and beyond(items[i], items[j]):
                break
            if may_overlap(items[i], items[j]):
                parent[find(i)] = find(j)
    groups: dict[int, list[int]] = {}
    for i in range(len(items)):
        groups.setdefault(find(i), []).append(i)
    return list(groups.values())
