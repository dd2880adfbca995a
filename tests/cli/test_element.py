"""The extraordinary element a command is asked about: read once (``symdecomp.cli.element``), routed by a table per command.

Issue 30, "one model of a neighbourhood": the kind of element (interior vertex, sector at a sharp vertex, a zoo
scheme's vertex or face) is read in one place, each command keeps a table from kind to route, and a kind a command has
no route for fails in one line naming the command and the kind (exit status 2 on the command line).
"""

import importlib
import inspect
import re

import pytest

from symdecomp.cli import build_parser, main
from symdecomp.cli.element import KINDS, Element, named_element, route
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.scheme import catmull_clark

#: The commands that analyse one element, and their modules.
COMMANDS = {"spectrum": "spectrum_cmd", "masks": "masks_cmd", "check": "check_cmd", "c1": "c1_cmd",
            "artifacts": "artifacts_cmd", "evaldata": "evaldata_cmd"}


def _module(command: str):
    return importlib.import_module(f"symdecomp.cli.{COMMANDS[command]}")


@pytest.mark.parametrize(("argv", "kind", "tags"), [
    (["spectrum", "5"], "vertex", ()),
    (["spectrum", "5", "--scheme", "loop", "--rings", "2"], "vertex", ()),
    (["spectrum", "4", "--boundary"], "sector", ("--boundary",)),
    (["masks", "3", "--crease", "3"], "sector", ("--crease",)),
    (["check", "--k", "3:4", "--dart"], "sector", ("--dart",)),
    (["c1", "--crease", "2,3"], "sector", ("--crease",)),
    (["evaldata", "--crease", "--k", "2", "--out", "x.json"], "sector", ("--crease",)),
    (["spectrum", "5", "--scheme", "doo-sabin"], "zoo", ()),
    (["artifacts", "--n", "3:4", "--scheme", "sqrt3"], "zoo", ()),
    (["masks", "5", "--scheme", "doo-sabin", "--corner"], "zoo sector", ("--corner",)),
])
def test_the_element_is_read_from_the_scheme_and_the_sharp_options(argv, kind, tags):
    element = named_element(build_parser().parse_args(argv))
    assert (element.kind, element.tags) == (kind, tags)
    assert element.words == KINDS[kind]


@pytest.mark.parametrize(("argv", "centre", "sizes", "depth"), [
    (["spectrum", "5"], "vertex", (5,), 1),
    (["spectrum", "7", "--scheme", "loop", "--rings", "2"], "vertex", (7,), 2),
    (["check", "--k", "3:5", "--boundary"], "vertex", (3, 4, 5), 1),
    (["c1", "--every-n"], "vertex", (), 1),
    (["evaldata", "--n", "3:4", "--scheme", "doo-sabin", "--out", "x.json"], "face", (3, 4), 1),
    (["masks", "6", "--scheme", "midedge", "--rings", "2"], "face", (6,), 2),
    (["check", "--n", "3:4", "--scheme", "sqrt3", "--certify"], "vertex", (3, 4), 1),
])
def test_the_element_knows_its_centre_sizes_and_depth(argv, centre, sizes, depth):
    """Doo-Sabin and mid-edge are dual: their element is an n-sided face; sqrt(3) is primal, a vertex."""
    element = named_element(build_parser().parse_args(argv))
    assert (element.centre, element.sizes, element.depth) == (centre, sizes, depth)


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_every_command_routes_by_its_table_of_kinds(command):
    """Each command module has one table, keys among the kinds, values its own functions, and no per-kind if-chain."""
    module = _module(command)
    assert set(module.ROUTES_BY_KIND) <= set(KINDS) and "vertex" in module.ROUTES_BY_KIND
    assert all(inspect.getmodule(f) is module for f in module.ROUTES_BY_KIND.values())
    source = inspect.getsource(module)
    assert re.findall(r"is_stencil_scheme\(|sharp_given\(|isinstance\(args\.scheme", source) == []


def test_a_kind_without_a_route_is_refused_naming_the_command_and_the_kind():
    element = Element(catmull_clark(), "sector", ("--boundary",))
    with pytest.raises(InvalidInputError) as exc:
        route("artifacts", _module("artifacts").ROUTES_BY_KIND, element)
    assert str(exc.value) == ("artifacts: a boundary, crease, corner or dart vertex (--boundary) is not answered by artifacts "
                              "(--scheme catmull-clark); it answers an interior vertex; the extraordinary vertex or face of a "
                              "scheme of the zoo")


def test_on_the_command_line_the_refusal_is_one_line_and_exit_status_2(monkeypatch, capsys):
    """A command whose table loses a route refuses that kind at once: no traceback, no other route taken."""
    monkeypatch.delitem(_module("spectrum").ROUTES_BY_KIND, "zoo")
    assert main(["spectrum", "5", "--scheme", "doo-sabin"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == ("symdecomp: error: spectrum: the extraordinary vertex or face of a scheme of the zoo is not "
                            "answered by spectrum (--scheme doo-sabin); it answers an interior vertex; a boundary, crease, "
                            "corner or dart vertex; a boundary, crease, corner or dart vertex of a scheme of the zoo\n")


def test_a_new_route_is_one_entry_in_the_table(monkeypatch, capsys):
    """The table is the dispatch: an entry put in for a kind is what the command runs for it."""
    seen = []
    monkeypatch.setitem(_module("artifacts").ROUTES_BY_KIND, "vertex", lambda args: seen.append(args.valences) or 0)
    assert main(["artifacts", "--n", "3:4"]) == 0
    assert seen == [[3, 4]] and capsys.readouterr().out == ""


@pytest.mark.parametrize(("tag", "faces", "sectors", "closed", "corner"), [
    ("--boundary", 4, (4,), False, False),
    ("corner", 2, (2,), False, True),
    ("--crease", (2, 3), (2, 3), True, False),
    ("dart", 5, (5,), True, False),
])
def test_a_sharp_vertex_is_built_from_its_tag_in_one_place(tag, faces, sectors, closed, corner):
    """A boundary's fan is open, a crease's and a dart's closed (a dart: one sector around the whole fan)."""
    from symdecomp.cli.element import sector_vertex

    vertex = sector_vertex(tag, faces, "quad")
    assert (vertex.sectors, vertex.closed, vertex.corner, vertex.faces) == (sectors, closed, corner, sum(sectors))
