"""One eigenvalue type: the closed-form spectrum, the K-ring's factored spectrum and the numeric match speak of one thing."""

import pytest

from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.spectrum import closed_form_spectrum, ring_spectrum
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.numeric import numeric_check


@pytest.mark.parametrize("n", [3, 5, 6])
def test_the_closed_forms_and_the_factored_spectrum_give_the_same_eigenvalues(n):
    closed = closed_form_spectrum(catmull_clark(), n, digits=12).eigenvalues
    factored = ring_spectrum(catmull_clark(), n, 1, digits=12).eigenvalues
    assert all(type(e) is Eigenvalue for e in closed + factored)
    assert sum(e.multiplicity for e in closed) == 2 * n + 1
    assert [(e.multiplicity, e.frequencies) for e in closed] == [(e.multiplicity, e.frequencies) for e in factored]
    assert all(abs(complex(e.value) - complex(f.value.mid())) < 1e-12 for e, f in zip(closed, factored))
    assert all(e.jordan is not None and sum(e.jordan) == e.multiplicity for e in factored)  # known on the factored route


def test_a_numeric_match_holds_the_closed_form_eigenvalue_with_where_it_comes_from():
    r = numeric_check(catmull_clark(), 4, dps=20)
    quarter = next(m.eigenvalue for m in r.matches if m.eigenvalue.text == "0.25")
    assert type(quarter) is Eigenvalue and quarter.multiplicity == len(quarter.labels) == 3
    assert quarter.frequencies == (0, 2)
    # once from the Eq. 43 block, twice from M_2 = I/4 (both of its closed forms)
    assert sorted((lab.frequency, lab.label.split(" root")[0]) for lab in quarter.labels) == [
        (0, "Eq. 43"), (2, "Eq. 34 dominant"), (2, "Eq. 34 subdominant")]
    assert quarter.describe().endswith("; k = 0, 2; multiplicity 3)")


def test_the_json_of_an_eigenvalue_keeps_its_shape():
    e = closed_form_spectrum(catmull_clark(), 4, digits=10).eigenvalues[1]
    assert e.as_json() == {"value": "0.5", "multiplicity": 2, "frequencies": [1, 3]}
    f = ring_spectrum(catmull_clark(), 4, 1, digits=10).eigenvalues[1]
    assert f.as_json(exact=True) == {"value": "0.5", "multiplicity": 2, "frequencies": [1, 3], "exact": "1/2", "jordan_blocks": [1, 1]}
