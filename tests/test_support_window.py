"""The window argument of Section 3 against the whole valence-n mesh, and the exact sign tests in n."""

import pytest
import sympy as sp

from symdecomp.algebra.valence_signs import integer_zeros, positive_from
from symdecomp.analysis.support import support_relation
from symdecomp.analysis.support_window import FIRST_VALENCE, predicted_region, window
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
