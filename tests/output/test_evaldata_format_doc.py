"""The evaluation-data formats have one description, the docstring of ``symdecomp.output.evaldata`` (the
documentation's page is that text): the layouts it states are compared here with what the writer writes."""

import json
import math
import re

import pytest

import symdecomp as sd
from symdecomp.analysis.eigendata import rounded_eigendata
from symdecomp.output import evaldata

DOC = " ".join(evaldata.__doc__.split())


def _sizes(declaration: str, k: int) -> list[int]:
    """The element counts of ``float64 name[K*16]``-style declarations, with ``K = k``."""
    return [math.prod(k if f == "K" else int(f) for f in dims.split("*")) for dims in re.findall(r"\w+\[([K0-9*]+)\]", declaration)]


def _json_keys(layout: str) -> tuple[list[str], list[str]]:
    """The keys the docstring gives a document (depth 1) and a valence (depth 2): ``{"format", ..., "valences": [{"n", ...}]}``."""
    depth, keys = 0, {1: [], 2: []}
    for token in re.finditer(r'(?<!: )"([\w-]+)"|\{|\}', layout):
        if token.group(0) in "{}":
            depth += 1 if token.group(0) == "{" else -1
        elif depth in keys:
            keys[depth].append(token.group(1))
    return keys[1], keys[2]


def _data(scheme, n=3):
    ((_, data),) = rounded_eigendata(scheme, [n])
    return data


@pytest.fixture(scope="module")
def catmull_clark_3():
    return _data(sd.catmull_clark())


def test_the_binary_layout_is_the_writer_s(catmull_clark_3):
    declarations = DOC.split("Binary", 1)[1].split("JSON:", 1)[0]
    k = 2 * 3 + 8
    assert "K = 2N + 8" in declarations
    raw = evaldata.binary_bytes([catmull_clark_3])
    stated = _sizes(declarations.split("for N = 3 .. Nmax", 1)[1], k)
    assert stated == [k, k * k, 16 * k, 16 * k, 16 * k]
    assert len(raw) == 4 + 8 * sum(stated)
    assert int.from_bytes(raw[:4], "little") == 3


def test_the_catmull_clark_json_layout_is_the_writer_s(catmull_clark_3):
    layout = re.search(r'JSON: ``(\{"format": "stam-catmull-clark".*?\}\]\})``', DOC).group(1)
    top, valence = _json_keys(layout)
    document = json.loads("".join(evaldata.json_chunks([evaldata.json_valence(catmull_clark_3)], 3, evaldata.FLOAT_DIGITS)))
    assert list(document) == top and document["format"] == "stam-catmull-clark"
    (entry,) = document["valences"]
    assert list(entry) == valence
    k = 14
    assert [len(entry["values"]), len(entry["inverse"])] + [len(p) for p in entry["phi"]] == [k, k * k, 16 * k, 16 * k, 16 * k]
    # element (i, j) at i + K*j: the JSON's inverse is the binary file's, read back as a matrix
    assert float(entry["inverse"][2 + k * 5]) == catmull_clark_3.inverse[2, 5]


def test_the_loop_json_layout_is_the_writer_s():
    layout = re.search(r'``(\{"format": "stam-loop".*?\}\]\})``', DOC).group(1)
    top, valence = _json_keys(layout)
    data = _data(sd.loop())
    document = json.loads("".join(evaldata.json_chunks([evaldata.json_valence(data)], 3, evaldata.FLOAT_DIGITS, scheme="loop")))
    assert list(document) == top and document["format"] == "stam-loop" and document["layout"] == evaldata.LOOP_LAYOUT
    (entry,) = document["valences"]
    assert list(entry) == valence
    k = 3 + 6
    assert "K = N + 6" in DOC and "``Phi_k[K*12]``" in DOC
    assert [len(entry["values"]), len(entry["inverse"])] + [len(p) for p in entry["phi"]] == [k, k * k, 12 * k, 12 * k, 12 * k]
    assert entry["jordan"], "Loop at N = 3 is not diagonalizable: the docstring says the Jordan pairs are listed"
