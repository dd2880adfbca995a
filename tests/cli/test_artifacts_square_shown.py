"""``artifacts`` shows ``lambda_1^2`` wherever ``lambda_1`` is known (sqrt(3) at n = 7 and 24 printed ``-``): exactly,
reduced to cosines where that fits the line, else as the certified value, which agrees with the exact square."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.analysis.zoo_roots import cosine_form
from symdecomp.cli import main


@pytest.mark.parametrize("n", [7, pytest.param(24, marks=pytest.mark.slow)])
def test_the_square_is_shown_and_is_lambda_1_squared(capsys, n) -> None:
    assert main(["artifacts", "--scheme", "sqrt3", "--n", str(n), "--json"]) == 0
    curvature = json.loads(capsys.readouterr().out)["rows"][0]["curvature"]
    lam, square = sp.sympify(curvature["lambda1_exact"]), sp.sympify(curvature["lambda1_squared"])
    field = CyclotomicField(4 * n)  # both are numbers of Q(zeta_4n) (sympy's radicals read back as cosines): exact there
    assert cyclotomic_value(cosine_form(lam, n), field=field) ** 2 == cyclotomic_value(cosine_form(square, n), field=field)
    value = curvature["lambda1_squared_value"]
    assert abs(sp.N(square, 40) - sp.Float(value, 40)) < sp.Float("1e-19")
    assert main(["artifacts", "--scheme", "sqrt3", "--n", str(n)]) == 0
    line = capsys.readouterr().out.splitlines()[1]
    shown = line.split("lambda_1^2 = ", 1)[1].split(", mu = ", 1)[0]
    assert shown in (curvature["lambda1_squared"], value)
