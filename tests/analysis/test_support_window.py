"""The window argument of Section 3 against the whole valence-n mesh, and the exact sign tests in n."""

import pytest
import sympy as sp

from symdecomp.algebra.valence_signs import integer_zeros, positive_from
from symdecomp.analysis.support import support_relation
from symdecomp.analysis.support_window import FIRST_VALENCE, predicted_region, window
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.mesh import ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import catmull_clark

n = sp.Symbol("n")


@pytest.mark.parametrize("valence", [FIRST_VALENCE, 6, 9])
def test_window_predicts_every_pair_of_the_mesh(valence):
    w = window()
    labels = ring_mesh_labels(valence, 5)
    verts = [i for i, lab in enumerate(labels) if max(lab[1], lab[2]) <= 3]
    rel = support_relation(ring_mesh(valence, 5), catmull_clark(), verts)
    wrong = [(labels[p], labels[q]) for p in verts for q in verts if rel[p, q] is not predicted_region(w, labels[p], labels[q], valence)]
    assert wrong == []


def test_integer_zeros_and_positivity():
    assert integer_zeros((n - 5) * (n - sp.Rational(7, 2)) * (n + 4) / (n - 9), n, 3) == (5, 9)
    assert integer_zeros(sp.Integer(0), n, 3) is None
    assert integer_zeros(25 * (n + 5) * (5 * n**2 - 30 * n + 49) / n, n, 3) == ()
    assert positive_from(n / (n + 5), n, 3)
    assert not positive_from(-6 * (n - 5000) / (n * (7493 * n + 37500)), n, 3)  # negative past n = 5000


@pytest.mark.parametrize("decide", [integer_zeros, positive_from])
def test_a_weight_that_is_not_rational_in_n_is_refused_with_the_package_error(decide):
    # cos(2 pi/n) (Loop's vertex rule, or a tuned Catmull-Clark) is not a rational function of n: the
    # every-n argument must not apply, rather than the check crashing
    with pytest.raises(InvalidInputError, match="not a rational function of n"):
        decide(1 + sp.cos(2 * sp.pi / n) / 100, n, 3)


def test_every_valence_hypotheses_fail_with_a_reason_for_a_cos_vertex_weight():
    from symdecomp.analysis.support_window import hypotheses_for_every_valence

    scheme = catmull_clark(sp.Rational(3, 2) / n**2 + sp.cos(2 * sp.pi / n) / (100 * n**2), sp.Rational(1, 4) / n**2)
    failures, _ = hypotheses_for_every_valence(scheme)
    assert any("not a rational function of n" in f for f in failures)
