"""How one step of a StencilScheme makes the new mesh: one object per topology.

* ``primal``: a new point per old vertex, per edge and (when the scheme has ``[face]`` rules) per
  face; each ``m``-gon becomes ``m`` quads around its face point, or, without face points, each
  triangle becomes four;
* ``dual``: a new point per face corner; new faces per old face, per interior edge and per
  interior vertex;
* ``sqrt3``: a new point per vertex and per face; each interior edge becomes two triangles (the
  lattice turns by half a sector: the analysis is of two steps).

:func:`refine_step` applies the rules (:mod:`symdecomp.schemes.stencil_rows`) and builds the new
faces from the new points that are computable; :meth:`Topology.track` names the halfedge of the new
mesh that continues a halfedge at the centre, so that the new mesh is labelled from the same place.

>>> from symdecomp.schemes.halfedge import halfedge_mesh
>>> TOPOLOGIES["dual"].centre, TOPOLOGIES["primal"].centre
('face', 'vertex')
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.halfedge import HalfedgeMesh, halfedge_mesh
from symdecomp.schemes.stencil_rows import PointKey, Row, kind_row, point_key
from symdecomp.schemes.stencils import StencilScheme

__all__ = ["Topology", "TOPOLOGIES", "topology_of", "RefinedStep", "refine_step"]


@dataclass(frozen=True)
class RefinedStep:
    """One step on a local mesh: the new mesh (computable points only) and each new point's row."""

    #: The new mesh (vertex ids ``0..``).
    mesh: HalfedgeMesh
    #: New vertex id -> row on the old vertex ids.
    rows: dict[int, Row]
    #: Point key (``(kind, x)``) -> new vertex id.
    ids: dict[PointKey, int]


def _new_faces_primal(mesh: HalfedgeMesh, with_face_points: bool) -> Iterator[tuple[PointKey, ...]]:
    for f, hs in enumerate(mesh.face_halfedges):
        if with_face_points:
            for h in hs:
                yield (("vertex", mesh.origin[h]), point_key(mesh, "edge", h), ("face", f), point_key(mesh, "edge", mesh.prev[h]))
            continue
        if len(hs) != 3:
            raise InvalidSchemeError(f"a primal scheme without [face] rules splits triangles, but a face has {len(hs)} sides")
        for h in hs:
            yield (("vertex", mesh.origin[h]), point_key(mesh, "edge", h), point_key(mesh, "edge", mesh.prev[h]))
        yield tuple(point_key(mesh, "edge", h) for h in hs)


def _new_faces_dual(mesh: HalfedgeMesh) -> Iterator[tuple[PointKey, ...]]:
    for hs in mesh.face_halfedges:
        yield tuple(("corner", h) for h in hs)
    for h, t in enumerate(mesh.twin):
        if h < t and mesh.face[h] is not None and mesh.face[t] is not None:
            yield (("corner", mesh.next[t]), ("corner", t), ("corner", mesh.next[h]), ("corner", h))
    for v in mesh.vertices():
        ring = mesh.outgoing(v)
        if ring is not None:
            yield tuple(("corner", h) for h in ring)


def _new_faces_sqrt3(mesh: HalfedgeMesh) -> Iterator[tuple[PointKey, ...]]:
    for h, t in enumerate(mesh.twin):
        f, g = mesh.face[h], mesh.face[t]
        if h < t and f is not None and g is not None:
            yield (("vertex", mesh.origin[h]), ("face", g), ("face", f))
            yield (("vertex", mesh.origin[t]), ("face", f), ("face", g))


@dataclass(frozen=True)
class Topology:
    """A topology: which new points a step keeps, how they form faces, and where the centre goes."""

    name: str
    #: The centre element of an extraordinary neighbourhood: ``"vertex"`` or ``"face"``.
    centre: str

    def point_kinds(self, scheme: StencilScheme) -> tuple[str, ...]:
        """The kinds of new points that are vertices of the new mesh."""
        kinds = {k.kind for k in scheme.kinds}
        wanted = {"primal": ("vertex", "edge", "face"), "dual": ("corner",), "sqrt3": ("vertex", "face")}[self.name]
        if self.name != "primal":
            missing = [k for k in wanted if k not in kinds]
            if missing:
                raise InvalidSchemeError(f"a {self.name} scheme needs [{missing[0]}] rules")
            return wanted
        for k in ("vertex", "edge"):
            if k not in kinds:
                raise InvalidSchemeError(f"a primal scheme needs [{k}] rules")
        return tuple(k for k in wanted if k in kinds)

    def new_faces(self, mesh: HalfedgeMesh, scheme: StencilScheme) -> Iterator[tuple[PointKey, ...]]:
        """The new faces as tuples of point keys, counter-clockwise."""
        if self.name == "primal":
            return _new_faces_primal(mesh, "face" in self.point_kinds(scheme))
        return _new_faces_dual(mesh) if self.name == "dual" else _new_faces_sqrt3(mesh)

    def track(self, mesh: HalfedgeMesh, h: int, parity: int) -> tuple[PointKey, PointKey]:
        """``(origin key, tip key)`` of the new halfedge that continues ``h`` (a halfedge at the centre) after a step.

        The sqrt(3) step turns by half a sector; its track alternates sides so that two steps
        return to the direction of ``h``.
        """
        if self.name == "primal":
            return ("vertex", mesh.origin[h]), point_key(mesh, "edge", h)
        if self.name == "dual":
            return ("corner", h), ("corner", mesh.next[h])
        return ("vertex", mesh.origin[h]), point_key(mesh, "face", h if parity == 0 else mesh.twin[h])


#: The topologies, by name.
TOPOLOGIES = {t.name: t for t in (Topology("primal", "vertex"), Topology("dual", "face"), Topology("sqrt3", "vertex"))}


def topology_of(scheme: StencilScheme) -> Topology:
    """The topology a scheme names; :class:`InvalidSchemeError` if unknown."""
    if scheme.topology not in TOPOLOGIES:
        raise InvalidSchemeError(f"topology must be one of {', '.join(TOPOLOGIES)}, got {scheme.topology!r:.20}")
    return TOPOLOGIES[scheme.topology]


def _keys_of(mesh: HalfedgeMesh, kind: str) -> list[PointKey]:
    if kind == "vertex":
        return [("vertex", v) for v in mesh.vertices()]
    if kind == "face":
        return [("face", f) for f in range(len(mesh.faces))]
    if kind == "edge":
        return [("edge", h) for h, t in enumerate(mesh.twin) if h < t]
    return [("corner", h) for h, f in enumerate(mesh.face) if f is not None]


def refine_step(scheme: StencilScheme, mesh: HalfedgeMesh, *, regular: int) -> RefinedStep:
    """One step of ``scheme`` on ``mesh``: every computable new point's exact row, and the new faces among them."""
    topology = topology_of(scheme)
    made: dict[PointKey, Row] = {}
    for rules in scheme.kinds:
        for key in _keys_of(mesh, rules.kind):
            row = kind_row(mesh, rules, key, made, regular=regular)
            if row is not None:
                made[key] = row
    kinds = topology.point_kinds(scheme)
    ids: dict[PointKey, int] = {}
    for key in made:
        if key[0] in kinds:
            ids[key] = len(ids)
    faces = [tuple(ids[k] for k in f) for f in topology.new_faces(mesh, scheme) if all(k in ids for k in f)]
    rows: dict[int, Row] = {i: made[key] for key, i in ids.items()}
    return RefinedStep(halfedge_mesh(faces), rows, ids)
