"""The spectrum of Midedge on the functions its four-direction patch makes, against a matrix built here.

The matrix, the local mesh and the orbit labels are the Doo-Sabin tests' (:mod:`tests.verify.test_c1_dual`), with
Midedge's corner rule ``(1/2, 1/4, 0, 1/4)`` in the quads and ``a, (1 - a)/2, (1 - a)/2`` in the centre triangle
(Midedge: ``a = 1/2``), exact. Independent checks: sympy's ranks of the powers of ``S - lambda`` for the Jordan
structure, and the alternating sign across every edge for the vector that vanishes at the regular valence.
"""

from fractions import Fraction as F

import pytest
import sympy as sp

from symdecomp.schemes.four_direction import four_direction_patch
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.c1_four_direction_quotient import (
    quotient_test,
    ring_evaluation,
    rotation_matrix,
    vanishing_space,
)
from symdecomp.verify.c1_zoo import c1_zoo
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import engine_neighbourhood
from tests.verify.test_c1_dual import CLASSES, doo_sabin_matrix, local_mesh

MIDEDGE = (F(1, 2), F(1, 4), F(0), F(1, 4))


@pytest.fixture(scope="module")
def patch():
    return four_direction_patch(MIDEDGE)


def exact_matrix(n, own=F(1, 2)):
    """The one-step matrix (sympy, exact) and its order; the centre n-gon's own corner weighs ``own``."""
    centre = [F(0)] * n
    centre[0] += own
    centre[1] += (1 - own) / 2
    centre[n - 1] += (1 - own) / 2
    rows = doo_sabin_matrix(n, centre, list(MIDEDGE))
    order = [(s, *c) for s in range(n) for c in CLASSES]
    index = {v: i for i, v in enumerate(order)}
    S = sp.zeros(len(order), len(order))
    for new, row in rows.items():
        for old, w in row.items():
            S[index[new], index[old]] += sp.Rational(w.numerator, w.denominator)
    return S, order


def _flint(S):
    import flint

    return flint.fmpq_mat(S.rows, S.cols, [flint.fmpq(int(x.p), int(x.q)) for x in S])


def test_at_a_triangle_no_vector_gives_the_zero_function(patch):
    S, order = exact_matrix(3)
    E = ring_evaluation(local_mesh(3), order, patch)
    assert E.rank() == len(order) == 27 and vanishing_space(E, _flint(S)) == []


def test_at_the_regular_valence_the_alternating_net_is_what_vanishes(patch):
    S, order = exact_matrix(4)
    mesh = local_mesh(4)
    (v,) = vanishing_space(ring_evaluation(mesh, order, patch), _flint(S))
    value = dict(zip(order, v))
    assert all(value[f[k]] + value[f[(k + 1) % len(f)]] == 0 for f in mesh.faces[1:] for k in range(4))  # each quad edge
    x = sp.Matrix([sp.Rational(int(c.p), int(c.q)) for c in v])
    assert x != sp.zeros(len(order), 1) and sp.Matrix.hstack(S * x, x).rank() == 1  # an eigenvector of S


def test_the_jordan_structure_at_a_triangle_agrees_with_sympy_s_ranks(patch):
    S, order = exact_matrix(3)
    found = quotient_test(local_mesh(3), order, S, patch, 3)
    spectrum = found.spectrum
    assert spectrum.subdominant == F(1, 4) and not spectrum.vanishing
    A = S - sp.eye(len(order)) / 4
    kernels = [len(order) - (A ** p).rank() for p in (1, 2, 3)]
    assert kernels == [6, 8, 8]  # two Jordan blocks of size 2 at 1/4, four of size 1
    by_class = {c.frequency_class: c.dims for c in spectrum.jordan}
    assert [sum(d[min(p, len(d)) - 1] for d in by_class.values()) for p in (1, 2, 3)] == kernels
    assert set(by_class) == {1, 3} and by_class[3][-1] > by_class[3][0] and len(by_class[1]) == 1  # the blocks: frequencies 1, 2
    assert not found.conditions_hold and not found.refuted and found.frequency == 1
    assert found.ring is not None and found.ring.status == "regular" and found.ring.winding_number == found.ring.jacobian_sign


@pytest.mark.parametrize("own", [F(3, 4), F(2, 5)])
def test_a_mutated_triangle_changes_the_outcome(own, patch):
    """The triangle's circulant has ``own + (1 - own) cos(2 pi/3)`` at frequencies 1, 2: above 1/4 the conditions hold on
    the quotient; below, 1/4 is left at frequencies 0, 1, 2 with no Jordan block, and they fail."""
    S, order = exact_matrix(3, own)
    found = quotient_test(local_mesh(3), order, S, patch, 3)
    pair = own + (1 - own) * sp.cos(2 * sp.pi / 3)
    if pair > sp.Rational(1, 4):
        assert found.conditions_hold and sp.Rational(found.spectrum.subdominant) - pair == 0
        assert found.ring.status == "regular" and found.ring.winding_number == found.ring.jacobian_sign == 1
    else:
        assert found.refuted and found.spectrum.subdominant == F(1, 4)
        assert {c.frequency_class: c.dims for c in found.spectrum.jordan} == {1: (2,), 3: (4,)}


def test_the_engine_s_matrix_gives_the_same_quotient(patch):
    nb = engine_neighbourhood(load_zoo("midedge"), 3)
    ours = quotient_test(local_mesh(3), *exact_matrix(3)[::-1], patch, 3)
    engine = quotient_test(nb.mesh, nb.order, nb.matrix, patch, 3)
    assert engine.spectrum.factors == ours.spectrum.factors and engine.spectrum.jordan == ours.spectrum.jordan
    r = c1_zoo(load_zoo("midedge"), 3, neighbourhood=engine_neighbourhood)
    assert r.verdict is C1Verdict.C1 and "Jordan blocks: 1 of size 2, 1 of size 1" in r.reason
    assert "no vector gives the zero function near the centre" in r.reason and r.winding_number == r.jacobian_sign == 1


def test_the_rotation_moves_each_sector_to_the_next():
    order = [(s, *c) for s in range(3) for c in CLASSES]
    R = rotation_matrix(local_mesh(3).labels, order, 3)
    assert R ** 3 == R ** 0 and R != R ** 0
