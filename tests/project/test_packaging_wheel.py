"""The package as it is distributed: one version, everything it reads at run time declared as package
data, and (slow) the sdist and wheel built from a copy of this tree hold exactly the package: every
module and data file, no compiled bridge, no tests. ``.ci/package.sh`` installs the wheel and runs it."""

from __future__ import annotations

import ast
import fnmatch
import re
import shutil
import subprocess
import sys
import tarfile
import tomllib
import zipfile
from pathlib import Path

import pytest

import symdecomp

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "symdecomp"
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
#: What building the bridge or running Python leaves in the package folder; never distributed.
LOCAL = ("_build", "__pycache__")


def _local(path: Path) -> bool:
    return any(part in LOCAL for part in path.relative_to(PACKAGE).parts)


def _modules() -> set[str]:
    return {p.relative_to(ROOT).as_posix() for p in PACKAGE.rglob("*.py") if not _local(p)}


def _data_files() -> set[str]:
    return {p.relative_to(ROOT).as_posix() for p in PACKAGE.rglob("*") if p.is_file() and p.suffix not in (".py", ".pyc")
            and not _local(p)}


def test_one_version_source():
    """pyproject.toml has no version of its own: it reads symdecomp.__version__, one literal assignment."""
    project = PYPROJECT["project"]
    assert "version" not in project and "version" in project["dynamic"]
    assert PYPROJECT["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "symdecomp.__version__"}
    tree = ast.parse((PACKAGE / "__init__.py").read_text(encoding="utf-8"))
    values = [node.value for node in tree.body if isinstance(node, ast.Assign)
              and any(isinstance(t, ast.Name) and t.id == "__version__" for t in node.targets)]
    assert len(values) == 1 and isinstance(values[0], ast.Constant)  # read by setuptools without importing the package
    assert values[0].value == symdecomp.__version__
    assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", symdecomp.__version__)
    assert PYPROJECT["project"]["license"] == "MIT"  # an SPDX expression, not the deprecated table


def test_the_license_is_the_one_pyproject_names():
    """MIT, held by the symdecomp authors (as pyproject.toml's authors); no license classifier beside the expression."""
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License\n\nCopyright (c) the symdecomp authors\n")
    assert "THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND" in text
    project = PYPROJECT["project"]
    assert project["license-files"] == ["LICENSE"] and project["authors"] == [{"name": "the symdecomp authors"}]
    assert not [c for c in project["classifiers"] if c.startswith("License ::")]  # PEP 639: the expression says it
    assert (PACKAGE / "py.typed").is_file() and "py.typed" in PYPROJECT["tool"]["setuptools"]["package-data"]["symdecomp"]


def test_the_version_the_program_prints(capsys):
    from symdecomp.cli import main

    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"symdecomp {symdecomp.__version__}\n"


def test_every_data_file_is_declared():
    """A file the package reads at run time (not a module) is in the wheel only if pyproject.toml names it."""
    declared = PYPROJECT["tool"]["setuptools"]["package-data"]
    undeclared = []
    for path in sorted(_data_files()):
        parts = path.split("/")  # a package's pattern may name a data folder inside it ("zoo/*.toml")
        candidates = [(".".join(parts[:i]), "/".join(parts[i:])) for i in range(len(parts) - 1, 0, -1)]
        if not any(fnmatch.fnmatch(rel, pattern) and pattern.count("/") == rel.count("/")
                   for package, rel in candidates for pattern in declared.get(package, [])):
            undeclared.append(path)
    assert undeclared == []
    assert {"symdecomp/output/preamble.tex", "symdecomp/output/json_schema.json", "symdecomp/verify/opensubdiv/osd_bridge.cpp"} <= _data_files()


def _source_copy(target: Path) -> Path:
    """This tree's package, pyproject.toml and README, plus a compiled bridge and a test file that must stay out."""
    shutil.copytree(PACKAGE, target / "symdecomp", ignore=shutil.ignore_patterns(*LOCAL))
    for name in ("pyproject.toml", "README.md", "MANIFEST.in", "LICENSE"):
        shutil.copy(ROOT / name, target / name)
    built = target / "symdecomp" / "verify" / "opensubdiv" / "_build"
    built.mkdir()
    (built / "libsymdecomp_osd.so").write_bytes(b"\x7fELF not a library")
    (built / "libsymdecomp_osd.stamp").write_text("version 1\n")
    (target / "tests").mkdir()
    (target / "tests" / "test_something.py").write_text("def test_nothing():\n    assert 1 + 1 == 2\n")
    return target


@pytest.mark.slow
def test_the_wheel_and_the_sdist_hold_the_package_and_nothing_else(tmp_path):
    pytest.importorskip("build", reason="needs the 'build' package (pip install 'symdecomp[test]')")
    source, dist = _source_copy(tmp_path / "src"), tmp_path / "dist"
    built = subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--outdir", str(dist), str(source)],
                           capture_output=True, text=True, timeout=600)
    assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    (wheel,), (sdist,) = dist.glob("*.whl"), dist.glob("*.tar.gz")
    assert wheel.name == f"symdecomp-{symdecomp.__version__}-py3-none-any.whl"
    names = set(zipfile.ZipFile(wheel).namelist())
    info = f"symdecomp-{symdecomp.__version__}.dist-info/"
    assert {n for n in names if not n.startswith(info)} == _modules() | _data_files()
    metadata = zipfile.ZipFile(wheel).read(info + "METADATA").decode()
    assert "License-Expression: MIT" in metadata and f"Version: {symdecomp.__version__}" in metadata
    assert "License-File: LICENSE" in metadata and "Classifier: Typing :: Typed" in metadata
    assert zipfile.ZipFile(wheel).read(info + "licenses/LICENSE") == (ROOT / "LICENSE").read_bytes()
    assert "symdecomp/py.typed" in names  # PEP 561: users' type checkers read the annotations
    assert "symdecomp = symdecomp.cli:entry" in zipfile.ZipFile(wheel).read(info + "entry_points.txt").decode()
    with tarfile.open(sdist) as archive:
        members = {m.split("/", 1)[1] for m in archive.getnames() if "/" in m}
    assert _modules() | _data_files() | {"LICENSE"} <= members
    assert not [m for m in members if "_build" in m or m.endswith((".so", ".stamp", ".pyc")) or m.startswith("tests/")]
    pytest.importorskip("twine", reason="needs the 'twine' package (pip install 'symdecomp[test]')")
    checked = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", str(wheel), str(sdist)],
                             capture_output=True, text=True, timeout=120)
    assert checked.returncode == 0, checked.stdout + checked.stderr
