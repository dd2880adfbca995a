"""What a mesh file says besides its faces: OpenSubdiv's sharpness tags, and what was left out of the mesh.

:class:`MeshTags` holds the tags of OpenSubdiv's OBJ dialect (``t crease``, ``t corner``, ``t hole``,
``t interpolateboundary``) in the mesh's own vertex and face indices; :class:`MeshDefects` lists the
elements of a file that a subdivision scheme cannot take (non-manifold edges and vertices,
degenerate and repeated faces, isolated vertices), in the file's numbering, so that the analysis can
go on around them and report them. Both are plain data; reading them is
:mod:`symdecomp.schemes.meshformats`, using them is the mesh's analysis.

>>> MeshTags(creases={(0, 1): Fraction(2)}).sharpness_of_edge(1, 0)
Fraction(2, 1)
>>> MeshDefects().is_empty()
True
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from types import MappingProxyType

from symdecomp.errors import InvalidMeshError

__all__ = ["BOUNDARY_INTERPOLATIONS", "CREASE_METHODS", "TRIANGLE_SUBDIVISIONS", "MeshDefects", "MeshTags"]

#: OpenSubdiv's boundary interpolation options: the boundary is not interpolated, its edges are sharp, or its
#: edges and its corners (vertices of one face) are sharp. OpenSubdiv's shape reader maps ``t interpolateboundary``
#: 0, 1, 2 to none, edge-and-corner, edge-only (``regression/common/far_utils.h``, RenderMan's convention); a mesh
#: without the tag is edge-and-corner here (OpenSubdiv's shape loader would take edge-only: write the tag to match it).
BOUNDARY_INTERPOLATIONS = ("none", "edge-only", "edge-and-corner")
#: OpenSubdiv's creasing methods (``t creasemethod``): ``normal`` (uniform) or ``chaikin``.
CREASE_METHODS = ("uniform", "chaikin")
#: OpenSubdiv's rules for triangles in a Catmull-Clark mesh (``t smoothtriangles``): ``catmark`` or ``smooth``.
TRIANGLE_SUBDIVISIONS = ("catmark", "smooth")


def _frozen(mapping: Mapping) -> Mapping:
    return MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class MeshTags:
    """OpenSubdiv's sharpness tags of a mesh (all empty for a mesh without tags)."""

    #: Sharp edges: ``(u, v)`` with ``u < v`` -> sharpness (a non-negative rational; 10 or more is infinitely sharp, as in OpenSubdiv).
    creases: Mapping[tuple[int, int], Fraction] = field(default_factory=dict)
    #: Sharp vertices (``t corner``): vertex -> sharpness.
    corners: Mapping[int, Fraction] = field(default_factory=dict)
    #: Faces tagged as holes (``t hole``), by face index.
    holes: frozenset[int] = frozenset()
    #: How the boundary is treated, one of :data:`BOUNDARY_INTERPOLATIONS` (edge-and-corner without a tag).
    interpolate_boundary: str = "edge-and-corner"
    #: How semi-sharp creases of varying sharpness are refined, one of :data:`CREASE_METHODS`.
    crease_method: str = "uniform"
    #: The rule for a triangle's face point in a Catmull-Clark mesh, one of :data:`TRIANGLE_SUBDIVISIONS`.
    triangle_subdivision: str = "catmark"

    def __post_init__(self):
        object.__setattr__(self, "creases", _frozen(self.creases))
        object.__setattr__(self, "corners", _frozen(self.corners))
        object.__setattr__(self, "holes", frozenset(self.holes))
        for option, known in (("interpolate_boundary", BOUNDARY_INTERPOLATIONS), ("crease_method", CREASE_METHODS),
                              ("triangle_subdivision", TRIANGLE_SUBDIVISIONS)):
            if getattr(self, option) not in known:
                raise InvalidMeshError(f"{option} must be one of {', '.join(known)}, got {getattr(self, option)!r:.40}")

    def __reduce__(self):  # the read-only mappings do not pickle; the tags travel to worker processes
        return (MeshTags, (dict(self.creases), dict(self.corners), self.holes, self.interpolate_boundary, self.crease_method,
                           self.triangle_subdivision))

    def sharpness_of_edge(self, u: int, v: int) -> Fraction:
        """The sharpness of edge ``{u, v}`` (0 when untagged)."""
        return self.creases.get((min(u, v), max(u, v)), Fraction(0))

    def is_empty(self) -> bool:
        """Whether the mesh carries no tag (the boundary option aside)."""
        return not (self.creases or self.corners or self.holes)


@dataclass(frozen=True)
class MeshDefects:
    """The elements of a mesh file left out of the analysis, each in the file's numbering (0-based)."""

    #: Edges ``(u, v)``, ``u < v``, shared by three or more faces.
    non_manifold_edges: tuple[tuple[int, int], ...] = ()
    #: Edges ``(u, v)``, ``u < v``, of two faces running along them the same way (inconsistent orientation).
    misoriented_edges: tuple[tuple[int, int], ...] = ()
    #: Vertices where two or more separate fans of faces meet.
    non_manifold_vertices: tuple[int, ...] = ()
    #: Faces with fewer than 3 distinct corners, a repeated corner, or zero area.
    degenerate_faces: tuple[int, ...] = ()
    #: Faces on the same corners as an earlier face (the later ones are listed).
    repeated_faces: tuple[int, ...] = ()
    #: Vertices in no face of the file, or in none of the faces kept (they keep their index; they are not analysed).
    isolated_vertices: tuple[int, ...] = ()
    #: Every face dropped to leave a manifold mesh: the degenerate and repeated ones, and those that the rules of
    #: :mod:`symdecomp.schemes.mesh_topology` drop at non-manifold and misoriented edges and non-manifold vertices.
    dropped_faces: tuple[int, ...] = ()
    #: OpenSubdiv's hierarchical edits (``t vertexedit``, ``edgeedit``, ``faceedit``) as ``(line, level)``: the file's
    #: line and the first refined level the edit acts at; the analysis is of the unedited surface.
    hierarchical_edits: tuple[tuple[int, int], ...] = ()

    def is_empty(self) -> bool:
        """Whether nothing was left out."""
        return not any(getattr(self, name) for name in _DEFECTS)

    def as_dict(self) -> dict[str, list]:
        """The lists as JSON-ready lists (edges as pairs)."""
        return {name: [list(x) if isinstance(x, tuple) else x for x in getattr(self, name)] for name in _DEFECTS}


_DEFECTS = ("non_manifold_edges", "misoriented_edges", "non_manifold_vertices", "degenerate_faces", "repeated_faces",
            "isolated_vertices", "dropped_faces", "hierarchical_edits")
