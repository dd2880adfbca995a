"""``spectrum``, ``masks`` and ``check --certify`` of sharp vertices under the shipped BLZ scheme files."""

from __future__ import annotations

import json

import mpmath
import sympy as sp

from symdecomp.cli import main
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix


def test_spectrum_prints_the_field_and_the_double_half(capsys):
    assert main(["spectrum", "5", "--boundary", "--scheme", "catmull-clark-blz", "--json", "--digits", "40"]) == 0
    (level,) = json.loads(capsys.readouterr().out)["levels"]
    assert level["field"] == "Q(cos(pi/5))" and level["decomposed"]
    half = [e for e in level["eigenvalues"] if e["exact"] == "1/2"]
    assert half[0]["multiplicity"] == 2 and half[0]["blocks"][0] == "crease"
    # the printed values: their product (with multiplicity) is the determinant of the refined matrix
    S = sharp_subdivision_matrix(load_scheme("catmull-clark-blz"), SharpVertex.boundary(5, load_scheme("catmull-clark-blz").lattice))
    with mpmath.workdps(60):
        det = mpmath.det(mpmath.matrix([[mpmath.mpf(str(sp.N(e, 70))) for e in row] for row in S.tolist()]))
        product = mpmath.fprod(mpmath.mpf(e["value"]) ** e["multiplicity"] for e in level["eigenvalues"])
        assert abs(product - det) < mpmath.mpf(10) ** -30 * abs(det)


def test_masks_exit_0_and_explain_the_shared_eigenvalue(capsys):
    assert main(["masks", "5", "--boundary", "--scheme", "loop-blz", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["tangent_plane"] and "share the eigenvalue 0.5" in out["reason"]
    cross = out["tangents"][1]
    assert cross["exact"]["a_0"] == cross["exact"]["a_5"] and cross["eigenvalue"] == "0.5"


def test_check_certifies_the_range(capsys):
    assert main(["check", "--k", "1:6", "--boundary", "--certify", "--scheme", "loop-blz", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["summary"]["ok"] and out["summary"]["agree"] == 6


def test_two_fields_are_refused_in_one_line(capsys):
    assert main(["masks", "5", "--crease", "4", "--scheme", "catmull-clark-blz"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Q(cos(pi/4), cos(pi/5))" in err and "Traceback" not in err


def test_the_spectrum_of_two_fields_comes_from_the_blocks(capsys):
    """The matrix's entries lie in two fields (out of the dense route's reach); the blocks each lie in one."""
    assert main(["spectrum", "5", "--crease", "4", "--scheme", "catmull-clark-blz"]) == 0
    out = capsys.readouterr().out
    assert "from the blocks (O(k))" in out and "over Q(cos(pi/4), cos(pi/5))" in out
