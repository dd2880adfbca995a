"""The boundary/corner evaluation document: the docstring's layout is the writer's, and the data read back evaluate exactly."""

import json
import re
from fractions import Fraction

import pytest

from symdecomp.analysis.evaluation import evaluate
from symdecomp.analysis.subpatch_data import sharp_patch_data
from symdecomp.errors import EvalDataFileError
from symdecomp.output import evaldata
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex


def _write(path, datas, scheme):
    text = "".join(evaldata.sharp_json_chunks(map(evaldata.sharp_entry, datas), scheme.name, scheme.lattice.name))
    path.write_text(text)
    return json.loads(text)


@pytest.mark.parametrize("make", [catmull_clark, loop])
def test_round_trip_evaluates_exactly_as_computed(tmp_path, make):
    scheme = make()
    datas = [sharp_patch_data(scheme, SharpVertex.boundary(3, scheme.lattice)),
             sharp_patch_data(scheme, SharpVertex.corner(2, scheme.lattice))]
    _write(tmp_path / "d.json", datas, scheme)
    back = evaldata.read_sharp_json(tmp_path / "d.json")
    assert sorted(back) == [("boundary", 3), ("corner", 2)]
    for data in datas:
        read = back[(data.kind, data.faces)]
        assert (read.matrix, read.patches, read.limit, read.vertex) == (data.matrix, data.patches, data.limit, data.vertex)
        net = [[Fraction(i * i % 7, 3), Fraction(-i, 5)] for i in range(data.size)]
        u, v = Fraction(3, 32), Fraction(1, 8)
        assert evaluate(read, data.faces - 1, u, v, net) == evaluate(data, data.faces - 1, u, v, net)


def test_the_docstring_names_the_writer_s_keys(tmp_path):
    scheme = catmull_clark()
    doc = _write(tmp_path / "d.json", [sharp_patch_data(scheme, SharpVertex.boundary(1, scheme.lattice))], scheme)
    text = " ".join(evaldata.__doc__.split()).split("Boundary and corner patches", 1)[1]
    layout = re.search(r'``(\{"format": "sharp-patches".*?\]\})``', text).group(1)
    top = re.findall(r'"(\w+)"', layout.split("[{", 1)[0])
    inner = re.findall(r'"(\w+)"', layout.split("[{", 1)[1])
    assert top == list(doc)
    assert inner == list(doc["vertices"][0])
    assert doc["format"] == "sharp-patches" and doc["layout"] == evaldata.SHARP_LAYOUT


def test_malformed_documents_are_refused_in_one_line(tmp_path):
    scheme = loop()
    doc = _write(tmp_path / "d.json", [sharp_patch_data(scheme, SharpVertex.boundary(2, scheme.lattice))], scheme)
    bad = [dict(doc, format="stam-loop")]
    for key, value in (("limit", ["1/2"]), ("kind", "crease"), ("k", 5)):
        bad.append(dict(doc, vertices=[dict(doc["vertices"][0], **{key: value})]))
    row = doc["vertices"][0]["matrix"][0]
    for weight in ("0.5", "1e3", "__import__('os')", 7):
        matrix = [[[row[0][0], weight]]] + doc["vertices"][0]["matrix"][1:]
        bad.append(dict(doc, vertices=[dict(doc["vertices"][0], matrix=matrix)]))
    bad.append(dict(doc, vertices=[dict(doc["vertices"][0], matrix=[[[999, "1"]]] + doc["vertices"][0]["matrix"][1:])]))
    for i, d in enumerate(bad):
        path = tmp_path / f"bad{i}.json"
        path.write_text(json.dumps(d))
        with pytest.raises(EvalDataFileError) as info:
            evaldata.read_sharp_json(path)
        assert "\n" not in str(info.value)
