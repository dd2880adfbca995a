"""Build the OpenSubdiv bridge (``osd_bridge.cpp``) into a shared library with the system g++.

Uses only the standard library, so CI can run it before the package is installed::

    python symdecomp/verify/opensubdiv/build.py [--force]   # prints the path of the built library

The library goes to :data:`BUILD_DIR` (:func:`build_dir`): ``$SYMDECOMP_BRIDGE_DIR`` if set; otherwise the
user's cache folder (``$XDG_CACHE_HOME`` or ``~/.cache``, then ``symdecomp/opensubdiv-bridge-<interface version>``),
for an installed package, an editable install and a checkout alike: a package never writes into its own folder.
The folder is trusted only if it is a real folder (not a symbolic link) of this user that no one
else may write to; a library there is loaded only with a stamp naming the interface version and
the hashes of the source and of the library itself: one without a matching stamp (stale,
truncated, altered) is rebuilt before it is ever loaded. The loader
(:func:`symdecomp.verify.opensubdiv.load_bridge`) also runs a self-test before trusting it.
It needs g++ and the OpenSubdiv headers and CPU library (Debian: ``libosd-dev``, ``libosdcpu3.5.0``).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = HERE / "osd_bridge.cpp"
HEADER = "opensubdiv/far/primvarRefiner.h"
#: The version of the bridge's C interface this package expects (``symdecomp_osd_bridge_version()``).
BRIDGE_VERSION = 2
#: The environment variable that chooses the build folder.
BUILD_DIR_VARIABLE = "SYMDECOMP_BRIDGE_DIR"


def build_dir() -> Path:
    """The folder of the compiled bridge (see the module docstring for the order)."""
    chosen = os.environ.get(BUILD_DIR_VARIABLE)
    if chosen:
        return Path(chosen).absolute()
    cache = os.environ.get("XDG_CACHE_HOME", "")
    cache = Path(cache) if os.path.isabs(cache) else Path.home() / ".cache"  # a relative XDG path is ignored (the spec)
    return cache / "symdecomp" / f"opensubdiv-bridge-{BRIDGE_VERSION}"


BUILD_DIR = build_dir()
LIBRARY = BUILD_DIR / "libsymdecomp_osd.so"


# Not in symdecomp.errors: this script runs stand-alone with the standard library only (before the
# package is installed); the loader turns it into BridgeUnavailableError.
class BridgeBuildError(RuntimeError):
    """g++ or OpenSubdiv is missing, or compiling the bridge failed."""


def compiler() -> str | None:
    """The C++ compiler to use (``$CXX`` or ``g++``), if it is on the path."""
    return shutil.which(os.environ.get("CXX", "g++"))


def headers_present(cxx: str | None = None) -> bool:
    """Whether the compiler finds the OpenSubdiv headers."""
    cxx = cxx or compiler()
    if cxx is None:
        return False
    probe = subprocess.run(
        [cxx, "-x", "c++", "-std=c++14", "-fsyntax-only", "-"],
        input=f"#include <{HEADER}>\n",
        capture_output=True,
        text=True,
    )
    return probe.returncode == 0


#: Records what the library in ``BUILD_DIR`` was built from (interface version and source hash).
STAMP = BUILD_DIR / "libsymdecomp_osd.stamp"
#: The command that rebuilds the bridge from scratch.
REBUILD_COMMAND = "python -m symdecomp.verify.opensubdiv.build --force"


def check_build_dir(create: bool = False) -> Path:
    """:data:`BUILD_DIR`, made (``create``) and checked: a folder, not a symbolic link, of this user, that
    no one else may write to (a library loaded from it runs in this process). Raises :class:`BridgeBuildError`."""
    folder = BUILD_DIR
    if create:
        try:
            folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        except FileExistsError:  # a file or a link in its place: refused below
            pass
        except OSError as exc:
            raise BridgeBuildError(f"cannot create the bridge's build folder {folder} ({exc.strerror or exc}); "
                                   f"set {BUILD_DIR_VARIABLE} to a writable folder") from None
    try:
        info = os.lstat(folder)
    except OSError as exc:
        raise BridgeBuildError(f"the bridge's build folder {folder} is missing ({exc.strerror or exc})") from None
    problem = ("is not a folder" if not stat.S_ISDIR(info.st_mode)
               else "belongs to another user" if hasattr(os, "getuid") and info.st_uid != os.getuid()
               else "may be written by other users" if info.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
               else None)
    if problem:
        raise BridgeBuildError(f"the bridge's build folder {folder} {problem}: not trusted; "
                               f"set {BUILD_DIR_VARIABLE} to a folder of your own")
    return folder


def _fingerprint(library: Path) -> str:
    source = hashlib.sha256(SOURCE.read_bytes()).hexdigest()
    built = hashlib.sha256(library.read_bytes()).hexdigest()
    return f"version {BRIDGE_VERSION}\nsource sha256 {source}\nlibrary sha256 {built}\n"


def is_current() -> bool:
    """Whether the library exists, whole, built from this source for this interface version.

    The stamp holds the library's own hash: a truncated or altered library is never loaded
    (loading a truncated shared library can crash the process, not just fail).
    """
    try:
        check_build_dir()
        return LIBRARY.is_file() and STAMP.read_text() == _fingerprint(LIBRARY)
    except (OSError, BridgeBuildError):
        return False


def build(force: bool = False) -> Path:
    """Compile the bridge (unless a current build exists) and return the library's path.

    The library and its stamp are each written to a temporary name and renamed, so a
    concurrent loader never sees half a file, and an interrupted build leaves no stamp that
    vouches for a library it did not finish.
    """
    if not force and is_current():
        return LIBRARY
    check_build_dir(create=True)
    cxx = compiler()
    if cxx is None:
        raise BridgeBuildError("no C++ compiler: install g++ (Debian: apt-get install g++), or set CXX")
    if not headers_present(cxx):
        raise BridgeBuildError(f"the OpenSubdiv headers (<{HEADER}>) are not installed: "
                               "apt-get install libosd-dev libosdcpu3.5.0")
    fd, tmp = tempfile.mkstemp(suffix=".so", dir=BUILD_DIR)
    os.close(fd)
    cmd = [cxx, "-O2", "-std=c++14", "-shared", "-fPIC", str(SOURCE), "-o", tmp, "-losdCPU"]
    try:
        result = subprocess.run(cmd, capture_output=True, text=True)
        if result.returncode != 0:
            raise BridgeBuildError(f"compiling the OpenSubdiv bridge failed: {' '.join(cmd)}: "
                                   + " ".join(result.stderr.split())[:500])
        STAMP.unlink(missing_ok=True)
        os.replace(tmp, LIBRARY)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    fd, tmp = tempfile.mkstemp(suffix=".stamp", dir=BUILD_DIR)
    with os.fdopen(fd, "w") as fh:
        fh.write(_fingerprint(LIBRARY))
    os.replace(tmp, STAMP)
    return LIBRARY


if __name__ == "__main__":
    try:
        print(build(force="--force" in sys.argv[1:]))
    except BridgeBuildError as exc:
        print(f"build.py: {exc}", file=sys.stderr)
        sys.exit(1)
