"""The tests are grouped like the package: one folder per layer, so a change in one layer shows which tests are its own.

``tests/core/`` holds the tests of the top-level modules (errors, symbols, expressions, validate, parallel), one
folder per subpackage holds that layer's tests (``tests/algebra/``, ..., ``tests/cli/``), and ``tests/project/`` the
whole-project checks. The folders are derived from the package, so a new layer needs its test folder and a test file
added at the top level or in an unknown folder fails here.
"""

import pathlib

from tests.project.test_layers import LAYERS, PACKAGE

TESTS = pathlib.Path(__file__).resolve().parents[1]

#: Folders under tests/ that hold data, not tests: the scheme files read by tests of several layers.
DATA_FOLDERS = {"corpus"}

#: Files allowed at the top of tests/ (the test modules live in the layer folders).
TOP_FILES = {"__init__.py", "README.md"}


def layer_folders(package: pathlib.Path) -> set[str]:
    """The test folders the package asks for: ``core`` for its top-level modules, one per subpackage, ``project``."""
    subpackages = {p.parent.name for p in package.glob("*/__init__.py")}
    modules = {p.stem for p in package.glob("*.py")} - {"__init__", "__main__"}
    assert modules and subpackages, f"no layers found in {package}"
    return {"core", "project"} | subpackages


def misplaced(tests: pathlib.Path, folders: set[str]) -> list[str]:
    """What breaks the grouping: unknown folders, layer folders that are not packages, files outside the layers."""
    found = {p.name for p in tests.iterdir() if p.is_dir() and p.name != "__pycache__" and not p.name.startswith(".")}
    problems = [f"{name}/ is not a layer folder" for name in sorted(found - folders - DATA_FOLDERS)]
    problems += [f"{name}/ is missing" for name in sorted(folders - found)]
    problems += [f"{name}/ has no __init__.py" for name in sorted(folders & found) if not (tests / name / "__init__.py").is_file()]
    problems += [f"{p.name} belongs in a layer folder" for p in sorted(tests.iterdir()) if p.is_file() and p.name not in TOP_FILES]
    for path in sorted(tests.rglob("*.py")):
        rel = path.relative_to(tests)
        if len(rel.parts) > 1 and (len(rel.parts) != 2 or rel.parts[0] not in folders):
            problems.append(f"{rel} is not directly in a layer folder")
    return problems


def test_the_layer_folders_are_the_layers_of_the_package():
    """Every layer of the import order (tests/project/test_layers.py) is a top-level module or a subpackage."""
    folders = layer_folders(PACKAGE)
    core = [name for name in LAYERS if (PACKAGE / f"{name}.py").is_file()]
    assert set(core) == {p.stem for p in PACKAGE.glob("*.py")} - {"__init__", "__main__"}
    assert core and set(LAYERS) - set(core) == folders - {"core", "project"}


def test_every_test_file_lives_in_a_layer_folder():
    assert misplaced(TESTS, layer_folders(PACKAGE)) == []


def test_the_grouping_check_can_fail(tmp_path):
    package = tmp_path / "pkg"
    (package / "algebra").mkdir(parents=True)
    (package / "algebra" / "__init__.py").write_text("")
    (package / "errors.py").write_text("")
    tests = tmp_path / "tests"
    for name in ("core", "algebra", "misc", "corpus"):
        (tests / name).mkdir(parents=True)
    (tests / "core" / "__init__.py").write_text("")
    (tests / "core" / "test_ok.py").write_text("")
    (tests / "test_top.py").write_text("")
    (tests / "misc" / "test_where.py").write_text("")
    (tests / "corpus" / "helper.py").write_text("")
    (tests / "core" / "deeper").mkdir()
    (tests / "core" / "deeper" / "test_deep.py").write_text("")
    assert misplaced(tests, layer_folders(package)) == [
        "misc/ is not a layer folder",
        "project/ is missing",
        "algebra/ has no __init__.py",
        "test_top.py belongs in a layer folder",
        "core/deeper/test_deep.py is not directly in a layer folder",
        "corpus/helper.py is not directly in a layer folder",
        "misc/test_where.py is not directly in a layer folder",
    ]
