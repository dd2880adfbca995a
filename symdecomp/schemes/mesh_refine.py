"""Whole meshes refined exactly by a scheme, sharpness tags and all (``symdecomp refine``).

:func:`refine_mesh` takes ``steps`` exact steps of a scheme on a :class:`~symdecomp.schemes.meshfile.PolygonMesh`:
each step is :func:`~symdecomp.schemes.tagged_refinement.refine_tagged` (every vertex, edge and face point by the
rule its own tags and valence give, OpenSubdiv's semantics, boundary interpolation from the mesh's tags), after a
first exact Catmull-Clark step on a mesh with faces other than quads
(:func:`~symdecomp.schemes.polygon_step.catmull_clark_polygon_step`). The result's coordinates are exact
(``Fraction``); its creases carry the decayed sharpness.

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> quad = PolygonMesh.from_arrays([(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0)], [(0, 1, 2, 3)])
>>> r = refine_mesh(quad, catmull_clark(), 2)
>>> len(r.points), len(r.faces), r.creases
(25, 16, {})
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from symdecomp.errors import InvalidInputError, InvalidMeshError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import INPUT_LIMITS, check_int, check_memory

__all__ = ["RefinedMesh", "refine_mesh", "MAX_STEPS"]

#: Most steps :func:`refine_mesh` takes (each multiplies the faces by 4).
MAX_STEPS = INPUT_LIMITS["refine --steps (refine_mesh)"][0]


@dataclass(frozen=True)
class RefinedMesh:
    """A mesh after ``steps`` exact steps: points (exact), faces, and the creases still sharp."""

    points: tuple
    faces: tuple
    #: ``(u, v)`` with ``u < v`` -> sharpness (``math.inf`` or a ``Fraction``) of the refined creases.
    creases: dict
    #: Corner vertices (infinitely sharp or semi-sharp) -> sharpness.
    corners: dict
    steps: int


def _tagged(mesh: PolygonMesh, lattice):
    from symdecomp.schemes.sharp import SharpOptions
    from symdecomp.schemes.tagged_refinement import TaggedMesh

    tags = mesh.tags
    if tags.holes:
        raise InvalidMeshError(f"{mesh.name}: faces tagged as holes are not refined here")
    if tags.interpolate_boundary == "none":
        raise InvalidMeshError(f"{mesh.name}: interpolateboundary none is not refined here (edge-only or edge-and-corner)")
    edges = {frozenset(e): s for e, s in tags.creases.items() if s > 0}
    corners = {v: s for v, s in tags.corners.items() if s > 0}
    return TaggedMesh(mesh.local_mesh(lattice), edges, corners), SharpOptions(tags.interpolate_boundary)


def _result(tagged, steps: int) -> RefinedMesh:
    ids = tagged.mesh.vertices()
    index = {v: i for i, v in enumerate(ids)}
    points = tuple(tuple(Fraction(c) for c in tagged.mesh.values[v]) for v in ids)
    faces = tuple(tuple(index[v] for v in f) for f in tagged.mesh.faces)
    creases = {tuple(sorted(index[v] for v in e)): s for e, s in tagged.edge_sharpness.items() if s > 0}
    corners = {index[v]: s for v, s in tagged.vertex_sharpness.items() if s > 0}
    return RefinedMesh(points, faces, dict(sorted(creases.items())), dict(sorted(corners.items())), steps)


def refine_mesh(mesh: PolygonMesh, scheme: Scheme, steps: int, *, progress=None) -> RefinedMesh:
    """``steps`` exact steps of ``scheme`` on ``mesh`` (module docstring); ``progress(iterable, total)`` wraps the steps."""
    from symdecomp.schemes.polygon_step import catmull_clark_polygon_step
    from symdecomp.schemes.tagged_refinement import refine_tagged

    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    scheme = check_scheme(scheme)
    steps = check_int(steps, "steps", minimum=0, maximum=MAX_STEPS)
    check_memory(400 * (len(mesh.points) + len(mesh.faces)) * 4**steps,
                 f"{mesh.name}: {steps} steps of {len(mesh.faces)} faces ({len(mesh.faces) * 4**steps} faces)")
    done = 0
    if mesh.face_sizes() != (scheme.lattice.face_sides,):
        if scheme.name != "catmull-clark":
            mesh.require_lattice(scheme.lattice, scheme.name)
        if steps == 0:
            raise InvalidInputError("steps must be at least 1 for a mesh with faces other than quads")
        mesh, done = catmull_clark_polygon_step(mesh).mesh, 1
    tagged, options = _tagged(mesh, scheme.lattice)
    loop = range(done, steps)
    for _ in progress(loop, len(loop)) if progress is not None else loop:
        tagged = refine_tagged(tagged, scheme, options)[0]
    return _result(tagged, steps)
