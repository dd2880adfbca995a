"""Output paths: checked before the work starts; special files written in place; links followed; exit codes."""

import errno
import os
import socket
import stat
import struct
import threading
from pathlib import Path

import pytest

import symdecomp.cli.derive_cmd as derive_cmd
import symdecomp.output.every_n_derivations as every_n_derivations
from symdecomp.cli import main
from symdecomp.cli.files import check_output_file, output_stream, write_output_file
from symdecomp.errors import InvalidInputError, OutputWriteError
from symdecomp.output.evaldata import read_binary

EVALDATA = ["evaldata", "--n", "3:4"]


def _nmax(raw: bytes) -> int:
    return struct.unpack_from("<i", raw, 0)[0]


@pytest.fixture
def umask_022():
    old = os.umask(0o022)
    yield
    os.umask(old)


@pytest.fixture
def no_claims(monkeypatch):
    """derive without computing: the document of no claims, no zoo and no proofs for every valence (the writing is what these tests are about)."""
    monkeypatch.setattr(derive_cmd, "all_claims", lambda: [])
    monkeypatch.setattr(derive_cmd, "zoo_files", lambda show_progress=False: {})
    monkeypatch.setattr(every_n_derivations, "every_n_files", lambda: {})


def _device_copy(path: Path, device: str) -> None:
    """``path``: a character device like ``device`` (needs root and a system that allows mknod)."""
    if not os.path.exists(device) or os.geteuid() != 0:
        pytest.skip(f"needs root and {device}")
    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.stat(device).st_rdev)
    except OSError as exc:
        pytest.skip(f"mknod refused: {exc.strerror}")


# --- special files and links --------------------------------------------------------------------


def test_evaldata_streams_into_a_fifo_and_leaves_it_a_fifo(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    keep = tmp_path / "pipe-inode"
    os.link(fifo, keep)  # to release the reader should the FIFO be renamed over
    received = []
    reader = threading.Thread(target=lambda: received.append(Path(fifo).read_bytes()), daemon=True)
    reader.start()
    try:
        assert main([*EVALDATA, "--out", str(fifo)]) == 0
        reader.join(60)
        assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
        layout = 4 + 8 * sum((2 * n + 8) * (1 + (2 * n + 8) + 48) for n in (3, 4))  # Nmax, then per valence
        assert received and _nmax(received[0]) == 4 and len(received[0]) == layout
    finally:
        if reader.is_alive():
            os.close(os.open(keep, os.O_WRONLY | os.O_NONBLOCK))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe", "pipe-inode"]  # no temporary file left


def test_evaldata_into_a_character_device_writes_through_it(tmp_path):
    null = tmp_path / "null"
    _device_copy(null, "/dev/null")
    assert main([*EVALDATA, "--out", str(null)]) == 0
    st = os.lstat(null)
    assert stat.S_ISCHR(st.st_mode) and st.st_rdev == os.stat("/dev/null").st_rdev
    assert [p.name for p in tmp_path.iterdir()] == ["null"]


def test_evaldata_writes_through_a_symbolic_link(tmp_path, umask_022):
    real = tmp_path / "real.dat"
    real.write_bytes(b"old")
    real.chmod(0o640)
    link = tmp_path / "link.dat"
    link.symlink_to(real.name)
    assert main([*EVALDATA, "--out", str(link)]) == 0
    assert link.is_symlink() and os.readlink(link) == "real.dat"
    assert read_binary(real)[4].values.size == 16
    assert stat.S_IMODE(real.stat().st_mode) == 0o640  # a replaced file keeps its mode
    dangling = tmp_path / "dangling"
    dangling.symlink_to("made.dat")
    write_output_file(dangling, b"new")
    assert dangling.is_symlink() and (tmp_path / "made.dat").read_bytes() == b"new"
    assert stat.S_IMODE((tmp_path / "made.dat").stat().st_mode) == 0o644


def test_a_new_file_gets_the_permissions_of_the_umask(tmp_path, umask_022):
    out = tmp_path / "cc.dat"
    assert main([*EVALDATA, "--out", str(out)]) == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o644
    os.umask(0o027)
    write_output_file(tmp_path / "b.json", "{}\n")
    assert stat.S_IMODE((tmp_path / "b.json").stat().st_mode) == 0o640


def test_unwritable_kinds_of_file_are_refused_in_one_line(tmp_path):
    with pytest.raises(InvalidInputError, match="--out .*: is a directory"):
        check_output_file(tmp_path)
    sock = socket.socket(socket.AF_UNIX)
    try:
        sock.bind(str(tmp_path / "s"))
        with pytest.raises(InvalidInputError, match="is a socket"):
            check_output_file(tmp_path / "s")
    finally:
        sock.close()
    with pytest.raises(InvalidInputError, match="parent directory .* does not exist"):
        check_output_file(tmp_path / "no" / "x")
    (tmp_path / "file").write_text("x")
    with pytest.raises(InvalidInputError, match="Not a directory"):
        check_output_file(tmp_path / "file" / "x")


def test_derive_into_a_link_replaces_the_directory_behind_it(tmp_path, no_claims, capsys):
    real = tmp_path / "real"
    real.mkdir()
    (real / "notes.txt").write_text("mine")
    (real / "section-9.tex").write_text("stale")
    link = tmp_path / "link"
    link.symlink_to("real", target_is_directory=True)
    assert main(["derive", "--out", str(link), "--no-progress"]) == 0
    assert link.is_symlink() and os.readlink(link) == "real"
    assert sorted(p.name for p in real.iterdir()) == ["main.tex", "notes.txt"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "real"]  # no staging directory or link left


# --- checked before the work; exit codes ------------------------------------------------------


def test_derive_checks_its_default_directory_before_computing(tmp_path, monkeypatch, capsys):
    def computing():
        raise AssertionError("computed before the output directory was checked")

    monkeypatch.setattr(derive_cmd, "all_claims", computing)
    monkeypatch.chdir(tmp_path)
    Path("derivations").write_text("a file, not a directory")
    assert main(["derive"]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "symdecomp: error: --out derivations: exists and is not a directory"]
    assert main(["derive", "--out", "derivations/x"]) == 2
    assert "--out derivations/x" in capsys.readouterr().err


def test_evaldata_checks_its_output_before_computing(tmp_path, monkeypatch, capsys):
    import symdecomp.cli.evaldata_cmd as evaldata_cmd

    def computing(*args, **kwargs):
        raise AssertionError("computed before the output file was checked")

    monkeypatch.setattr(evaldata_cmd, "rounded_eigendata", computing)
    assert main([*EVALDATA, "--out", str(tmp_path)]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        f"symdecomp: error: --out {tmp_path}: is a directory; give a regular file, a character device or a FIFO"]


#: Every option that names an output, pointed at a place not even root can write (a directory in /proc),
#: with the step that would compute the output replaced by a failure: (argv, the function that does the work).
UNWRITABLE = "/proc/symdecomp-unwritable"
OUTPUTS = [
    (["derive", "--out", UNWRITABLE], "symdecomp.cli.derive_cmd.write_derivations"),
    (["evaldata", "--n", "3:128", "--out", UNWRITABLE + ".dat"], "symdecomp.cli.evaldata_cmd.rounded_eigendata"),
    (["report", "loop", "--n", "3:6", "--out", UNWRITABLE + ".html"], "symdecomp.output.report.build_report"),
    (["design", "--n", "5", "--normal", "0,0,1", "--out", UNWRITABLE + ".obj"], "symdecomp.analysis.design.design_ring"),
    (["tune", "5", "--region", "--plot", UNWRITABLE + ".png"], "symdecomp.verify.tuning_c1.certified_tuning_region"),
    (["inspect", str(Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"),
      "--figures", UNWRITABLE], "symdecomp.analysis.inspection.inspect_mesh"),
]


@pytest.mark.parametrize("argv, work", OUTPUTS, ids=[argv[0] for argv, _ in OUTPUTS])
def test_every_output_in_an_unwritable_place_is_refused_before_the_work(argv, work, monkeypatch, capsys):
    """Issue 24: ``derive --out`` to a place that cannot be written computed for minutes first. Every output option
    is checked before the work: /proc takes no new entry, for root either (a read-only directory would not stop root)."""
    if not os.path.isdir("/proc/self"):
        pytest.skip("needs Linux's /proc")
    module, name = work.rsplit(".", 1)
    monkeypatch.setattr(module + "." + name, lambda *a, **k: pytest.fail(f"{argv[0]}: the work started before the output was checked"))
    assert main(argv) == 2
    option = next(a for a in argv if a.startswith("--") and UNWRITABLE in argv[argv.index(a) + 1])
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"symdecomp: error: {option} {UNWRITABLE}") and "not writable" in err[0], err


def _full_disk(monkeypatch):
    def fsync(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "fsync", fsync)


def test_a_full_disk_is_exit_status_1_for_evaldata(tmp_path, monkeypatch, capsys):
    out = tmp_path / "cc.dat"
    out.write_bytes(b"old")
    _full_disk(monkeypatch)
    assert main([*EVALDATA, "--out", str(out)]) == 1
    assert capsys.readouterr().err.strip().splitlines() == [
        f"symdecomp: error: --out {out}: cannot write (No space left on device)"]
    assert out.read_bytes() == b"old" and [p.name for p in tmp_path.iterdir()] == ["cc.dat"]


def test_a_full_device_is_exit_status_1(tmp_path, capsys):
    full = tmp_path / "full"
    _device_copy(full, "/dev/full")
    assert main([*EVALDATA, "--out", str(full)]) == 1
    assert "No space left on device" in capsys.readouterr().err
    assert stat.S_ISCHR(os.lstat(full).st_mode)


def test_a_full_disk_is_exit_status_1_for_derive(tmp_path, monkeypatch, no_claims, capsys):
    import symdecomp.cli.files as files

    out = tmp_path / "d"
    assert main(["derive", "--out", str(out), "--no-progress"]) == 0
    before = (out / "main.tex").read_text()

    def swap(staging, target):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(files, "_swap_in", swap)
    capsys.readouterr()
    assert main(["derive", "--out", str(out), "--no-progress"]) == 1
    assert capsys.readouterr().err.strip().splitlines() == [
        f"symdecomp: error: --out {out}: cannot write (No space left on device)"]
    assert (out / "main.tex").read_text() == before and sorted(p.name for p in tmp_path.iterdir()) == ["d"]


def test_output_stream_raises_the_package_error_and_keeps_the_old_file(tmp_path, monkeypatch):
    out = tmp_path / "x.json"
    out.write_text("old")
    _full_disk(monkeypatch)
    with pytest.raises(OutputWriteError, match=r"--out .*x\.json: cannot write \(No space left on device\)"):
        with output_stream(out) as fh:
            fh.write(b"new")
    assert out.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["x.json"]
    assert issubclass(OutputWriteError, OSError)
