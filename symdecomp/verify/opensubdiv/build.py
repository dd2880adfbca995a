"""Build the OpenSubdiv bridge (``osd_bridge.cpp``) into a shared library with the system g++.

Uses only the standard library, so CI can run it before the package is installed::

    python symdecomp/verify/opensubdiv/build.py        # prints the path of the built library

The library goes to ``_build/`` next to this file (ignored by git). It needs g++ and the
OpenSubdiv headers and CPU library (Debian: ``libosd-dev``, ``libosdcpu3.5.0``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = HERE / "osd_bridge.cpp"
BUILD_DIR = HERE / "_build"
LIBRARY = BUILD_DIR / "libsymdecomp_osd.so"
HEADER = "opensubdiv/far/primvarRefiner.h"


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


def build(force: bool = False) -> Path:
    """Compile the bridge (unless an up-to-date build exists) and return the library's path."""
    if not force and LIBRARY.exists() and LIBRARY.stat().st_mtime >= SOURCE.stat().st_mtime:
        return LIBRARY
    cxx = compiler()
    if cxx is None:
        raise BridgeBuildError("no C++ compiler: install g++ (or set CXX)")
    if not headers_present(cxx):
        raise BridgeBuildError(f"the OpenSubdiv headers (<{HEADER}>) are not installed: install libosd-dev")
    BUILD_DIR.mkdir(exist_ok=True)
    # Build to a temporary name and rename, so a concurrent loader never sees half a file.
    fd, tmp = tempfile.mkstemp(suffix=".so", dir=BUILD_DIR)
    os.close(fd)
    cmd = [cxx, "-O2", "-std=c++14", "-shared", "-fPIC", str(SOURCE), "-o", tmp, "-losdCPU"]
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        os.unlink(tmp)
        raise BridgeBuildError(f"compiling the OpenSubdiv bridge failed:\n{' '.join(cmd)}\n{result.stderr}")
    os.replace(tmp, LIBRARY)
    return LIBRARY


if __name__ == "__main__":
    try:
        print(build(force="--force" in sys.argv[1:]))
    except BridgeBuildError as exc:
        print(f"build.py: {exc}", file=sys.stderr)
        sys.exit(1)
