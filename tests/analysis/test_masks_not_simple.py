"""Where the masks' eigenvalue is not simple, ``masks`` says so from the computed spectrum: at n = 3 the mid-edge
scheme's 1/4 is a multiple eigenvalue with Jordan blocks (read here from the explicit matrix's ranks), so there is no
single tangent mask; one line, exit 2, with and without ``--json``."""

from __future__ import annotations

import pytest
import sympy as sp

from symdecomp.analysis.zoo_masks import zoo_masks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.cli import main
from symdecomp.errors import SymdecompError
from symdecomp.schemes.stencil_files import load_zoo

MIDEDGE = load_zoo("midedge")


def _jordan_text(S: sp.Matrix, lam: sp.Expr) -> tuple[int, str]:
    """``(algebraic multiplicity, block sizes joined by '+', largest first)`` of ``lam``, from the ranks of
    ``(S - lam I)^k`` (the number of blocks of size >= k is ``rank^(k-1) - rank^k``)."""
    x = sp.Symbol("x")
    multiplicity = sp.roots(S.charpoly(x).as_expr(), x)[lam]
    A, size = S - lam * sp.eye(S.rows), S.rows
    ranks = [size]
    while len(ranks) < 2 or ranks[-1] != ranks[-2]:
        ranks.append((A ** len(ranks)).rank())
    at_least = [ranks[k - 1] - ranks[k] for k in range(1, len(ranks))]
    sizes = [k for k in range(len(at_least), 0, -1) for _ in range(at_least[k - 1] - (at_least[k] if k < len(at_least) else 0))]
    return multiplicity, "+".join(map(str, sizes))


def _expected() -> str:
    S = zoo_matrix(MIDEDGE, 3).matrix
    x = sp.Symbol("x")
    lam = max(r for r in sp.roots(sp.Matrix(S).charpoly(x).as_expr(), x) if r not in (0, 1))  # the subdominant one
    multiplicity, sizes = _jordan_text(sp.Matrix(S), lam)
    assert multiplicity > 1 and "2" in sizes  # not simple, and defective: the case the message is about
    return (f"n = 3: no masks: the eigenvalue {lam} has multiplicity {multiplicity} (frequencies 0, 1, 2) with Jordan "
            f"blocks of sizes {sizes}, so its left eigenvector at frequency 1 is not one mask")


@pytest.mark.parametrize("json_flag", [[], ["--json"]])
def test_masks_says_why_there_is_no_mask(capsys, json_flag) -> None:
    assert main(["masks", "3", "--scheme", "midedge", *json_flag]) == 2
    captured = capsys.readouterr()
    assert captured.err == f"symdecomp: error: {_expected()}\n"
    assert captured.out == ""


def test_api_raises_the_package_error() -> None:
    with pytest.raises(SymdecompError, match="multiplicity"):
        zoo_masks(MIDEDGE, 3)
