"""Exact eigenvalues of sharp vertices matched to their balls by sympy's isolating intervals, and the mask's size bound."""

from __future__ import annotations

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis import triangular_masks as masks_module
from symdecomp.analysis.triangular_eigen import _factor_roots
from symdecomp.cli import main
from symdecomp.errors import NotApplicableError


@pytest.mark.slow  # 5-9 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_each_root_gets_the_ball_its_thirty_digit_value_lies_in():
    S = sd.exact_sharp_matrix(sd.catmull_clark(), sd.SharpVertex.dart(12, sd.QUAD))
    _, factors = S.charpoly().factor()
    checked = 0
    for f, _ in factors:
        f = f / f.leading_coefficient()
        roots = _factor_roots(f, 256)
        assert sorted(i for i, _, _ in roots) == list(range(f.degree()))
        for _, exact, ball in roots:
            z = complex(sp.N(exact, 30))
            assert abs(complex(float(ball.real.mid()), float(ball.imag.mid())) - z) < 1e-25 * max(1.0, abs(z))
            checked += 1
        assert len({(float(b.real.mid()), float(b.imag.mid())) for _, _, b in roots}) == f.degree()  # one ball per root
    assert checked >= 12  # the dart's factors of degree > 2 are matched by their intervals


def test_a_mask_beyond_the_exact_system_bound_is_refused_before_the_work(monkeypatch, capsys):
    monkeypatch.setattr(masks_module, "MAX_MASK_SYSTEM", 20)
    with pytest.raises(NotApplicableError, match=r"rational system of \d+ x \d+ = \d+ unknowns, more than the 20 solved"):
        sd.sharp_masks(sd.catmull_clark(), sd.SharpVertex.dart(8, sd.QUAD))
    assert main(["masks", "8", "--dart"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "more than the 20 solved exactly here" in err[0]
