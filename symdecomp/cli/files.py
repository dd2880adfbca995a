"""Writing the command line's output files so that an interrupted run never leaves a mix.

:func:`replace_owned_files` writes a whole set of files into a directory as one step: the new
directory is assembled next to the old one (the new files, plus the files of the old directory
that the command does not own) and then swapped in with one ``renameat2(RENAME_EXCHANGE)``
(Linux; elsewhere two renames, with the old copy kept until the new one is in place). Either
the old set or the new set is there, never some of each. :func:`atomic_write_text` does the
same for one file (temporary file and ``os.replace``).
"""

from __future__ import annotations

import ctypes
import os
import re
import shutil
import tempfile
from pathlib import Path

from symdecomp.errors import InvalidInputError

__all__ = ["check_output_directory", "replace_owned_files", "atomic_write_text"]


def check_output_directory(out, option: str = "--out") -> Path:
    """``out`` as a Path if it is (or can become) a writable directory; else one clear error."""
    text = os.fspath(out) if isinstance(out, (str, os.PathLike)) else None
    if text is None or not text.strip():
        raise InvalidInputError(f"{option}: the output directory must be a non-empty path")
    if "\0" in text:
        raise InvalidInputError(f"{option}: the path contains a NUL character")
    path = Path(text)
    parent = path.absolute().parent
    if path.exists() and not path.is_dir():
        raise InvalidInputError(f"{option} {text}: exists and is not a directory")
    if not parent.is_dir():
        raise InvalidInputError(f"{option} {text}: the parent directory {parent} does not exist")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InvalidInputError(f"{option} {text}: the parent directory {parent} is not writable")
    if path.exists() and not os.access(path, os.W_OK | os.X_OK):
        raise InvalidInputError(f"{option} {text}: the directory is not writable")
    return path


def atomic_write_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file in the same directory and ``os.replace``."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        _remove(tmp)
        raise


def replace_owned_files(out: Path, files: dict[str, str], owned: re.Pattern) -> list[Path]:
    """Make ``out`` hold exactly ``files`` among the names matching ``owned``, in one step.

    Files in ``out`` whose names do not match ``owned`` are carried over unchanged. Returns the
    paths written. Raises :class:`~symdecomp.errors.InvalidInputError` for an unusable ``out``.
    """
    out = check_output_directory(out)
    parent = out.absolute().parent
    staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=parent))
    try:
        if out.is_dir():
            shutil.copymode(out, staging)
            for entry in sorted(out.iterdir()):
                if owned.match(entry.name) and entry.is_file():
                    continue
                target = staging / entry.name
                if entry.is_dir() and not entry.is_symlink():
                    shutil.copytree(entry, target, symlinks=True)
                else:
                    shutil.copy2(entry, target, follow_symlinks=False)
        else:
            os.chmod(staging, 0o777 & ~_umask())
        for name, text in files.items():
            with open(staging / name, "w", encoding="utf-8", newline="\n") as fh:
                fh.write(text)
        _swap_in(staging, out)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    shutil.rmtree(staging, ignore_errors=True)  # now holds the old directory, if there was one
    return [out / name for name in files]


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
