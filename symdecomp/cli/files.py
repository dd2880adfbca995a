"""Writing the command line's output files: checked before the work starts, never left half written.

Every output path is checked first (:func:`check_output_file`, :func:`check_output_directory`):
a bad path is bad input, one line naming the option (exit code 2), before anything is computed.
A write that fails later (a full disk, an I/O error) raises
:class:`~symdecomp.errors.OutputWriteError` (exit code 1).

How a file is written (:func:`output_stream`, :func:`write_output_file`): a symbolic link is
followed and its target written (the link stays); a character device or a FIFO (``/dev/null``,
``/dev/stdout``, a named pipe) is opened and written in place, never renamed over; a regular file
is written through a temporary file in its directory and ``os.replace``, so that a reader sees the
old file or the new one. A new file gets the permissions the umask gives; a replaced file keeps
its mode. Other kinds of file (a block device, a socket) are refused.

A FIFO is opened when it is checked, before the work, without blocking: if no reader has it open
within :data:`FIFO_WAIT` seconds, that is bad input (start the reader first); otherwise the open end
is held until the output is written into it (closing it would end the reader's input), so a command
never computes and then blocks on a FIFO nobody reads. :func:`release_held` closes what a command
checked and did not write (the command line calls it when a command ends).

:func:`write_output_files` writes several files (a document and its figures) all or nothing: every
regular file is written to a temporary file first, and only when all of them are complete are they
renamed into place; a failure (a full disk) leaves every old file as it was and no new one.

:func:`replace_owned_files` writes a whole set of files into a directory as one step: the new
directory is assembled next to the old one (the new files, plus the files of the old directory
that the command does not own) and then swapped in with one ``renameat2(RENAME_EXCHANGE)``
(Linux; elsewhere two renames, with the old copy kept until the new one is in place). Either
the old set or the new set is there, never some of each. A symbolic link to a directory is
followed: the directory it points to is replaced, the link stays.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import os
import re
import shutil
import stat
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path

from symdecomp.errors import InvalidInputError, OutputWriteError

__all__ = ["check_output_directory", "check_output_file", "output_stream", "write_output_file", "write_output_files",
           "replace_owned_files", "release_held", "FIFO_WAIT"]

#: Seconds a FIFO given as an output may wait for its reader when it is checked.
FIFO_WAIT = 2.0

#: FIFOs opened when checked, by their resolved path: the write end, held until the output is written.
_HELD: dict[str, int] = {}

#: The kinds of existing file written in place (opened and streamed into, never replaced).
_STREAMED = {stat.S_IFCHR: "a character device", stat.S_IFIFO: "a FIFO"}
_KINDS = {stat.S_IFBLK: "a block device", stat.S_IFSOCK: "a socket", stat.S_IFDIR: "a directory"}


def _path_text(out, option: str, what: str) -> str:
    text = os.fspath(out) if isinstance(out, (str, os.PathLike)) else None
    if text is None or not text.strip():
        raise InvalidInputError(f"{option}: the output {what} must be a non-empty path")
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if "\0" in text:
        raise InvalidInputError(f"{option}: the path contains a NUL character")
    return text


def _target(text: str) -> Path:
    """Where writing ``text`` lands: the path with every symbolic link followed (a dangling one: where it points)."""
    return Path(os.path.realpath(text))


def _stat(target: Path, option: str, text: str) -> os.stat_result | None:
    try:
        return os.stat(target)
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise InvalidInputError(f"{option} {text}: {exc.strerror or exc}") from None


def _probe(folder: Path, option: str, text: str) -> None:
    """Create and remove a directory in ``folder``: the only test of writability that also holds for root
    and for read-only file systems."""
    if not folder.is_dir():
        raise InvalidInputError(f"{option} {text}: the parent directory {folder} does not exist")
    try:
        os.rmdir(tempfile.mkdtemp(prefix=".symdecomp-probe-", dir=folder))
    except OSError as exc:
        raise InvalidInputError(f"{option} {text}: the parent directory {folder} is not writable ({exc.strerror or exc})") from None


def check_output_file(out, option: str = "--out") -> Path:
    """``out`` as a Path if an output file can be written there (module docstring); else one clear error."""
    text = _path_text(out, option, "file")
    target = _target(text)
    st = _stat(target, option, text)
    if st is not None:
        kind = stat.S_IFMT(st.st_mode)
        if kind in _STREAMED:
            if not os.access(target, os.W_OK):
                raise InvalidInputError(f"{option} {text}: {_STREAMED[kind]} that is not writable")
            if kind == stat.S_IFIFO:
                _hold_fifo(target, option, text)
            return Path(text)
        if kind != stat.S_IFREG:
            raise InvalidInputError(f"{option} {text}: is {_KINDS.get(kind, 'not a regular file')}; give a regular file, "
                                    "a character device or a FIFO")
    _probe(target.parent, option, text)
    return Path(text)


def _hold_fifo(target: Path, option: str, text: str) -> None:
    """Open the FIFO ``target`` for writing without blocking, waiting up to :data:`FIFO_WAIT` s for a reader; hold it."""
    key = os.fspath(target)
    if key in _HELD:
        return
    end = time.monotonic() + FIFO_WAIT
    while True:
        try:
            fd = os.open(target, os.O_WRONLY | os.O_NONBLOCK)
            break
        except OSError as exc:
            if exc.errno != errno.ENXIO:  # ENXIO: no reader yet
                raise InvalidInputError(f"{option} {text}: {exc.strerror or exc}") from None
        if time.monotonic() > end:
            raise InvalidInputError(f"{option} {text}: a FIFO that no process reads (waited {FIFO_WAIT:g} s); "
                                    "start its reader first")
        time.sleep(0.02)
    os.set_blocking(fd, True)  # the writes wait for the reader, as into any pipe
    _HELD[key] = fd


def release_held() -> None:
    """Close the FIFOs checked and not written (their readers then see the end of their input)."""
    while _HELD:
        with contextlib.suppress(OSError):
            os.close(_HELD.popitem()[1])


def check_output_directory(out, option: str = "--out") -> Path:
    """``out`` as a Path if it is (or can become) a writable directory; else one clear error."""
    text = _path_text(out, option, "directory")
    target = _target(text)
    st = _stat(target, option, text)
    if st is not None and not stat.S_ISDIR(st.st_mode):
        raise InvalidInputError(f"{option} {text}: exists and is not a directory")
    _probe(target.parent, option, text)
    if st is not None and not os.access(target, os.R_OK | os.W_OK | os.X_OK):
        raise InvalidInputError(f"{option} {text}: the directory is not writable")
    return Path(text)


@contextlib.contextmanager
def output_stream(out, option: str = "--out"):
    """A binary file object writing the output file ``out`` as the module docstring says.

    Check ``out`` first (:func:`check_output_file`). An ``OSError`` while writing becomes
    :class:`~symdecomp.errors.OutputWriteError`; a regular file is then left as it was.
    """
    target = _target(_path_text(out, option, "file"))
    try:
        st = _stat(target, option, os.fspath(out))
        if st is not None and stat.S_IFMT(st.st_mode) in _STREAMED:
            if stat.S_ISFIFO(st.st_mode):
                _hold_fifo(target, option, os.fspath(out))  # checked already: the end held then; else opened now
            held = _HELD.pop(os.fspath(target), None)
            with os.fdopen(held if held is not None else os.open(target, os.O_WRONLY), "wb") as fh:
                yield fh
            return
        mode = stat.S_IMODE(st.st_mode) if st is not None else 0o666 & ~_umask()
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
        try:
            with os.fdopen(fd, "wb") as fh:
                yield fh
                fh.flush()
                os.fsync(fh.fileno())
            os.chmod(tmp, mode)
            os.replace(tmp, target)
        except BaseException:
            _remove(tmp)
            raise
    except OSError as exc:
        if isinstance(exc, OutputWriteError):
            raise
        raise OutputWriteError(f"{option} {os.fspath(out)}: cannot write ({exc.strerror or exc})") from None


def write_output_file(out, content: bytes | str | Iterable[bytes | str], option: str = "--out") -> int:
    """Write ``content`` (``str``: UTF-8), or its pieces as they come, to the output file ``out``
    (:func:`output_stream`); return the number of bytes written. An error while the pieces are
    made leaves a regular file as it was."""
    written = 0
    with output_stream(out, option) as fh:
        for piece in [content] if isinstance(content, (bytes, str)) else content:
            raw = piece.encode("utf-8") if isinstance(piece, str) else piece
            fh.write(raw)
            written += len(raw)
    return written


def write_output_files(files: dict, option: str = "--out") -> int:
    """Write ``files`` (output path -> ``bytes`` or ``str``) all or nothing (module docstring); return the bytes written.

    Check every path first (:func:`check_output_file`). The regular files are staged as temporary files next
    to their targets and renamed into place only when every one is complete; a FIFO or character device
    among them is written last, in place. An ``OSError`` becomes :class:`~symdecomp.errors.OutputWriteError`,
    with no new regular file left.
    """
    staged, streamed, written, failing = [], [], 0, None
    try:
        try:
            for out, content in files.items():
                failing = out
                raw = content.encode("utf-8") if isinstance(content, str) else content
                target = _target(_path_text(out, option, "file"))
                st = _stat(target, option, os.fspath(out))
                if st is not None and stat.S_IFMT(st.st_mode) in _STREAMED:
                    streamed.append((out, raw))
                    continue
                fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
                staged.append((tmp, target))
                with os.fdopen(fd, "wb") as fh:
                    fh.write(raw)
                    fh.flush()
                    os.fsync(fh.fileno())
                os.chmod(tmp, stat.S_IMODE(st.st_mode) if st is not None else 0o666 & ~_umask())
                written += len(raw)
            while staged:
                tmp, failing = staged[0]
                os.replace(tmp, failing)
                staged.pop(0)
        finally:
            for tmp, _ in staged:
                _remove(tmp)
    except OSError as exc:
        raise OutputWriteError(f"{option} {os.fspath(failing)}: cannot write ({exc.strerror or exc})") from None
    for out, raw in streamed:
        written += write_output_file(out, raw, option)
    return written


def replace_owned_files(out: Path, files: dict[str, str | bytes], owned: re.Pattern, option: str = "--out") -> list[Path]:
    """Make ``out`` hold exactly ``files`` (text, written as UTF-8, or bytes) among the names matching ``owned``, in one step.

    Files in ``out`` whose names do not match ``owned`` are carried over unchanged. Returns the
    paths written. Raises :class:`~symdecomp.errors.InvalidInputError` for an unusable ``out``
    and :class:`~symdecomp.errors.OutputWriteError` when writing fails (the old files stay).
    """
    out = check_output_directory(out, option)
    target = _target(os.fspath(out))  # a link to a directory: the directory is replaced, the link stays
    try:
        staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=target.parent))
        try:
            _assemble(staging, target, files, owned)
            _swap_in(staging, target)
        except BaseException:
            shutil.rmtree(staging, ignore_errors=True)
            raise
        shutil.rmtree(staging, ignore_errors=True)  # now holds the old directory, if there was one
    except OSError as exc:
        raise OutputWriteError(f"{option} {out}: cannot write ({exc.strerror or exc})") from None
    return [out / name for name in files]


def _assemble(staging: Path, target: Path, files: dict[str, str | bytes], owned: re.Pattern) -> None:
    """Fill ``staging`` with ``files`` and the entries of ``target`` (if it exists) that are not owned."""
    if target.is_dir():
        shutil.copymode(target, staging)
        for entry in sorted(target.iterdir()):
            if owned.match(entry.name) and entry.is_file():
                continue
            copy = staging / entry.name
            if entry.is_dir() and not entry.is_symlink():
                shutil.copytree(entry, copy, symlinks=True)
            else:
                shutil.copy2(entry, copy, follow_symlinks=False)
    else:
        os.chmod(staging, 0o777 & ~_umask())
    for name, content in files.items():
        if isinstance(content, bytes):
            (staging / name).write_bytes(content)
            continue
        with open(staging / name, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(content)


def _swap_in(staging: Path, out: Path) -> None:
    if not out.exists():
        os.rename(staging, out)
        return
    if _exchange(staging, out):
        return
    old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-", dir=out.absolute().parent))
    os.rmdir(old)
    os.rename(out, old)
    try:
        os.rename(staging, out)
    except BaseException:
        os.rename(old, out)
        raise
    os.rename(old, staging)


def _exchange(a: Path, b: Path) -> bool:
    """Atomically exchange two paths with ``renameat2(RENAME_EXCHANGE)``; False if unsupported."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    renameat2.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    rc = renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange)
    return rc == 0


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _remove(path) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass
