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

__all__ = ["BOUNDARY_INTERPOLATIONS", "MeshDefects", "MeshTags"]

#: OpenSubdiv's boundary interpolation options (``t interpolateboundary`` 0, 1, 2): the boundary is
#: not interpolated, its edges are sharp, or its edges and its corners (vertices of one face) are sharp.
BOUNDARY_INTERPOLATIONS = ("none", "edge-only", "edge-and-corner")


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
    #: How the boundary is treated, one of :data:`BOUNDARY_INTERPOLATIONS` (OpenSubdiv's default for its shapes: edge-and-corner).
    interpolate_boundary: str = "edge-and-corner"

    def __post_init__(self):
        object.__setattr__(self, "creases", _frozen(self.creases))
        object.__setattr__(self, "corners", _frozen(self.corners))
        object.__setattr__(self, "holes", frozenset(self.holes))
        if self.interpolate_boundary not in BOUNDARY_INTERPOLATIONS:
            raise ValueError(f"interpolate_boundary must be one of {', '.join(BOUNDARY_INTERPOLATIONS)}, got {self.interpolate_boundary!r}")

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
    #: Vertices where two or more separate fans of faces meet.
    non_manifold_vertices: tuple[int, ...] = ()
    #: Faces with fewer than 3 distinct corners, a repeated corner, or zero area.
    degenerate_faces: tuple[int, ...] = ()
    #: Faces on the same corners as an earlier face (the later ones are listed).
    repeated_faces: tuple[int, ...] = ()
    #: Vertices in no face.
    isolated_vertices: tuple[int, ...] = ()
    #: Faces dropped to leave a manifold mesh (those on non-manifold edges and vertices, and the degenerate and repeated ones).
    dropped_faces: tuple[int, ...] = ()

    def is_empty(self) -> bool:
        """Whether nothing was left out."""
        return not any((self.non_manifold_edges, self.non_manifold_vertices, self.degenerate_faces, self.repeated_faces,
                        self.isolated_vertices, self.dropped_faces))

    def as_dict(self) -> dict[str, list]:
        """The lists as JSON-ready lists (edges as pairs)."""
        return {name: [list(x) if isinstance(x, tuple) else x for x in getattr(self, name)]
                for name in ("non_manifold_edges", "non_manifold_vertices", "degenerate_faces", "repeated_faces",
                             "isolated_vertices", "dropped_faces")}
