"""One shape for ``--json`` (issue 34, item 4): every command's output validates against the shipped JSON Schema."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest

from symdecomp import __version__
from symdecomp.cli import COMMANDS, build_parser, main
from symdecomp.cli.json_envelope import envelope, json_schema
from symdecomp.errors import InternalError

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "notebooks" / "data" / "valences-3-5-6.obj"

#: A small run of every command that has --json (``{tmp}``: a fresh directory); the slow ones are marked.
CASES = {
    "claims": ["claims", "--label", "Eq. 34"],
    "derive": pytest.param(["derive", "--out", "{tmp}/derivations"], marks=pytest.mark.slow),
    "spectrum": ["spectrum", "5"],
    "spectrum --boundary": ["spectrum", "3", "--boundary"],
    "charpoly": ["charpoly", "5"],
    "charpoly --rings": ["charpoly", "4", "--rings", "2"],
    "oracle": ["oracle", "--n", "3", "--levels", "2"],
    "tune": ["tune", "5"],
    "tune --table": ["tune", "5", "--table"],
    "masks": ["masks", "5"],
    "masks --boundary": ["masks", "2", "--boundary"],
    "check": ["check", "--n", "3:4"],
    "check --boundary": ["check", "--boundary", "--k", "2", "--certify"],
    "c1": ["c1", "--n", "3:4"],
    "c1 --boundary": ["c1", "--boundary", "--k", "2"],
    "artifacts": ["artifacts", "--n", "3:4"],
    "evaldata": ["evaldata", "--n", "3", "--out", "{tmp}/cc.dat"],
    "inspect": ["inspect", str(MODEL)],
    "refine": ["refine", str(MODEL), "--steps", "1", "--out", "{tmp}/refined.obj"],
    "oracle --mesh": ["oracle", "--mesh", str(MODEL)],
    "design": ["design", "--n", "5", "--normal", "0,0,1", "--out", "{tmp}/ring.obj"],
}


def _json_commands() -> set[str]:
    """The commands whose parser has a --json option."""
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    return {name for name, p in sub.choices.items() if any("--json" in a.option_strings for a in p._actions)}


def test_every_command_with_json_is_run_here_and_named_in_the_schema():
    assert {case.split()[0] for case in CASES} == _json_commands()
    assert set(json_schema()["properties"]["command"]["enum"]) == _json_commands()
    assert _json_commands() <= {name.removesuffix("_cmd") for name in COMMANDS}


@pytest.mark.parametrize("argv", CASES.values(), ids=CASES.keys())
def test_json_output_validates_against_the_schema(argv, tmp_path, capsys):
    argv = [part.replace("{tmp}", str(tmp_path)) for part in argv] + ["--json"]
    code = main(argv)
    captured = capsys.readouterr()
    if code == 3:
        pytest.skip(f"{argv[0]}: an optional component is missing: {captured.err.strip()}")
    assert code in (0, 1), captured.err
    data = json.loads(captured.out)
    jsonschema.validate(data, json_schema())
    assert list(data)[:3] == ["command", "inputs", "version"]
    assert data["command"] == argv[0] and data["version"] == __version__
    assert data["inputs"].get("scheme") is None or isinstance(data["inputs"]["scheme"], str)


def _row_enum(command: str, *path: str) -> set:
    rule = next(r["then"] for r in json_schema()["allOf"] if r["if"]["properties"]["command"]["const"] == command)
    node = rule["properties"]["rows"]["items"]
    for key in path:
        node = node["properties"][key]
    return set(node["enum"])


def test_the_schemas_verdicts_are_the_packages():
    from symdecomp.analysis.curvature_regime import CurvatureRegime
    from symdecomp.claims import Status
    from symdecomp.verify.result import C1Verdict, CrossCheckStatus

    assert _row_enum("claims", "status") == {s.value for s in Status}
    assert _row_enum("c1", "verdict") == {v.value for v in C1Verdict}
    assert _row_enum("check", "status") == {s.value for s in CrossCheckStatus}
    assert _row_enum("artifacts", "curvature", "regime") == {r.value for r in CurvatureRegime}


def test_the_schema_rejects_the_old_shapes():
    """A list at top level (the old c1 and claims) and rows without their keys do not validate."""
    schema = json_schema()
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate([{"n": 3, "verdict": "c1", "reason": ""}], schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(envelope("c1", {}, [{"n": 3}]), schema)
    with pytest.raises(jsonschema.ValidationError, match="'C1' is not one of"):
        jsonschema.validate(envelope("c1", {}, [{"n": 3, "verdict": "C1", "reason": "r"}]), schema)
    jsonschema.validate(envelope("c1", {"valences": [3]}, [{"n": 3, "verdict": "c1", "reason": "r"}]), schema)


def test_the_envelope_wraps_a_list_as_rows_and_refuses_a_clash():
    assert envelope("c1", {"n": [3]}, [{"n": 3}]) == {"command": "c1", "inputs": {"n": [3]}, "version": __version__,
                                                       "rows": [{"n": 3}]}
    with pytest.raises(InternalError, match="'version' is one of the envelope's"):
        envelope("spectrum", {}, {"version": 1})


def test_inputs_are_json_a_scheme_by_name_and_inf_as_text(capsys):
    assert main(["c1", "--crease", "2,2", "--json", "--depth", "0"]) in (0, 1)
    inputs = json.loads(capsys.readouterr().out)["inputs"]
    assert inputs["scheme"] == "catmull-clark" and inputs["sharpness"] == "inf" and inputs["crease"] == [2, 2]
    assert inputs["depth"] == 0 and inputs["valences"] is None


def test_inputs_hold_no_parser_bookkeeping(capsys):
    """A parser's markers (names starting with ``_``: the sharp options' own) are not the user's inputs."""
    assert main(["spectrum", "5", "--json"]) == 0
    inputs = json.loads(capsys.readouterr().out)["inputs"]
    assert [k for k in inputs if k.startswith("_")] == [] and inputs["boundary"] is False


def test_a_long_list_is_printed_one_row_per_line_and_reads_back_the_same(capsys):
    """A top-level list past ROWS_PER_LINE (25,000 vertices of a scan) is printed one compact row per line: the
    indenting encoder is pure Python; the object read back is the one given."""
    import argparse

    from symdecomp.cli.json_envelope import ROWS_PER_LINE, print_json

    rows = [{"vertex": i, "limit": [i / 3, float("nan") if i == 7 else -i, 0.0], "kind": "smooth n = 5"}
            for i in range(ROWS_PER_LINE + 1)]
    print_json(argparse.Namespace(command="inspect", quiet=True), {"extraordinary": rows, "short": [1, 2]})
    out = capsys.readouterr().out
    data = json.loads(out)
    assert json.dumps(data["extraordinary"]) == json.dumps(rows) and data["short"] == [1, 2]
    assert sum(line.startswith('    {"vertex": ') and line.endswith(("},", "}")) for line in out.splitlines()) == len(rows)
