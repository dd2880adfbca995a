"""The guide pages' pictures (issue 34): each is drawn by its command while the site is built
(``docs/_ext/guide_figures.py``), the same bytes every time; a command that cannot draw yet is skipped with one
build-time line, and its page shows a note until the option exists."""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "guide"


def _extension():
    spec = importlib.util.spec_from_file_location("guide_figures", ROOT / "docs" / "_ext" / "guide_figures.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclass looks its module up there
    spec.loader.exec_module(module)
    return module


EXT = _extension()


def test_every_figure_is_on_one_guide_page_and_every_page_names_a_known_one():
    shown = {}
    for page in sorted(GUIDE.glob("*.md")):
        for name in re.findall(r"^```\{symdecomp-figure\} (\S+)$", page.read_text(), re.M):
            shown.setdefault(name, []).append(page.name)
    assert sorted(shown) == sorted(f.name for f in EXT.FIGURES)
    assert {name: pages for name, pages in shown.items() if len(pages) != 1} == {}
    assert shown["c1"] == ["c1.md"] and shown["check"] == ["check.md"] and shown["inspect-vertex"] == ["control-nets.md"]


def test_the_commands_that_draw_today_are_drawn_and_the_others_wait_for_plot():
    import argparse

    from symdecomp.cli import build_parser
    from symdecomp.cli.common import Parser  # noqa: F401 - the parser the figures ask

    (action,) = [a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)]
    for figure in EXT.FIGURES:
        options = {o for a in action.choices[figure.command]._actions for o in a.option_strings}
        assert EXT.missing_options(figure) == [a for a in figure.argv if a.startswith("--") and a not in options]
    assert EXT.missing_options(next(f for f in EXT.FIGURES if f.name == "inspect-vertex")) == []
    assert EXT.missing_options(next(f for f in EXT.FIGURES if f.name == "tune-region")) == []


def test_a_figure_that_cannot_be_drawn_yet_is_skipped_with_one_line_and_a_note(tmp_path):
    waiting = EXT.Figure("waits", ("spectrum", "5", "--no-such-picture-option", "{out}"), caption="symdecomp spectrum: x")
    said = []
    assert EXT.draw_all(tmp_path, figures=(waiting,), say=said.append) == {"waits": None}
    assert said == ["symdecomp docs: figure 'waits' skipped: 'symdecomp spectrum' has no --no-such-picture-option yet; "
                    "its guide page shows a note instead"]
    assert not (tmp_path / EXT.FIGURE_DIR).exists()
    note = EXT.figure_text("c1", {"c1": None})
    assert note.startswith(".. note::") and "``symdecomp c1 --plot``" in note
    with pytest.raises(ValueError, match="unknown figure 'nope'"):
        EXT.figure_text("nope", {})


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_a_figure_is_drawn_the_same_every_time_and_again_only_when_its_inputs_change(tmp_path):
    pytest.importorskip("matplotlib")
    figure = next(f for f in EXT.FIGURES if f.name == "tune-region")
    said = []
    first = EXT.draw_all(tmp_path / "a", figures=(figure,), say=said.append)["tune-region"]
    second = EXT.draw(figure, tmp_path / "b")
    assert first.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and first.read_bytes() == second.read_bytes()
    assert said == ["symdecomp docs: drawing figure 'tune-region': symdecomp " + " ".join(figure.argv)]
    EXT.draw_all(tmp_path / "a", figures=(figure,), say=said.append)  # same digest: not drawn again
    assert len(said) == 1
    text = EXT.figure_text("tune-region", {"tune-region": first})
    assert text.startswith(".. figure:: /_generated/figures/tune-region.png\n") and "``symdecomp tune 5 --region" in text


def test_a_failing_command_fails_the_build_with_its_error_line(tmp_path):
    broken = EXT.Figure("broken", ("tune", "5", "--region", "--plot", "{out}"), caption="symdecomp tune: x")
    with pytest.raises(RuntimeError, match=r"symdecomp tune 5 --region --plot \{out\}: exit 2: symdecomp: error: scheme"):
        EXT.draw(broken, tmp_path)
