"""``artifacts`` shows ``lambda_1^2`` wherever ``lambda_1`` is known: where the exact square is too long for a line
(sqrt(3) at n = 7, a sum of products of cosines), as the certified value, which agrees with the exact square."""

from __future__ import annotations

import json

import sympy as sp

from symdecomp.cli import main


def test_the_square_is_shown_and_agrees_with_the_exact_one(capsys) -> None:
    assert main(["artifacts", "--scheme", "sqrt3", "--n", "7", "--json"]) == 0
    curvature = json.loads(capsys.readouterr().out)["rows"][0]["curvature"]
    exact_square = sp.sympify(curvature["lambda1_squared"])
    assert sp.expand(sp.sympify(curvature["lambda1_exact"]) ** 2 - exact_square) == 0
    shown = curvature["lambda1_squared_value"]
    assert abs(sp.N(exact_square, 40) - sp.Float(shown, 40)) < sp.Float("1e-19")
    assert main(["artifacts", "--scheme", "sqrt3", "--n", "7"]) == 0
    line = capsys.readouterr().out.splitlines()[1]
    assert f"lambda_1^2 = {shown}," in line and "lambda_1^2 = -" not in line
