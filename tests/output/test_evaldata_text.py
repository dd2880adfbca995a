"""The JSON eigen-data text written in bulk (``json_valence_text``) is ``json.dumps`` of ``json_valence``, character
for character: on computed valences of both layouts and on the float64s a formatter could merge (signed zeros)."""

import json

import numpy as np
import pytest

import symdecomp as sd
from symdecomp.analysis.eigendata import RoundedEigenData, rounded_eigendata
from symdecomp.errors import EvalDataFileError
from symdecomp.output import evaldata


def _dumped(d) -> str:
    return json.dumps(evaldata.json_valence(d), separators=(",", ":"))


@pytest.mark.parametrize(("scheme", "n", "loop", "jordan"), [
    (sd.loop(), 3, True, True),  # not diagonalizable: the Jordan pairs are written
    (sd.loop(), 7, True, False),
    (sd.catmull_clark(), 5, False, False),
])
def test_bulk_text_is_the_encoder_s(scheme, n, loop, jordan):
    ((_, d),) = rounded_eigendata(scheme, [n])
    encoded = evaldata.json_valence_text(d)
    assert encoded.text == _dumped(d)
    assert (encoded.n, encoded.loop, bool(d.jordan)) == (n, loop, jordan)


def test_signed_zeros_and_neighbouring_doubles_keep_their_own_text():
    k = 2
    tiny = np.nextafter(0.0, 1.0)
    values = np.array([-0.0, 0.0])
    inverse = np.array([[0.1, np.nextafter(0.1, 1.0)], [-0.0, tiny]])
    phi = np.stack([np.full((k, 12), x) for x in (0.0, -0.0, 1 / 3)])
    d = RoundedEigenData(3, values, inverse, phi, ((0, 1, -0.0),))
    text = evaldata.json_valence_text(d).text
    assert text == _dumped(d)
    entry = json.loads(text)
    assert entry["values"] == ["-0.0", "0.0"] and entry["inverse"][1] == "-0.0" and entry["phi"][1][0] == "-0.0"


def test_the_catmull_clark_layout_refuses_a_jordan_block_in_either_writer():
    d = RoundedEigenData(3, np.zeros(2), np.zeros((2, 2)), np.zeros((3, 2, 16)), ((0, 1, 1.0),))
    for write in (evaldata.json_valence, evaldata.json_valence_text):
        with pytest.raises(EvalDataFileError, match="valence 3: the Catmull-Clark layout has no place for a Jordan block"):
            write(d)


def test_the_document_from_texts_is_the_document_from_entries():
    data = [d for _, d in rounded_eigendata(sd.loop(), [3, 4])]
    from_texts = "".join(evaldata.json_chunks(map(evaldata.json_valence_text, data), 4, 17, "loop"))
    assert from_texts == "".join(evaldata.json_chunks(map(evaldata.json_valence, data), 4, 17, "loop"))
