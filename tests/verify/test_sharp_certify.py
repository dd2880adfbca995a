"""The certificate of the mirror decomposition against the refined matrix (symdecomp.verify.certify)."""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis import mirror
from symdecomp.errors import NotApplicableError
from symdecomp.verify.certify import describe_vertex

CC, LOOP = sd.catmull_clark(), sd.loop()


@pytest.mark.parametrize("scheme, vertex", [
    (CC, sd.SharpVertex.boundary(7, sd.QUAD)), (LOOP, sd.SharpVertex.boundary(9, sd.TRIANGLE)),
    (CC, sd.SharpVertex.corner(4, sd.QUAD)), (LOOP, sd.SharpVertex.crease(4, 5, sd.TRIANGLE)),
    (CC, sd.SharpVertex.dart(6, sd.QUAD)),
])
def test_the_decomposition_is_proved_with_exact_multiplicities(scheme, vertex):
    c = sd.certify_sharp(scheme, vertex)
    assert c.ok and c.multiplicities_certified and c.route == "charpoly"
    chi = sd.exact_sharp_matrix(scheme, vertex).charpoly()
    assert sum(c.multiplicities) == chi.degree() and c.distinct == len(c.multiplicities) == len(c.values)
    assert c.as_json()["vertex"] == describe_vertex(vertex)


def test_a_crease_block_that_is_not_the_matrix_is_refuted(monkeypatch):
    real = mirror.sector_decomposition
    vertex = sd.SharpVertex.boundary(4, sd.QUAD)

    def wrong(scheme, vertex, rules=None):
        d = real(scheme, vertex, rules)
        C = sp.Matrix(d.crease)
        C[0, 0], C[0, 1] = C[0, 0] - sp.Rational(1, 8), C[0, 1] + sp.Rational(1, 8)
        return dataclasses.replace(d, crease=C)

    monkeypatch.setattr(mirror, "sector_decomposition", wrong)
    c = sd.certify_sharp(CC, vertex)
    assert c.status.value == "disagree" and "crease rows" in c.message and not c.ok


def test_semi_sharp_edges_are_out_of_the_decompositions_scope():
    from fractions import Fraction

    with pytest.raises(NotApplicableError, match="semi-sharp"):
        sd.certify_sharp(CC, sd.SharpVertex.crease(3, 3, sd.QUAD, sharpness=Fraction(3, 2)))


def test_describe_vertex():
    from fractions import Fraction

    assert [describe_vertex(v) for v in (sd.SharpVertex.boundary(5, sd.QUAD), sd.SharpVertex.corner(2, sd.QUAD),
                                         sd.SharpVertex.crease(2, 3, sd.QUAD, sharpness=Fraction(1, 2)),
                                         sd.SharpVertex.dart(5, sd.TRIANGLE))] == \
        ["boundary k=5", "corner k=2", "crease 2+3, sharpness 1/2", "dart n=5"]
