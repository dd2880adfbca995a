"""The sector-evaldata document: written whole, read back exactly, malformed files refused in one line."""

import json
from fractions import Fraction

import pytest

from symdecomp.analysis.sector_evaldata import sector_evaldata
from symdecomp.analysis.sector_evaluation import evaluate
from symdecomp.errors import EvalDataFileError
from symdecomp.output.sector_evaldata import SECTOR_FORMAT, read_sector_json, sector_entry, sector_json_chunks
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex


def _write(path, data):
    path.write_text("".join(sector_json_chunks(map(sector_entry, data), "catmull-clark", "quad")))


def test_round_trip_keeps_every_number(tmp_path):
    data = [sector_evaldata(catmull_clark(), SharpVertex.corner(2, "quad"))]
    path = tmp_path / "s.json"
    _write(path, data)
    (read,) = read_sector_json(path).values()
    assert read.matrix == data[0].matrix and read.cells == data[0].cells and read.limit == data[0].limit
    assert [b.block for b in read.decomposition] == [b.block for b in data[0].decomposition]
    net = [[Fraction(i)] for i in range(read.size)]
    assert evaluate(read, 1, Fraction(1, 3), Fraction(1, 7), net) == evaluate(data[0], 1, Fraction(1, 3), Fraction(1, 7), net)
    assert json.loads(path.read_text())["format"] == SECTOR_FORMAT


@pytest.mark.parametrize("edit, message", [
    (lambda d: d.update(format="sharp-patches"), "not a sector evaluation data document"),
    (lambda d: d["vertices"][0]["matrix"][0].__setitem__(0, [0, "0.5"]), "'0.5' is not an exact rational"),
    (lambda d: d["vertices"][0].update(kind="dart"), "kind 'dart'"),
    (lambda d: d["vertices"][0]["cells"].pop(), "need 2 faces of 12 cells"),
    (lambda d: d["vertices"][0]["matrix"][0].__setitem__(0, [99, "1"]), "column 99 outside"),
])
def test_malformed_documents_are_refused(tmp_path, edit, message):
    path = tmp_path / "s.json"
    _write(path, [sector_evaldata(catmull_clark(), SharpVertex.boundary(2, "quad"))])
    doc = json.loads(path.read_text())
    edit(doc)
    path.write_text(json.dumps(doc))
    with pytest.raises(EvalDataFileError, match=message) as info:
        read_sector_json(path)
    assert "\n" not in str(info.value)
