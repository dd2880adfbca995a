"""The leading eigenvalues of a sharp vertex (O(log k)) against every eigenvalue of its blocks (O(k)).

:func:`structural_values` reads every block and joins equal values exactly; :func:`leading_values` reads the blocks
``j <= HEAD`` the same way and bounds the others in one interval computation. The head must be the structural
route's values of those blocks, and the tail bound must lie above every other value, for each scheme and sector kind.
"""

from __future__ import annotations

import flint
import pytest

import symdecomp as sd
from symdecomp.analysis.block_values import checked_polynomials, structural_values
from symdecomp.analysis.leading_values import HEAD, leading_values, tail_bound
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme

SCHEMES = {"cc": sd.catmull_clark(), "loop": sd.loop(), "cc-blz": load_scheme("catmull-clark-blz")}


def _from_head(value) -> bool:
    return all(n.block != "sine" or n.j <= HEAD for n in value.blocks)


def _tail_count(scheme, k: int) -> int:
    """Eigenvalues of the sine blocks ``j = HEAD+1..k-1`` (2 x 2 on quads, 1 x 1 on triangles)."""
    return max(0, k - 1 - HEAD) * (2 if scheme.face_rule is not None else 1)


@pytest.mark.parametrize("name", SCHEMES)
@pytest.mark.parametrize("kind", ["boundary", "corner"])
@pytest.mark.parametrize("k", [2, 5, 12, 40])
def test_head_is_the_structural_values_and_the_tail_bounds_the_rest(name, kind, k):
    scheme = SCHEMES[name]
    vertex = getattr(sd.SharpVertex, kind)(k, scheme.lattice)
    lead = leading_values(scheme, vertex)
    every, size = structural_values(scheme, vertex)
    # each head value is a structural value (which may also be a tail block's: then its multiplicity is larger)
    for a in lead.values:
        (b,) = [b for b in every if b.ball.overlaps(a.ball)]
        assert a.multiplicity <= b.multiplicity
    assert sum(a.multiplicity for a in lead.values) + _tail_count(scheme, k) == size
    rest = [v for v in every if not _from_head(v)]
    assert (lead.tail is None) == (not rest) == (k - 1 <= HEAD)
    assert not any(abs(v.ball) > lead.tail for v in rest)  # no value certainly above the bound


@pytest.mark.parametrize("name", SCHEMES)
def test_the_tail_is_below_lambda_2_at_many_faces(name):
    # the subdominant values come from j = 1 (and the crease block): at k = 2000 the next blocks differ by O(1/k^2),
    # so the bisection must resolve c to about 1e-6 near 1
    scheme = SCHEMES[name]
    lead = leading_values(scheme, sd.SharpVertex.boundary(2000, scheme.lattice))
    moduli = sorted((abs(v.ball) for v in lead.values for _ in range(v.multiplicity)), key=lambda b: -b.mid())
    assert lead.tail < moduli[2]


def test_the_tail_bound_is_refined_only_as_far_as_needed():
    # a target above every value: one piece suffices; the bound is then the interval's, above the true maximum
    polys = checked_polynomials(SCHEMES["cc"])
    coarse = tail_bound(polys, 50, HEAD, flint.arb(2))
    fine = tail_bound(polys, 50, HEAD, flint.arb("0.6"))
    truth = max((abs(v.ball) for v in structural_values(SCHEMES["cc"], sd.SharpVertex.boundary(50, "quad"))[0]
                 if not _from_head(v)), key=lambda b: b.mid())
    # the bound is attained at j = HEAD + 1 (the interval's end): it meets the largest tail value, never falls below it
    assert not truth > fine and fine - truth < 1e-12 and fine < coarse < 2


def test_darts_and_angles_are_refused_as_by_the_structural_route():
    with pytest.raises(NotApplicableError, match="dart"):
        leading_values(SCHEMES["cc"], sd.SharpVertex.dart(5, "quad"))
