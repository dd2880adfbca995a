"""``symdecomp spectrum K --boundary`` (and --corner, --crease K2, --dart, --sharpness S): the exact spectrum of a
sharp vertex, each eigenvalue named by its block, checked against the full matrix built by refinement."""

from __future__ import annotations

import json

import flint
import mpmath
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.cli import main


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def _vertex(kind, k, lattice):
    if kind == "boundary":
        return sd.SharpVertex.boundary(k, lattice)
    if kind == "corner":
        return sd.SharpVertex.corner(k, lattice)
    if kind == "dart":
        return sd.SharpVertex.dart(k, lattice)
    return sd.SharpVertex.crease(k, 3, lattice)


CASES = [(scheme, kind, k) for scheme in ("catmull-clark", "loop") for kind, k in
         [("boundary", 1), ("boundary", 4), ("boundary", 7), ("corner", 3), ("crease", 2), ("dart", 4)]]


@pytest.mark.slow
@pytest.mark.parametrize("scheme, kind, k", CASES)
def test_the_printed_eigenvalues_multiply_to_the_determinant_of_the_refined_matrix(capsys, scheme, kind, k):
    argv = ["spectrum", str(k), "--scheme", scheme, "--json", "--digits", "30"] + (["--crease", "3"] if kind == "crease" else [f"--{kind}"])
    out = _json(capsys, argv)
    (level,) = out["levels"]
    scheme_obj = sd.catmull_clark() if scheme == "catmull-clark" else sd.loop()
    S = sd.exact_sharp_matrix(scheme_obj, _vertex(kind, k, scheme_obj.lattice))
    assert sum(e["multiplicity"] for e in level["eigenvalues"]) == S.nrows() == level["size"]
    with mpmath.workdps(40):
        product = mpmath.fprod(mpmath.mpmathify(e["value"]) ** e["multiplicity"] for e in level["eigenvalues"])
        trace = mpmath.fsum(mpmath.mpmathify(e["value"]) * e["multiplicity"] for e in level["eigenvalues"])
        det = S.det()
        assert abs(product - mpmath.mpf(int(det.p)) / int(det.q)) < mpmath.mpf(10) ** -25
        tr = sum((S[i, i] for i in range(S.nrows())), flint.fmpq(0))
        assert abs(trace - mpmath.mpf(int(tr.p)) / int(tr.q)) < mpmath.mpf(10) ** -25
    assert level["eigenvalues"][0]["value"] == "1.0" and level["eigenvalues"][0]["exact"] == "1"


def test_the_blocks_of_a_catmull_clark_boundary_vertex_are_named(capsys):
    assert main(["spectrum", "5", "--boundary"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("catmull-clark, boundary k=5 (quad mesh): 12 eigenvalues, 11 distinct; blocks of the mirror decomposition")
    assert "crease; 1/2" in out
    for j in range(1, 5):
        assert f"sine j={j} (theta = {'' if j == 1 else j}{'*' if j > 1 else ''}pi/5)" in out
    assert "crease, last mode j=5 (b_i = (-1)^i); 1/4" in out


def test_the_first_sine_eigenvalue_is_its_block_closed_form():
    spectrum = sd.sharp_spectrum(sd.loop(), sd.SharpVertex.boundary(5, sd.TRIANGLE), digits=30)
    first = next(e for e in spectrum.entries if "sine j=1" in e.blocks[0])
    # on triangles the sine block M(theta) is 1 x 1: its entry at theta = pi/5 is the eigenvalue named "sine j=1"
    from symdecomp.analysis.mirror import THETA, sine_block

    value = sine_block(sd.loop())[0, 0].subs(THETA, sp.pi / 5)
    with mpmath.workdps(30):
        assert abs(mpmath.mpf(first.text) - mpmath.mpf(str(value.evalf(40)))) < mpmath.mpf(10) ** -25


def test_semi_sharp_levels_end_at_the_interior_spectrum(capsys):
    out = _json(capsys, ["spectrum", "3", "--crease", "3", "--sharpness", "3/2", "--json"])
    levels = out["levels"]
    assert [lv["sharpness"] for lv in levels] == ["3/2", "1/2", "0"]
    assert [lv["decomposed"] for lv in levels] == [False, False, False]
    interior = sd.closed_form_spectrum(sd.catmull_clark(), 6, digits=20)
    values = sorted(float(e["value"]) for e in levels[-1]["eigenvalues"] for _ in range(e["multiplicity"]))
    expected = sorted(float(mpmath.mpmathify(e.text).real) for e in interior.eigenvalues for _ in range(e.multiplicity))
    assert len(values) == len(expected) and max(abs(a - b) for a, b in zip(values, expected)) < 1e-15


def test_an_infinitely_sharp_crease_has_one_level(capsys):
    out = _json(capsys, ["spectrum", "2", "--crease", "2", "--sharpness", "inf", "--json"])
    assert len(out["levels"]) == 1 and out["levels"][0]["sharpness"] == "inf" and out["vertex"] == "crease 2+2"


@pytest.mark.parametrize("argv, words", [
    (["spectrum", "2"], "argument N: expected a valence"),
    (["spectrum", "0", "--boundary"], "argument N"),
    (["spectrum", "65", "--dart"], "more than 64 faces (the matrices are dense and exact)"),
    (["spectrum", "10001", "--boundary"], "argument N"),
    (["spectrum", "2000", "--crease", "9000"], "more than 10000 faces (the blocks are O(k))"),
    (["spectrum", "5", "--boundary", "--corner"], "--boundary and --corner cannot be used together"),
    (["spectrum", "5", "--sharpness", "2"], "--sharpness: the sharpness of a crease"),
    (["spectrum", "5", "--boundary", "--sharpness", "2"], "--sharpness: the sharpness of a crease"),
    (["spectrum", "5", "--corner", "--sharpness", "2"], "--sharpness"),
    (["spectrum", "5", "--crease", "2", "--sharpness", "-1"], "--sharpness"),
    (["spectrum", "5", "--crease", "2", "--sharpness", "abc"], "--sharpness"),
    (["spectrum", "5", "--crease", "0"], "--crease"),
    (["spectrum", "5", "--boundary", "--rings", "2"], "--rings: not available"),
    (["spectrum", "5", "--boundary", "--exact"], "--exact: not available"),
    (["spectrum", "2", "--dart"], "--dart: a dart is an interior vertex of valence K >= 3"),
    (["spectrum", "5", "--boundary", "--boundary"], "given more than once"),
])
def test_bad_combinations_are_one_line_and_exit_2(capsys, argv, words):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1 and "Traceback" not in err


def test_the_sharpness_is_exact(capsys):
    out = _json(capsys, ["spectrum", "3", "--dart", "--sharpness", "1/2", "--json"])
    assert out["levels"][0]["sharpness"] == "1/2" and out["levels"][-1]["sharpness"] == "0"
    assert main(["spectrum", "3", "--dart", "--sharpness", "0.5"]) == 2
    assert "give an exact rational" in capsys.readouterr().err
