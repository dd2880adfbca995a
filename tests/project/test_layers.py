"""The package's folders are layers, and imports only go downwards (the map is in symdecomp/__init__.py)."""

import ast
import pathlib

import pytest

PACKAGE = pathlib.Path(__file__).resolve().parents[2] / "symdecomp"

#: Lowest first; a module may import from its own layer and the ones before it.
LAYERS = ["errors", "symbols", "expressions", "validate", "parallel", "algebra", "schemes", "analysis", "verify", "claims", "output", "cli"]


def _layer(module: str) -> int:
    parts = module.split(".")
    assert parts[0] == "symdecomp"
    if len(parts) == 1 or parts[1] in {"__init__", "__main__"}:
        return len(LAYERS)  # the package itself re-exports everything
    return LAYERS.index(parts[1])


def _imports(path: pathlib.Path):
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module and node.module.split(".")[0] == "symdecomp":
            yield node.lineno, node.module
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "symdecomp":
                    yield node.lineno, alias.name


MODULES = sorted(p for p in PACKAGE.rglob("*.py") if "_build" not in p.parts)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_only_go_downwards(path):
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    here = _layer(".".join(rel.parts))
    upward = [(line, module) for line, module in _imports(path) if module != "symdecomp" and _layer(module) > here]
    assert not upward, f"{rel} imports a higher layer: {upward}"


def test_relative_imports_stay_inside_their_folder():
    """Relative imports only reach siblings (``from .x``), so a module's layer is visible from its path."""
    offenders = []
    for path in MODULES:
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level > 1:
                offenders.append((str(path.relative_to(PACKAGE)), node.lineno))
    assert not offenders


def test_the_layer_check_can_fail(tmp_path):
    bad = tmp_path / "symdecomp" / "algebra" / "bad.py"
    bad.parent.mkdir(parents=True)
    bad.write_text("from symdecomp.analysis.spectrum import Spectrum\n")
    assert list(_imports(bad)) == [(1, "symdecomp.analysis.spectrum")]
    assert _layer("symdecomp.analysis.spectrum") > _layer("symdecomp.algebra.bad")


def _module_map(doc: str) -> list[str]:
    """The modules the map in a package docstring names: the table's first column names a top-level module or a
    folder (``name/``); a folder's row names its modules, relative to it, as ``double-quoted literals``."""
    import re

    lines = doc.splitlines()
    borders = [i for i, line in enumerate(lines) if re.fullmatch(r"=+ +=+", line)]
    assert len(borders) == 2, "the map is one table without a header"
    width = lines[borders[0]].index(" ")
    named, folder = [], None
    for line in lines[borders[0] + 1 : borders[1]]:
        head, text = line[:width].strip(), line[width:]
        if head:
            (first,) = re.findall(r"``([^`]+)``", head)
            folder = first.rstrip("/").replace("/", ".") if first.endswith("/") else None
            named.append(first.rstrip("/"))
        inside = re.findall(r"``([^`]+)``", text)
        assert folder is not None or not inside, f"a top-level module's row names modules: {inside}"
        named += [f"{folder}.{name}" for name in inside]
    return named


def _package_modules() -> set[str]:
    import pkgutil

    import symdecomp

    return {m.name.removeprefix("symdecomp.") for m in pkgutil.walk_packages(symdecomp.__path__, "symdecomp.")}


def test_the_module_map_names_every_module_once_and_nothing_else():
    import symdecomp

    named = _module_map(symdecomp.__doc__)
    assert sorted(n for n in set(named) if named.count(n) > 1) == []
    assert sorted(_package_modules() - set(named)) == [], "modules missing from the map in symdecomp/__init__.py"
    assert sorted(set(named) - _package_modules()) == [], "the map names modules that do not exist"


def test_the_module_map_check_can_fail():
    doc = "x\n\n========  ====\n``a``     one\n``b/``    ``c``, ``d``\n          and ``e``\n========  ====\n"
    assert _module_map(doc) == ["a", "b", "b.c", "b.d", "b.e"]
    with pytest.raises(AssertionError, match="top-level"):
        _module_map("========  ====\n``a``     ``x``\n========  ====\n")


def test_the_subpackages_point_to_the_one_map():
    """One map, not partial copies: a subpackage's docstring names none of its modules as a list and points to the root map."""
    import importlib
    import re

    for name in sorted(n for n in _package_modules() if (PACKAGE / n.replace(".", "/") / "__init__.py").exists()):
        doc = importlib.import_module(f"symdecomp.{name}").__doc__ or ""
        assert "module map" in doc and ":mod:`symdecomp`" in doc, name
        assert not re.search(r":mod:`\.\w", doc), f"symdecomp.{name} lists its modules again"
#: The names of the mesh kinds; only the lattice objects (``schemes/lattice.py``) may ask which one a scheme has.
MESH_KINDS = {"quad", "triangle"}
LATTICE_MODULE = PACKAGE / "schemes" / "lattice.py"


def _kind_comparisons(source: str):
    """Lines that compare with a mesh kind's name (``== "quad"``, ``in ("quad", ...)``) or compare a ``.mesh``."""

    def names_a_kind(node) -> bool:
        if isinstance(node, ast.Constant):
            return node.value in MESH_KINDS
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            return any(names_a_kind(e) for e in node.elts)
        return isinstance(node, ast.Attribute) and node.attr == "mesh"

    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare) and any(names_a_kind(x) for x in (node.left, *node.comparators)):
            yield node.lineno
        elif isinstance(node, ast.Dict) and any(names_a_kind(k) for k in node.keys if k is not None):
            yield node.lineno  # a table keyed by the kinds' names is the same question


def test_only_the_lattice_asks_which_mesh_kind():
    """No module outside :mod:`symdecomp.schemes.lattice` branches on the mesh kind by name: it asks the lattice."""
    offenders = [
        (str(path.relative_to(PACKAGE)), line)
        for path in MODULES
        if path != LATTICE_MODULE
        for line in _kind_comparisons(path.read_text())
    ]
    assert not offenders, f"compare mesh kinds by name (ask scheme.lattice instead): {offenders}"


@pytest.mark.parametrize("line", [
    'if scheme.mesh == "triangle": pass',
    'x = "quad" != kind',
    'ok = vec.mesh != other',
    'ok = m in ("quad", "triangle")',
    'spline = {"quad": 1, "triangle": 2}',
])
def test_the_mesh_kind_check_can_fail(line):
    assert list(_kind_comparisons(line)) == [1]


def test_the_mesh_kind_check_lets_names_be_spelled():
    """Writing the name (files, JSON, messages) is not a comparison."""
    assert not list(_kind_comparisons('mesh = "quad"\nlines.append(f\'mesh = "{scheme.lattice.name}"\')\nd = {"mesh": m}'))
