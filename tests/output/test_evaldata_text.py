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
    assert (encoded.n, encoded.loop, encoded.jordan) == (n, loop, jordan)


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



def test_json_pieces_encoded_in_the_workers_are_those_of_the_arrays():
    """Two worker processes encode the valences where they compute them: the same text as the arrays computed in
    this process and encoded here, in the valences' order, with the Jordan pairs of Loop's N = 3 flagged."""
    ns = [3, 4, 5, 6]
    arrays = [d for _, d in rounded_eigendata(sd.loop(), ns)]
    pieces = [piece for _, piece in rounded_eigendata(sd.loop(), ns, jobs=2, encode=evaldata.json_valence_text)]
    assert [(piece.n, piece.jordan) for piece in pieces] == [(3, True), (4, False), (5, False), (6, False)]
    assert [piece.text for piece in pieces] == [_dumped(d) for d in arrays]


def test_binary_pieces_encoded_in_the_workers_make_the_file_of_the_arrays():
    ns = [3, 4, 5, 6]
    arrays = [d for _, d in rounded_eigendata(sd.catmull_clark(), ns)]
    pieces = [piece for _, piece in rounded_eigendata(sd.catmull_clark(), ns, jobs=2, encode=evaldata.binary_valence)]
    assert [piece.n for piece in pieces] == ns
    assert b"".join(evaldata.binary_chunks(pieces, 6)) == evaldata.binary_bytes(arrays)
    d = arrays[0]
    with pytest.raises(EvalDataFileError, match="valence 3: not Catmull-Clark data of a diagonalizable matrix"):
        evaldata.binary_valence(RoundedEigenData(3, d.values, d.inverse, d.phi, ((0, 1, 1.0),)))
