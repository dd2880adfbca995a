"""The README is a front door and the manual is the documentation site in docs/ (issue 23).

The README is short and starts with the two commands CI and readers run; the site's generated
pages cover every command of the parser and every module of the module map; the site builds with
warnings as errors (slow: it executes the notebooks)."""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = next(p for p in Path(__file__).resolve().parents if (p / "pyproject.toml").exists())
DOCS = ROOT / "docs"
README = (ROOT / "README.md").read_text()


def _extension():
    spec = importlib.util.spec_from_file_location("symdecomp_docs", DOCS / "_ext" / "symdecomp_docs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


EXT = _extension()


def test_the_readme_is_short_and_starts_with_the_two_commands():
    lines = README.splitlines()
    assert len(lines) <= 120
    assert lines[:9] == [
        "# symdecomp", "",
        "```bash", "pip install -e . && symdecomp claims", "```", "",
        "```bash", 'pip install -e ".[test]" && python -m pytest', "```",
    ]


def test_the_readme_holds_no_copy_of_a_reference_section():
    """The formats, the exit codes and the limits have their homes in docs/ and the code."""
    assert "[edge]" not in README and '"format": "stam' not in README
    assert "| exit code |" not in README and "| bound |" not in README


def test_the_readme_tour_shows_real_output(capsys):
    """The tour's spectrum is what the command prints (the lines shown, up to the ellipsis)."""
    from symdecomp.cli import main

    shown = README.split("$ symdecomp spectrum 5\n", 1)[1].split("\n...\n", 1)[0].splitlines()
    assert len(shown) >= 3
    assert main(["spectrum", "5"]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert printed[: len(shown)] == shown


def test_the_readme_links_resolve():
    for target in re.findall(r"\]\((docs/[^)#]+)\)", README):
        assert (ROOT / target).is_file(), target


def test_the_readme_docs_command_is_the_ci_one():
    command = re.search(r'pip install -e "\.\[docs\]" && (python -m sphinx .*)', README).group(1)
    assert command in (ROOT / ".ci" / "run").read_text()
    assert "docs" in __import__("tomllib").loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]


def test_every_subcommand_is_in_the_command_reference():
    from symdecomp.cli import build_parser

    text = EXT.command_reference()
    commands = EXT.subcommands(build_parser())
    assert len(commands) >= 10
    for name, parser in commands.items():
        section = text.split(f"``symdecomp {name}``\n", 1)[1].split("\n.. _command-", 1)[0]
        assert f"usage: symdecomp {name}" in section
        for action in parser._actions:
            for option in action.option_strings:
                assert option in section, f"symdecomp {name} {option}"
    assert (DOCS / "commands.rst").read_text().count(".. symdecomp-commands::") == 1


def test_every_exit_code_is_explained_in_the_guide():
    from symdecomp.cli import EXIT_CODES

    guide = (DOCS / "guide" / "command-line.md").read_text()
    rows = dict(re.findall(r"^\| (\d+) \| (.+) \|$", guide, re.M))
    assert sorted(map(int, rows)) == sorted(EXIT_CODES)
    assert "```{symdecomp-table} limits" in guide and "```{symdecomp-table} budget" in guide


def _map_modules():
    import symdecomp

    return EXT.map_modules(symdecomp.__doc__)


def test_every_module_of_the_map_has_an_api_page_entry(tmp_path):
    import symdecomp

    rows = [head.rstrip("/") for head, _, _ in EXT.map_rows(symdecomp.__doc__)]
    pages = "".join(path.read_text() for path in (DOCS / "api").glob("*.rst"))
    covered = re.findall(r"^\.\. symdecomp-api:: (\S+)$", pages, re.M)
    assert sorted(covered) == sorted(rows), "each row of the module map has its API page"
    generated = "".join(EXT.api_reference(row) for row in covered)
    pages = {path.stem: path.read_text() for path in EXT.write_module_pages(tmp_path)}
    for module in _map_modules():
        name = f"symdecomp.{module}"
        text = pages.get(name, generated)  # a folder's module has its own page; a top-level module is on its row's
        assert f".. automodule:: {name}\n" in text or f".. py:module:: {name}\n" in text, name
        assert name in pages or f"\n   modules/{name}\n" not in generated


def test_the_api_pages_have_one_line_summaries():
    """A folder's page is its package and a table of its modules (their docstrings' first sentences), one page per
    module; a module's page opens with a table of its public names, each beside its docstring's first sentence."""
    from symdecomp.analysis import spectrum

    analysis = EXT.api_reference("analysis")
    assert analysis.count(".. automodule::") == 1 and "   modules/symdecomp.analysis.spectrum\n" in analysis
    assert f"   * - :py:mod:`symdecomp.analysis.spectrum`\n     - {EXT.summary(spectrum)}\n" in analysis
    page = EXT.module_page("symdecomp.analysis.spectrum")
    table = page.split(".. list-table::", 1)[1].split(".. automodule::", 1)[0]
    names = re.findall(r"^   \* - :py:obj:`~symdecomp\.analysis\.spectrum\.(\w+)`$", table, re.M)
    assert names and not [n for n in names if n.startswith("_")]
    assert all(getattr(spectrum, n).__module__ == "symdecomp.analysis.spectrum" for n in names if callable(getattr(spectrum, n)))
    for name in names:
        assert f"`~symdecomp.analysis.spectrum.{name}`\n     - {EXT.summary(getattr(spectrum, name))}\n" in table
    errors = EXT.api_reference("errors")
    assert errors.index(".. list-table::") < errors.index(".. automodule:: symdecomp.errors")
    assert "   * - :py:obj:`~symdecomp.errors.SymdecompError`\n" in errors


def test_a_summary_is_the_first_sentence_unless_that_splits_markup():
    def f():
        """Eq. 34 in ``c = cos(j pi/n)``. More text.

        Another paragraph."""

    def g():
        """The ratio ``a. b`` of ``x``, e.g. two. Next."""

    def h():
        """No sentence end (a ``literal``. inside
        parentheses), two lines"""

    assert EXT.summary(f) == "Eq. 34 in ``c = cos(j pi/n)``."
    assert EXT.summary(g) == "The ratio ``a. b`` of ``x``, e.g. two."
    assert EXT.summary(h) == "No sentence end (a ``literal``. inside parentheses), two lines"
    assert EXT.summary(lambda: None) == ""


def test_the_docs_read_every_module_of_the_map():
    """The pages are generated from what this reader finds in the map: every module of the package, once."""
    import pkgutil

    import symdecomp

    found = {m.name.removeprefix("symdecomp.") for m in pkgutil.walk_packages(symdecomp.__path__, "symdecomp.")}
    assert sorted(_map_modules()) == sorted(found)
    with pytest.raises(ValueError, match="top-level"):
        EXT.map_rows("========  ====\n``a``     ``x``\n========  ====\n")


def test_the_notebook_pages_are_the_notebooks(tmp_path):
    copied = EXT.copy_notebooks(tmp_path)
    assert [p.name for p in copied] == sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
    assert all(p.read_bytes() == (ROOT / "notebooks" / p.name).read_bytes() for p in copied)


@pytest.mark.slow
def test_the_site_builds_with_warnings_as_errors(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_nb")
    result = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", "-d", str(tmp_path / "doctrees"), str(DOCS), str(tmp_path / "html")],
        cwd=ROOT, capture_output=True, text=True, timeout=1200,
    )
    assert result.returncode == 0, result.stderr[-3000:]
    commands = (tmp_path / "html" / "commands.html").read_text()
    assert 'id="command-check"' in commands and "usage: symdecomp check" in commands
    guide = (tmp_path / "html" / "guide" / "command-line.html").read_text()
    assert ".. list-table::" not in guide and guide.count("<table") >= 3, "the generated tables are tables on a Markdown page too"


def test_the_help_texts_send_readers_to_pages_that_exist():
    """A ``--help`` that names a documentation page names one that exists, and none sends to the README for a format."""
    from symdecomp.cli import build_parser

    helps = {name: " ".join(parser.format_help().split()) for name, parser in EXT.subcommands(build_parser()).items()}
    pages = {name: re.findall(r"docs/[\w./-]+\.(?:rst|md)", text) for name, text in helps.items()}
    assert "docs/formats/scheme-files.rst" in pages["report"] and "docs/formats/scheme-files.rst" in pages["spectrum"]
    assert [(name, page) for name, found in pages.items() for page in found if not (ROOT / page).is_file()] == []
    assert [name for name, text in helps.items() if "README" in text] == []


def test_the_notebook_titles_are_numbered_as_their_files():
    """The sidebar lists the notebooks by title: each is ``# N. ...`` with N the number its file name starts with."""
    import json

    titles = {}
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        cell = next(c for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "markdown")
        titles[path.name] = "".join(cell["source"]).splitlines()[0]
    assert len(titles) >= 10
    wrong = {name: title for name, title in titles.items() if not title.startswith(f"# {int(name.split('_', 1)[0])}. ")}
    assert wrong == {}


def test_the_readme_says_what_each_optional_part_needs():
    """The extras it names exist, and the Debian packages it names are those CI installs for the same part."""
    import tomllib

    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    named = re.findall(r'pip install "symdecomp\[(\w+)\]"', README)
    assert {"report", "dask"} <= set(named) and set(named) <= set(extras)
    steps = {path.name: path.read_text() for path in (ROOT / ".ci" / "steps").glob("*.sh")}
    for package in ("libosd-dev", "libosdcpu3.5.0", "g++"):
        assert package in README and package in steps["30-opensubdiv.sh"], package
    for package in ("texlive-latex-base", "texlive-latex-recommended"):
        assert package in README and package in steps["20-latex.sh"], package
    assert "matplotlib" in README and any(d.startswith("matplotlib") for d in extras["report"])
