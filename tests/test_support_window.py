"""The window argument of Section 3 against the whole valence-n mesh, and the exact sign tests in n."""

import pytest
import sympy as sp

from symdecomp.algebra.valence_signs import integer_zeros, positive_from
from symdecomp.analysis.support import Region, support_relation
from symdecomp.analysis.support_window import CENTRE, FIRST_VALENCE, NEAR, centre_region, far_region, region, window
from symdecomp.schemes.mesh import ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import catmull_clark

n = sp.Symbol("n")


def _predicted(w, p_label, q_label, valence):
    """The window's region of Q relative to the support of P on the valence-n mesh (P, Q labels of ring_mesh)."""
    if q_label == CENTRE:
        return Region.INSIDE if p_label == CENTRE else centre_region(w, (0, *p_label[1:]))[0]
    q_type = (0, *q_label[1:])
    if p_label == CENTRE:
        return region(w, CENTRE, q_type)
    t = (p_label[0] - q_label[0]) % valence
    t = t - valence if t > valence // 2 else t
    return region(w, (t, *p_label[1:]), q_type) if abs(t) <= NEAR else far_region(w, (0, *p_label[1:]), q_type)


@pytest.mark.parametrize("valence", [FIRST_VALENCE, 6, 9])
def test_window_predicts_every_pair_of_the_mesh(valence):
    w = window()
    labels = ring_mesh_labels(valence, 5)
    verts = [i for i, lab in enumerate(labels) if max(lab[1], lab[2]) <= 3]
    rel = support_relation(ring_mesh(valence, 5), catmull_clark(), verts)
    wrong = [(labels[p], labels[q]) for p in verts for q in verts if rel[p, q] is not _predicted(w, labels[p], labels[q], valence)]
    assert wrong == []


def test_integer_zeros_and_positivity():
    assert integer_zeros((n - 5) * (n - sp.Rational(7, 2)) * (n + 4) / (n - 9), n, 3) == (5, 9)
    assert integer_zeros(sp.Integer(0), n, 3) is None
    assert integer_zeros(25 * (n + 5) * (5 * n**2 - 30 * n + 49) / n, n, 3) == ()
    assert positive_from(n / (n + 5), n, 3)
    assert not positive_from(-6 * (n - 5000) / (n * (7493 * n + 37500)), n, 3)  # negative past n = 5000
