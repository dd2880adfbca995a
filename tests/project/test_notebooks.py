"""The notebooks in ``notebooks/`` run from a clean kernel, draw their figures, and are committed clean.

Each notebook is executed with nbclient in a fresh ``python3`` kernel whose working directory
is ``notebooks/`` (as ``jupyter nbconvert --execute`` would run it) and whose ``PYTHONPATH``
starts with this checkout, so the code under test is the code beside the notebooks. Any cell
that raises fails the test. The committed files carry no outputs: what they would show is
produced here, from the current code, every time the suite runs.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOK_DIR = ROOT / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("*.ipynb"))


def _read(path: Path):
    return nbformat.read(str(path), as_version=4)


def test_there_are_the_four_notebooks_of_the_issue():
    names = {p.stem for p in NOTEBOOKS}
    assert {"01_polygonal_decomposition", "02_tangent_plane", "03_elliptic_hyperbolic", "04_circulant_block_matrices"} <= names


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_committed_notebook_has_no_outputs(path):
    nb = _read(path)
    nbformat.validate(nb)
    for index, cell in enumerate(nb.cells):
        if cell.cell_type == "code":
            assert cell.outputs == [], f"{path.name} cell {index} carries outputs; strip them before committing"
            assert cell.execution_count is None, f"{path.name} cell {index} carries an execution count"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_opens_with_what_it_shows_and_how_to_change_it(path):
    first = _read(path).cells[0]
    assert first.cell_type == "markdown"
    assert first.source.lstrip().startswith("# ")
    assert "How to change it" in first.source


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_thin(path):
    """Notebooks call the package; functions and classes they need live in symdecomp."""
    for index, cell in enumerate(_read(path).cells):
        if cell.cell_type != "code":
            continue
        for line in cell.source.splitlines():
            stripped = line.lstrip()
            assert not stripped.startswith(("def ", "class ", "lambda")), (
                f"{path.name} cell {index} defines {stripped.split('(')[0]!r}; put it in the library"
            )


@pytest.mark.slow  # 5-20 s each; CI's docs build executes every notebook too (raising on an error)
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_executes_from_a_clean_kernel(path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep))
    nb = _read(path)
    # A last cell reports which symdecomp the kernel imported: it must be this checkout's.
    nb.cells.append(nbformat.v4.new_code_cell(
        "import symdecomp, pathlib; print(pathlib.Path(symdecomp.__file__).resolve().parent.parent)"
    ))
    client = nbclient.NotebookClient(
        nb, timeout=240, kernel_name="python3", resources={"metadata": {"path": str(NOTEBOOK_DIR)}}
    )
    client.execute()  # raises CellExecutionError naming the cell if any cell fails

    outputs = [o for c in nb.cells[:-1] if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {}) and "<Figure" in o["data"].get("text/plain", "")]
    assert images, f"{path.name} drew no figure"
    # The figures were rendered (not just created): a PNG of a real plot is several kilobytes.
    assert all(len(o["data"]["image/png"]) > 5000 for o in images)
    assert Path(nb.cells[-1].outputs[0]["text"].strip()) == ROOT
