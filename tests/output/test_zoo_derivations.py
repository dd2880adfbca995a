"""The zoo's derivations (``derivations/zoo.tex``): what the document states is the mathematics of each family.

The byte-for-byte drift check of the committed file is ``tests/output/test_latex.py``
(``test_committed_derivations_match_the_registry``: ``write_derivations`` writes ``zoo.tex`` too).
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
import sympy as sp

from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_symbols import FamilySymbol
from symdecomp.output.texlayout import latex
from symdecomp.output.zoo_derivations import ZOO_FILE, factored_charpoly, family_latex, rule_symbols, zoo_derivation_files
from symdecomp.schemes.stencil_files import ZOO_FILES, load_zoo
from symdecomp.schemes.stencils import J, M
from symdecomp.symbols import lam, omega
from tests.output.test_latex import COMMITTED, PDFLATEX, _overfull, needs_tex


def _is_zero(expr) -> bool:
    """Exactly: the minimal polynomial of an algebraic number (roots of unity, their cosines) is x only for 0."""
    x = sp.Symbol("x")
    return sp.minimal_polynomial(sp.expand_complex(expr), x) == x


def _corner_symbol():
    [(where, term, symbol)] = rule_symbols(load_zoo("doo-sabin"))
    assert where == "corner rule" and isinstance(symbol, FamilySymbol)
    return term, symbol


@pytest.mark.slow
@pytest.mark.parametrize("m", [3, 4, 5, 6, 7])
def test_doo_sabins_symbol_is_the_circulants_eigenvalue_at_each_face_size(m):
    """The closed form in m against the circulant of the corner weights, summed exactly at each m and frequency."""
    term, symbol = _corner_symbol()
    for k in range(m):
        signed = k - m if k > m // 2 else k
        direct = sum(term.weight.subs({M: m, J: j}) * sp.exp(2 * sp.pi * sp.I * j * k / m) for j in range(m))
        assert _is_zero(direct - symbol.value(signed)), (m, k)
    assert (symbol.at[0], symbol.at[1], symbol.at[-1], symbol.otherwise) == (1, sp.Rational(1, 2), sp.Rational(1, 2), sp.Rational(1, 4))


@pytest.mark.slow
def test_doo_sabins_corner_block_entry_is_the_symbol():
    """The corners of the n-gon are one orbit: the block's corner entry at omega = zeta^k is the rule's symbol."""
    _, symbol = _corner_symbol()
    for n in (5, 7):
        B = zoo_blocks(zoo_matrix(load_zoo("doo-sabin"), n)).frequency_matrix(omega)
        for k in range(n):
            signed = k - n if k > n // 2 else k
            value = B[0, 0].subs(omega, sp.exp(2 * sp.pi * sp.I * k / n))
            assert _is_zero(value - symbol.value(signed)), (n, k)


@pytest.mark.parametrize("name", ["doo-sabin", "midedge", "modified-butterfly"])
def test_the_blocks_charpolys_multiply_to_the_whole_matrixs(name):
    """At n = 4 (rational entries): det(lam I - S) of the whole matrix is the product of the factored block
    polynomials over the frequencies (B_0 bordered by the centre where there is one)."""
    zm = zoo_matrix(load_zoo(name), 4)
    blocks = zoo_blocks(zm)
    whole = (lam * sp.eye(zm.matrix.rows) - sp.Matrix(zm.matrix)).det(method="berkowitz")
    product = factored_charpoly(blocks.frequency_zero_matrix())
    for k in range(1, 4):
        product *= factored_charpoly(blocks.frequency_matrix(omega)).subs(omega, sp.I**k)
    assert sp.expand(whole - product) == 0


def test_the_factored_charpoly_is_an_identity_with_radicals():
    B = zoo_blocks(zoo_matrix(load_zoo("doo-sabin"), 5)).frequency_matrix(omega)
    factored = factored_charpoly(B)
    assert sp.simplify(sp.expand(factored - (lam * sp.eye(4) - B).det(method="berkowitz"))) == 0
    # the rows of corners' neighbours give the biquadratic B-spline's subdominant eigenvalues 1/4, 1/8, 1/16
    for root in (sp.Rational(1, 4), sp.Rational(1, 8), sp.Rational(1, 16)):
        assert factored.subs(lam, root) == 0


def test_the_document_prints_what_the_engine_derived():
    doo = load_zoo("doo-sabin")
    section = family_latex(doo, valences=(4,))
    B = zoo_blocks(zoo_matrix(doo, 5)).frequency_matrix(omega)
    assert latex(factored_charpoly(B)) in section.replace("\n", " ")
    assert "\\hat w(\\pm 1) = \\frac{1}{2}" in section and "\\hat w(0) = 1" in section
    assert "4 & $\\frac{1}{2}$ & 2 & 1, 3 \\\\" in section  # the subdominant pair at n = 4, frequencies 1 and 3


def test_sqrt3_says_it_is_analysed_over_two_steps():
    section = family_latex(load_zoo("sqrt3"), valences=(3,))
    assert "after 2 steps, so the matrix, its blocks and its spectrum are those of 2 steps" in section.replace("\n", " ")
    assert "3 & $\\frac{1}{9}$ & 2 & 1, 2 \\\\" in section  # (1/3)^2: the two steps' subdominant eigenvalue at n = 3


def test_a_rule_without_a_closed_form_symbol_says_why():
    where = [(w, s) for w, _, s in rule_symbols(load_zoo("modified-butterfly"))]
    assert [w for w, _ in where] == ["edge rule at an origin of valence 3", "edge rule at an origin of valence 4",
                                     "edge rule at an irregular origin"]
    assert isinstance(where[1][1], str) and "KroneckerDelta(2, j)" in where[1][1]


def test_the_document_has_one_section_per_shipped_family():
    document = zoo_derivation_files(("midedge",))[ZOO_FILE]
    assert document.count("\\section{") == 1 and "\\section{midedge}" in document
    assert document.startswith("% Generated by `symdecomp derive`") and document.endswith("\\end{document}\n")
    committed = (COMMITTED / ZOO_FILE).read_text(encoding="utf-8")
    assert [name for name in ZOO_FILES if f"\\section{{{name}}}" in committed] == list(ZOO_FILES)
    assert committed.count("\\section{") == len(ZOO_FILES)


@pytest.mark.slow
def test_the_committed_zoo_document_is_what_derive_writes():
    """The file the byte-for-byte test regenerates (with the claims) is this generator's output."""
    assert (COMMITTED / ZOO_FILE).read_text(encoding="utf-8") == zoo_derivation_files()[ZOO_FILE]


@needs_tex
def test_the_zoo_document_compiles_and_nothing_runs_past_the_margin(tmp_path: Path):
    shutil.copy(COMMITTED / ZOO_FILE, tmp_path / ZOO_FILE)
    for _ in range(2):
        run = subprocess.run([str(PDFLATEX), "-interaction=nonstopmode", "-halt-on-error", ZOO_FILE], cwd=tmp_path,
                             capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, run.stdout[-2000:]
    assert _overfull((tmp_path / "zoo.log").read_text(errors="replace")) == []
