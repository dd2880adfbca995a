"""Reading a large mesh shows progress (issue 31): the line-by-line loops of the readers (an ASCII PLY's faces, an
OBJ read line by line, an OFF file) report through the command line's one progress display, a bar with rate and time left on
a terminal and plain lines otherwise; ``--quiet`` shows nothing. (The memory estimated before a file is read, from its
size and a PLY header's counts, is tested in ``tests/schemes/test_meshread.py``.)"""

import re

import pytest

from symdecomp.cli import main
from symdecomp.cli import progress as progress_module
from symdecomp.schemes.meshformats import decode_mesh, encode_mesh
from tests.analysis.test_mesh_limits import N, grid


def ascii_ply() -> bytes:
    """The 5 x 5 grid of quads as an ASCII PLY (25 face lines)."""
    mesh = grid()
    head = (f"ply\nformat ascii 1.0\nelement vertex {len(mesh.points)}\nproperty double x\nproperty double y\n"
            f"property double z\nelement face {len(mesh.faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    rows = [" ".join(str(float(c)) for c in p) for p in mesh.points] + [f"4 {' '.join(map(str, f))}" for f in mesh.faces]
    return (head + "\n".join(rows) + "\n").encode()


def recorded(data: bytes, fmt: str) -> list:
    seen = []

    def progress(items, total, what):
        items = list(items)
        seen.append((what, total, len(items)))
        return items

    mesh = decode_mesh(data, fmt, progress=progress)
    assert len(mesh.faces) == N * N
    return seen


def test_each_line_by_line_reader_reports_its_loop_with_its_total():
    obj = encode_mesh(grid(), "obj") + b"v 0 0 0 1\n"  # a vertex weight: the line-by-line reader
    lines = obj.count(b"\n") + 1  # split on newlines: the last, empty piece is a line too
    assert recorded(obj, "obj") == [("reading lines", lines, lines)]
    off = encode_mesh(grid(), "off")
    assert recorded(off, "off") == [("reading lines", off.count(b"\n") + 1, off.count(b"\n") + 1)]
    assert recorded(ascii_ply(), "ply") == [("reading faces", N * N, N * N)]
    assert recorded(encode_mesh(grid(), "ply"), "ply") == []  # binary: one numpy pass, nothing to report


@pytest.fixture
def mesh_file(tmp_path):
    path = tmp_path / "grid.ply"
    path.write_bytes(ascii_ply())
    return path


def test_a_terminal_gets_a_bar_with_rate_and_time_left_while_reading(mesh_file, capsys, monkeypatch):
    monkeypatch.setattr(progress_module, "_is_terminal", lambda stream: True)
    assert main(["inspect", str(mesh_file)]) == 0
    err = capsys.readouterr().err
    assert "inspect reading faces:" in err and f"| {N * N}/{N * N} [" in err and "it/s]" in err


def test_a_pipe_gets_plain_lines_and_quiet_gets_none(mesh_file, capsys, monkeypatch):
    monkeypatch.setattr(progress_module, "PLAIN_INTERVAL", 0.0)  # a line after every face, as a long read would
    assert main(["inspect", str(mesh_file)]) == 0
    lines = [line for line in capsys.readouterr().err.splitlines() if line.startswith("inspect reading faces")]
    assert len(lines) == N * N and all(progress_module.PLAIN_LINE.fullmatch(line) for line in lines)
    assert re.match(rf"inspect reading faces: {N * N}/{N * N} \(100 %\), ", lines[-1])
    assert main(["inspect", str(mesh_file), "--quiet"]) == 0
    assert "reading" not in capsys.readouterr().err

