"""The patch matrices past the reference valence: the reference's rows beyond the 1-ring, moved on the lattice,
equal the exact refinement at the valence itself (Catmull-Clark, Loop, Warren's Loop, an edge rule in n, BLZ)."""

from __future__ import annotations

import pathlib

import pytest

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes import patch
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop, loop_warren
from symdecomp.schemes.scheme import catmull_clark

CORPUS = pathlib.Path(__file__).resolve().parents[1] / "corpus"
SCHEMES = {
    "catmull-clark": catmull_clark, "loop": loop, "loop-warren": loop_warren,
    "n-dependent-edge": lambda: load_scheme(CORPUS / "n-dependent-edge.toml"),
    "own-regular-vertex": lambda: load_scheme(CORPUS / "own-regular-vertex.toml"),
    "catmull-clark-blz": lambda: load_scheme("catmull-clark-blz"),
    "loop-blz": lambda: load_scheme("loop-blz"),
}


def _quad(scheme) -> bool:
    return patch.patch_matrices(scheme, 3).size == 14  # 2n + 8 control points: the quad patch


def _refined(scheme, n: int):
    """The patch matrices read off the refinement at ``n`` (the path up to the reference valence)."""
    return patch._quad_by_refinement(scheme, n) if _quad(scheme) else patch._triangle_by_refinement(scheme, n)


def _arguments(scheme):
    if _quad(scheme):
        return patch._quad_subpatch_rows, True
    return (lambda m: patch._triangle_subpatch_rows(m, patch.triangle_patch_rows(m))), False


@pytest.mark.parametrize("name", sorted(SCHEMES))
@pytest.mark.parametrize("n", [patch.REFERENCE_VALENCE + 1, 10, 13, 24])
def test_transplanted_rows_equal_the_refinement(name, n):
    scheme = SCHEMES[name]()
    fast = patch._transplanted(scheme, n, scheme.lattice, *_arguments(scheme))
    assert fast is not None
    whole = _refined(scheme, n)
    assert fast.sparse == whole.sparse and fast.subpatches == whole.subpatches
    assert (fast.size, fast.ring_size) == (whole.size, whole.ring_size)
    assert (fast.extended is None and whole.extended is None) or fast.extended == whole.extended


def test_reference_valence_itself_is_refined():
    assert patch._transplanted(catmull_clark(), patch.REFERENCE_VALENCE, catmull_clark().lattice, *_arguments(catmull_clark())) is None


def test_a_bad_scheme_is_named_at_its_own_valence():
    scheme = load_scheme(CORPUS / "free-vertex.toml")
    with pytest.raises(InvalidSchemeError, match=r"-20\*alpha - 20\*beta \+ 1 at valence 20"):
        patch.quad_patch_matrices(scheme, 20)


def test_both_ways_to_the_one_ring_rows_are_compared():
    """The schemes above take the 1-ring's rows both ways: turned from the reference (rules that read no valence on
    the 1-ring's edges) and refined at n (an edge rule in n)."""
    fixed = {name: patch._ring_rules_fixed(make()) for name, make in SCHEMES.items()}
    assert fixed["catmull-clark"] and fixed["loop"] and not fixed["n-dependent-edge"]


@pytest.mark.parametrize(("name", "read_once"), [
    ("catmull-clark", True), ("loop", True), ("n-dependent-edge", True),
    ("loop-warren", False),  # a Piecewise in n: substituted by sympy at each valence, as before
])
def test_centre_weights_are_read_once_and_equal_sympy_s_substitution(name, read_once):
    """The vertex rule's weights are read by sympy once (``CyclotomicFunction``), not substituted at every valence,
    where they are rational functions of n and of cosines of rational multiples of pi; either way they equal
    the substitution exactly at every valence."""
    import sympy as sp

    from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
    from symdecomp.symbols import n as N

    rule = SCHEMES[name]().vertex_rule
    for w in (rule.center, rule.each_a):
        expr = sp.sympify(w, strict=True)
        assert (patch._weight_function(expr) is not None) == read_once
        for n in (3, 4, 7, 12, 31):
            exact = patch._exact_weight(expr, n)
            assert (cyclotomic_value(expr, {N: n}, field=CyclotomicField(2 * n)) - exact).poly == 0
