"""Lattice facts live in the lattice's file: no other module compares or branches on a lattice (issue 30).

The code that needs to know something about the mesh asks the scheme's lattice (a fact: an attribute,
a method, or :meth:`~symdecomp.schemes.lattice.Lattice.select` for a table kept per kind of regular
patch); a lattice that lacks the fact raises :class:`~symdecomp.errors.LatticeFactMissing` naming it,
instead of falling into another lattice's branch.
"""

import dataclasses
import pathlib
import re

import pytest

from symdecomp.errors import InvalidSchemeError, LatticeFactMissing
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, QUAD, TRIANGLE, Lattice, QuadLattice, lattice_of, lattice_of_reference

PACKAGE = pathlib.Path(__file__).resolve().parents[2] / "symdecomp"

#: The lattice files: the only place that may ask which lattice it is.
LATTICE_FILES = ("schemes/lattice.py", "schemes/lattices/")

#: Modules that still branch on a lattice: none since issue 30 turned the last branches in ``schemes/`` into facts
#: (``Lattice.stencil_sections``, ``sector_ring``, ``cell_faces``, ``refined_point``); a module here must still branch.
PENDING: tuple[str, ...] = ()

#: The forms of a branch on a lattice, by name.
FORMS = {
    "identity with a lattice": r"\bis\s+(not\s+)?(QUAD|TRIANGLE)\b",
    "equality with a lattice": r"[!=]=\s*(QUAD|TRIANGLE|PAPER_LATTICE)\b|\b(QUAD|TRIANGLE|PAPER_LATTICE)\s*[!=]=",
    "the paper's lattice": r"\bPAPER_LATTICE\b",
    "face neighbours as a switch": r"\bface_neighbours\b",
    "a table keyed by lattice": r"\b(QUAD|TRIANGLE)(\.name)?\s*:\s*\S",
    "a choice of lattice": r"\b(QUAD|TRIANGLE)\s+if\b|\belse\s+(QUAD|TRIANGLE)\b",
    "a mesh or lattice type test": r"isinstance\([^)]*\b(Quad|Triangle)(Mesh|Lattice)\b",
    "a lattice name compared": r"[!=]=\s*[\"'](quad|triangle)[\"']|[\"'](quad|triangle)[\"']\s*[!=]=",
}


def _is_lattice_file(rel: str) -> bool:
    return any(rel == f or (f.endswith("/") and rel.startswith(f)) for f in LATTICE_FILES)


def _branches(text: str) -> list[tuple[int, str, str]]:
    """``(line, form, text)`` of each branch on a lattice in ``text`` (doctest lines, which only show a use, excepted)."""
    out = []
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith((">>>", "...")):
            continue
        out += [(number, form, line.strip()) for form, pattern in FORMS.items() if re.search(pattern, line)]
    return out


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if "_build" not in path.parts and not _is_lattice_file(rel):
            yield rel, path


@pytest.mark.parametrize("form", FORMS)
def test_no_module_outside_the_lattice_files_branches_on_a_lattice(form):
    found = [f"symdecomp/{rel}:{number}: {line}" for rel, path in _modules() if rel not in PENDING
             for number, name, line in _branches(path.read_text()) if name == form]
    assert not found, f"{form} outside the lattice files (make it a fact of the lattice):\n" + "\n".join(found)


@pytest.mark.parametrize("rel", PENDING)
def test_the_pending_list_only_holds_modules_that_still_branch(rel):
    assert _branches((PACKAGE / rel).read_text()), f"{rel} no longer branches on a lattice: remove it from PENDING"


@pytest.mark.parametrize("line, form", [
    ("    if lat is QUAD:", "identity with a lattice"),
    ("    if sm.lattice is not TRIANGLE:", "identity with a lattice"),
    ("    if scheme.lattice != PAPER_LATTICE:", "equality with a lattice"),
    ("    other = (TRIANGLE if scheme.lattice == QUAD else QUAD).reference()", "a choice of lattice"),
    ("    if scheme.lattice.face_neighbours:", "face neighbours as a switch"),
    ("_CURVES = {QUAD: _quad_curves, TRIANGLE: _triangle_curves}", "a table keyed by lattice"),
    ("FIRST_K = {QUAD.name: 3, TRIANGLE.name: 4}", "a table keyed by lattice"),
    ('    name = "a" if isinstance(mesh, QuadMesh) else "b"', "a mesh or lattice type test"),
    ('    if scheme.lattice.name == "triangle":', "a lattice name compared"),
])
def test_each_form_is_found(line, form):
    assert form in {name for _, name, _ in _branches(line)}


def test_a_fact_of_the_lattice_is_not_a_branch():
    text = ("    kind = lat.handled('the nets', BICUBIC, BOX_SPLINE)\n    rows = lat.select(_ROWS, 'rows')\n"
            "    lattice: Lattice = QUAD\n    >>> QUAD is lattice('quad')\n")
    assert _branches(text) == []


def _lacking(fact: str) -> Lattice:
    """A stub quad lattice, called ``stub``, that does not state ``fact`` (the base class's missing fact instead)."""
    cls = type("LackingLattice", (QuadLattice,), {fact: getattr(Lattice, fact)})
    return cls(**{f.name: getattr(QUAD, f.name) for f in dataclasses.fields(QUAD)} | {"name": "stub"})


def _on(lat: Lattice):
    from symdecomp.schemes.scheme import catmull_clark

    return dataclasses.replace(catmull_clark(), lattice=lat)


def test_c1_on_a_lattice_without_a_patch_kind_fails_naming_the_fact():
    from symdecomp.verify.c1 import c1_test

    with pytest.raises(LatticeFactMissing, match=r"^the stub lattice has no 'patch'$") as info:
        c1_test(_on(_lacking("patch")), 5)
    assert info.value.fact == "patch" and isinstance(info.value, InvalidSchemeError)


def test_the_closed_forms_on_a_lattice_that_does_not_say_whether_the_paper_speaks_of_it():
    from symdecomp.claims.applicability import closed_form_obstacle

    with pytest.raises(LatticeFactMissing, match=r"^the stub lattice has no 'paper_claims'$"):
        closed_form_obstacle(_on(_lacking("paper_claims")))


def test_the_error_survives_a_process_pool():
    import pickle

    again = pickle.loads(pickle.dumps(LatticeFactMissing(TRIANGLE, "the rows", " (nothing for box-spline patches)")))
    assert (str(again), again.fact, again.lattice) == (
        "the triangle lattice has no 'the rows' (nothing for box-spline patches)", "the rows", "triangle")


def test_the_base_lattice_states_no_patch_facts():
    bare = Lattice("bare", 5, False, "", "", "")
    for ask, fact in ((lambda: bare.ring_size(5, 2), "ring_size"), (lambda: bare.reference(), "reference"),
                      (lambda: bare.neighbour_offsets, "neighbour_offsets"), (lambda: bare.patch, "patch")):
        with pytest.raises(LatticeFactMissing, match=rf"^the bare lattice has no '{fact}'$"):
            ask()


def test_a_table_without_the_lattice_s_patch_kind_names_the_fact():
    assert QUAD.select({BICUBIC: 1, BOX_SPLINE: 2}, "x") == 1 and TRIANGLE.select({BICUBIC: 1, BOX_SPLINE: 2}, "x") == 2
    with pytest.raises(LatticeFactMissing, match=r"^the triangle lattice has no 'the rows' \(nothing for box-spline patches\)$"):
        TRIANGLE.select({BICUBIC: 1}, "the rows")
    assert TRIANGLE.handled("the nets", BICUBIC, BOX_SPLINE) == BOX_SPLINE
    with pytest.raises(LatticeFactMissing, match="has no 'the nets'"):
        QUAD.handled("the nets", BOX_SPLINE)


def test_the_facts_that_replaced_branches():
    assert (QUAD.paper_claims, TRIANGLE.paper_claims) == (True, False)
    assert QUAD.one_ring_classes == (("a", (1, 0)), ("b", (1, 1))) and TRIANGLE.one_ring_classes == (("a", (1, 0)),)
    assert (QUAD.regular_boundary_faces, TRIANGLE.regular_boundary_faces) == (2, 3)
    # a phantom point is an affine combination of real points; the cell's faces cover its four corners
    assert all(sum(w for w, _ in lat.phantom_stencil) == 1 for lat in (QUAD, TRIANGLE))
    assert QUAD.cell_faces(0, 1, 2, 3) == ((0, 1, 2, 3),) and TRIANGLE.cell_faces(0, 1, 2, 3) == ((0, 1, 3), (1, 2, 3))
    # the neighbours of a regular point are its 1-ring: as many edge neighbours as the regular valence
    for lat in (QUAD, TRIANGLE):
        edge, face = lat.neighbour_offsets
        assert len(edge) == lat.regular_valence and len(face) == (lat.regular_valence if lat.face_neighbours else 0)
        assert {lat.ring_of(abs(u), abs(v)) for u, v in edge if u * v >= 0} == {1}
    assert QUAD.others() == (TRIANGLE,) and TRIANGLE.others() == (QUAD,)
    assert lattice_of(TRIANGLE.ring_mesh(5, 1)) is TRIANGLE and lattice_of(QUAD.ring_mesh(5, 1)) is QUAD
    assert lattice_of_reference("loop") is TRIANGLE and lattice_of_reference("catmull-clark") is QUAD
    with pytest.raises(LatticeFactMissing, match=r"^the 'butterfly' lattice has no 'lattice'"):
        lattice_of_reference("butterfly")
