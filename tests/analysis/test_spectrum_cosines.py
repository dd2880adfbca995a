"""Exact eigenvalues of the zoo that are real numbers of a cyclotomic field are shown as rational multiples of cosines
(one basis of the real subfield, :func:`~symdecomp.analysis.zoo_roots.real_cosine_form`), not as sums of exponentials
or products of cosines: ``spectrum N --scheme sqrt3`` for N = 9..19, with and without ``--json``."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.analysis.zoo_roots import real_cosine_form
from symdecomp.cli import main


def _no_exponentials(exact: str) -> bool:
    return "exp(" not in exact and "I" not in exact and "**" not in exact and "sqrt(sqrt" not in exact


@pytest.mark.slow
@pytest.mark.parametrize("n", [9, 11, 16, 19])
def test_sqrt3_exact_values_are_cosines(capsys, n) -> None:
    assert main(["spectrum", str(n), "--scheme", "sqrt3", "--json"]) == 0
    values = json.loads(capsys.readouterr().out)["eigenvalues"]
    for e in values:
        assert e["exact"] is not None and _no_exponentials(e["exact"]), e["exact"]
        exact = sp.sympify(e["exact"])
        assert abs(sp.N(exact, 30) - sp.Float(e["value"], 30)) < sp.Float("1e-18")
    assert main(["spectrum", str(n), "--scheme", "sqrt3"]) == 0
    lines = capsys.readouterr().out.splitlines()[2:]
    assert [line.split("; ", 1)[1] for line in lines] == [e["exact"] for e in values]


def _element(field: CyclotomicField, N: int):
    """``zeta zeta^2 + (its conjugate) + (zeta^3 + zeta^-3)/7 - 2`` with ``zeta = e^(2 pi i/N)`` in ``field`` (real: conjugate pairs)."""
    step = field.N // N
    z = [field.zeta(step * k) for k in range(N)]
    return z[1] * z[2] + z[N - 1] * z[N - 2] + (z[3] + z[N - 3]) / 7 - 2, z


@pytest.mark.parametrize("N", [7, 9, 16, 19, 24])
def test_the_cosine_form_is_the_same_number(N) -> None:
    x, z = _element(CyclotomicField(N), N)
    form = real_cosine_form(x)
    assert form is not None and not form.has(sp.I)
    wide = CyclotomicField(4 * N)  # holds the cosines of multiples of pi/N (cyclotomic_value reads cos(r pi))
    assert cyclotomic_value(form, field=wide) == _element(wide, N)[0]
    assert real_cosine_form(z[1] + 2 * z[N - 1]) is None  # not real: not its own conjugate
