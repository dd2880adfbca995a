"""The closed-form spectrum against the full matrix's spectrum computed without block structure."""

import json

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp import catmull_clark, closed_form_spectrum, subdivision_matrix
from symdecomp.cli import main


def full_matrix_eigenvalues(n: int, dps: int = 60):
    """Eigenvalues of the exact (2n+1)x(2n+1) matrix, without its block structure.

    FLINT computes the characteristic polynomial of the full rational matrix exactly and
    factors it over Q (so multiplicities are exact exponents); mpmath finds the roots of each
    irreducible factor at ``dps`` digits, with an error estimate that must be below 10^-(dps-10).
    """
    S = subdivision_matrix(catmull_clark(), n)
    matrix = flint.fmpq_mat(S.rows, S.cols, [flint.fmpq(int(x.p), int(x.q)) for x in S])
    _, factors = matrix.charpoly().factor()
    values = []
    with mpmath.workdps(dps):
        for poly, exponent in factors:
            coeffs = [mpmath.mpf(int(c.p)) / int(c.q) for c in reversed(poly.coeffs())]
            roots, err = mpmath.polyroots(coeffs, maxsteps=200, extraprec=2 * dps, error=True) if len(coeffs) > 2 else ([-coeffs[1] / coeffs[0]], 0)
            assert err < mpmath.mpf(10) ** (-dps + 10)
            for r in roots:
                assert abs(mpmath.im(r)) < mpmath.mpf(10) ** (-dps + 10)
                values += [mpmath.re(r)] * exponent
        assert len(values) == 2 * n + 1
        return sorted(values, reverse=True)


@pytest.mark.parametrize("n", range(3, 17))
def test_cli_spectrum_agrees_with_full_matrix_to_25_digits(n, capsys):
    assert main(["spectrum", str(n), "--json", "--digits", "30"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["n"] == n and out["scheme"] == "catmull-clark"
    reference = full_matrix_eigenvalues(n)
    with mpmath.workdps(60):
        closed = []
        for e in out["eigenvalues"]:
            closed += [mpmath.mpf(e["value"])] * e["multiplicity"]  # parsed at 60 digits
            assert all(0 <= k < n for k in e["frequencies"])
        assert len(closed) == 2 * n + 1
        closed.sort(reverse=True)
        for c, r in zip(closed, reference):
            assert abs(c - r) < mpmath.mpf(10) ** -25, (n, c, r)
        # multiplicities: the reference, grouped at 25 digits, has the same multiplicities
        groups = []
        for r in reference:
            if groups and abs(groups[-1][0] - r) < mpmath.mpf(10) ** -25:
                groups[-1].append(r)
            else:
                groups.append([r])
        assert [len(g) for g in groups] == [e["multiplicity"] for e in out["eigenvalues"]]


def test_n4_has_one_quarter_three_times_exactly():
    spectrum = closed_form_spectrum(catmull_clark(), 4, digits=20)
    quarter = [e for e in spectrum.eigenvalues if abs(e.value - mpmath.mpf(1) / 4) < mpmath.mpf(10) ** -40]
    assert len(quarter) == 1 and quarter[0].multiplicity == 3 and quarter[0].frequencies == (0, 2)


def test_frequency_zero_block_closed_form_is_catmull_clarks():
    # derived from the rules; compare with the eigenvalues of the 3x3 matrix computed by sympy at n = 7
    from symdecomp import recursion_eigenvalues, recursion_matrix
    from symdecomp.symbols import n

    closed = sorted(sp.N(e.subs(n, 7), 40) for e in recursion_eigenvalues(catmull_clark()))
    direct = sorted(sp.N(e, 40) for e in recursion_matrix(catmull_clark(), 7).eigenvals(multiple=True))
    assert all(abs(a - b) < 1e-35 for a, b in zip(closed, direct))


def test_spectrum_of_tuned_scheme_needs_parameter_values():
    from symdecomp.symbols import alpha, beta

    tuned = catmull_clark(alpha, beta)
    with pytest.raises(ValueError, match="free parameters"):
        closed_form_spectrum(tuned, 5)
    standard = closed_form_spectrum(catmull_clark(), 5, digits=25)
    same = closed_form_spectrum(tuned, 5, digits=25, parameters={alpha: sp.Rational(3, 50), beta: sp.Rational(1, 100)})
    assert [e.text for e in same.eigenvalues] == [e.text for e in standard.eigenvalues]


def test_digits_are_significant_digits():
    spectrum = closed_form_spectrum(catmull_clark(), 5, digits=12)
    sub = spectrum.eigenvalues[1]
    assert len(sub.text.replace("0.", "", 1).lstrip("0")) <= 12
