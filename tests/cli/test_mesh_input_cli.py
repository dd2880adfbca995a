"""Mesh input on the command line (``inspect``, ``design --mesh``): a FIFO, a device, a lying PLY header, a coordinate
beyond the bound, a float index, a valence beyond the shared bound: one line naming the file and the element, exit 2,
nothing written (issue 35, items 1, 2, 3, 5, 9, 10, 16)."""

import os
import sys

import numpy as np
import pytest

from symdecomp.cli import main
from symdecomp.validate import MAX_MESH_VALENCE

SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
PLY = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face {faces}\nproperty list uchar {kind} vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n{face}\n")

BAD = [
    ("lying.ply", PLY.format(faces=300_000_000, kind="int", face="3 0 1 2"), "announces 300000000 'face' elements"),
    ("floatindex.ply", PLY.format(faces=1, kind="int", face="3 0 1.7 2"), "face 0: vertex index '1.7' is not an integer"),
    ("nanindex.ply", PLY.format(faces=1, kind="int", face="3 0 nan 2"), "face 0: vertex index 'nan' is not an integer"),
    ("huge.obj", SQUARE + "v 1e309 0 0\nf 1 2 3\n", "line 5: 1e309 is beyond the range of doubles"),
    ("digits.obj", SQUARE + "v " + "1" * 5000 + " 0 0\nf 1 2 3\n", "line 5: a number of 5000 characters"),
]


def refuse(args, capsys, words):
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("symdecomp: error: ") and words in err, err


@pytest.mark.parametrize(("name", "content", "words"), BAD, ids=[b[0] for b in BAD])
@pytest.mark.parametrize("command", ["inspect", "design"])
def test_a_malformed_mesh_is_one_line_and_exit_2(tmp_path, capsys, command, name, content, words):
    path = tmp_path / name
    path.write_text(content)
    out = tmp_path / "out.obj"
    args = ["inspect", str(path)] if command == "inspect" else ["design", "--mesh", str(path), "--vertex", "0", "--normal", "0,0,1",
                                                                   "--out", str(out)]
    refuse(args, capsys, words)
    assert not out.exists()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="POSIX FIFOs")
@pytest.mark.parametrize("command", ["inspect", "design"])
def test_a_fifo_is_refused_without_blocking(tmp_path, capsys, command):
    fifo = tmp_path / "mesh.obj"
    os.mkfifo(fifo)
    args = ["inspect", str(fifo)] if command == "inspect" else ["design", "--mesh", str(fifo), "--vertex", "0", "--normal", "0,0,1",
                                                                   "--out", str(tmp_path / "out.obj")]
    refuse(args, capsys, "mesh.obj: not a regular file (a FIFO)")


@pytest.mark.skipif(not os.path.exists("/dev/zero") or sys.platform == "win32", reason="a character device")
def test_a_device_named_like_a_mesh_is_refused(tmp_path, capsys):
    link = tmp_path / "zero.obj"
    link.symlink_to("/dev/zero")
    refuse(["inspect", str(link)], capsys, "zero.obj: not a regular file (a character device)")


def test_design_on_a_vertex_beyond_the_valence_bound_is_refused(tmp_path, capsys):
    n = MAX_MESH_VALENCE + 1  # a bipyramid: the apex 0 is interior of valence n
    ring = [f"v {np.cos(2 * np.pi * k / n):.17g} {np.sin(2 * np.pi * k / n):.17g} 0\n" for k in range(n)]
    faces = [f"f 1 {k + 3} {(k + 1) % n + 3}\n" for k in range(n)] + [f"f 2 {(k + 1) % n + 3} {k + 3}\n" for k in range(n)]
    path = tmp_path / "fan.obj"
    path.write_text("v 0 0 1\nv 0 0 -1\n" + "".join(ring + faces))
    refuse(["design", "--mesh", str(path), "--vertex", "0", "--normal", "0,0,1", "--out", str(tmp_path / "out.obj")], capsys,
           f"fan.obj: vertex 0 has valence {n}; a mesh's vertices are analysed up to valence {MAX_MESH_VALENCE}")
