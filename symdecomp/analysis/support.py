"""Section 3: which control vertices are inside, on the boundary of, or outside the support of ``P``.

Let ``phi_P`` be the basis function of a control vertex ``P``: the limit of subdividing the
data that is 1 at ``P`` and 0 at every other vertex. Its *support* is the closure ``Omega``
of ``{phi_P != 0}`` on the limit surface, parametrised by the control mesh (a vertex ``Q``
of the control mesh is a point of it, the limit of ``Q``'s vertex points).

**Definition used here.** Around a vertex ``Q`` lie its faces ``F_0..F_{m-1}`` (the
*sectors*); at level ``k`` the sector ``s`` is the level-``k`` face at ``Q`` inside ``F_s``.
Sector ``s`` *carries* ``phi_P`` if at every level ``phi_P`` is not identically zero on it.
``Q`` is

* **outside** the support of ``P`` if no sector carries ``phi_P``: then ``phi_P = 0`` on a
  neighbourhood of ``Q``, i.e. ``Q`` is not in ``Omega``;
* **on the boundary** if some sectors carry it and some do not: ``Q`` is in ``Omega`` (it is
  a limit of points where ``phi_P != 0``) and the open faces of the other sectors, on which
  ``phi_P = 0``, touch ``Q``, so ``Q`` is on the boundary of ``Omega``; this is the split of a
  disk around ``Q`` into ``A_in`` and ``A_ex`` that the paper's argument uses;
* **inside** if every sector carries it. Where this coincides with ``phi_P(Q) != 0`` (the
  result records ``phi_P(Q)``; :attr:`SupportClassification.consistent` checks it), ``Q`` is
  in the interior of ``Omega``. It need not coincide: on the unrefined cube (where the 2-ring
  of a corner is the whole surface) the corner opposite ``P`` has every sector carrying
  ``phi_P`` but ``phi_P = 0`` there, an isolated zero (``phi_P > 0`` at every vertex near it of
  the refined meshes; see the tests). On meshes where the 2-ring of ``P`` is a disk the two
  agree in every case checked.

**How it is computed (from the rules).** Write ``N(F)`` for the vertices of the faces that
share a vertex with ``F``. Two facts decide every sector at level 0:

1. *Locality*: the limit function on a face ``F`` depends only on the values on ``N(F)``
   (each rule of :func:`symdecomp.schemes.refinement.mesh_rules` reads a vertex's 1-ring, an edge's two
   faces or one face). So values zero on ``N(F)`` mean ``phi_P = 0`` on ``F``.
2. *Propagation* (needs nonnegative rules whose vertex rule and limit masks are strictly
   positive; checked from the scheme, else :class:`~symdecomp.errors.InvalidSchemeError`):
   the data stay nonnegative; the child ``F'`` of ``F`` at ``Q`` has the vertex points of all
   four corners of ``F`` in ``N(F')``, and a vertex point is positive as soon as one value of
   its closed 1-ring is, so a positive value on ``N(F)`` gives one on ``N(F')``; and a positive
   value on ``N(F)`` gives a corner ``c`` of ``F`` with ``phi_P(c) > 0`` (positive limit mask),
   so ``phi_P`` is not identically zero on ``F``.

Hence sector ``s`` carries ``phi_P`` iff the values on ``N(F_s)`` are not all zero; for the
data ``e_P`` iff ``P`` is in ``N(F_s)``. :func:`classify_support` computes this, and with
``levels > 0`` also refines ``e_P`` exactly that many times and recomputes every sector's
``N(F)`` test at every level (the conclusion of fact 2, checked rather than assumed).

>>> from symdecomp.schemes.mesh import ring_mesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> c = classify_support(ring_mesh(4, 4), 0, catmull_clark())
>>> sorted(r.value for r in c.regions.values()).count("inside"), c.count(Region.BOUNDARY)
(9, 16)
"""

from __future__ import annotations

import enum
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from types import MappingProxyType

import sympy as sp

from symdecomp.algebra.numbers import to_fraction, to_sympy
from symdecomp.errors import InvalidMeshError, InvalidSchemeError, NotApplicableError
from symdecomp.schemes.mesh import QuadMesh
from symdecomp.schemes.refinement import mesh_rules, refine
from symdecomp.schemes.scheme import Scheme, check_scheme, subdivision_matrix
from symdecomp.validate import cached, check_levels, check_valence

__all__ = ["Region", "SupportClassification", "classify_support", "support_relation", "limit_mask", "check_positive_scheme"]


class Region(enum.Enum):
    """Where a vertex lies relative to the support of ``P``."""

    INSIDE = "inside"
    BOUNDARY = "boundary"
    OUTSIDE = "outside"


@cached(scheme=check_scheme, valence=check_valence)
def limit_mask(scheme: Scheme, valence: int) -> tuple[sp.Expr, ...]:
    """The limit mask at a vertex of this valence: the left eigenvector of eigenvalue 1 of the
    exact subdivision matrix, normalised to sum 1, in the order ``(O, a_0.., b_0..)``.

    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> limit_mask(catmull_clark(), 4)[:2], limit_mask(catmull_clark(), 4)[5]
    ((4/9, 1/9), 1/36)
    """
    S = subdivision_matrix(scheme, valence)
    left = (S.T - sp.eye(S.shape[0])).nullspace()
    if len(left) != 1:
        raise InvalidSchemeError(f"eigenvalue 1 of the valence-{valence} matrix of {scheme.name!r} is not simple: no limit mask")
    v = left[0]
    total = sp.simplify(sum(v))
    if total == 0:
        raise InvalidSchemeError(f"the valence-{valence} left eigenvector of {scheme.name!r} sums to 0: no limit mask")
    return tuple(sp.simplify(x / total) for x in v)


def check_positive_scheme(scheme: Scheme, valences: Iterable[int]) -> None:
    """Raise unless the scheme satisfies the hypotheses of the propagation argument.

    Face and edge weights ``>= 0``; at each valence the vertex-rule weights ``> 0`` and the
    limit mask ``> 0``. Weights must be numbers (substitute free parameters first).
    """
    rules = mesh_rules(scheme)
    for label, w in (("face", rules.face_corner), ("edge end", rules.edge_end), ("edge side", rules.edge_side)):
        if not (w.is_number and w >= 0):
            raise NotApplicableError(
                f"support classification needs nonnegative numeric rules; the {label} weight of {scheme.name!r} is {w}"
            )
    for m in sorted(set(valences)):
        for w in rules.vertex_weights(m):
            if not (w.is_number and w > 0):
                raise NotApplicableError(
                    f"support classification needs positive vertex-rule weights; {scheme.name!r} has {w} at valence {m}"
                )
        for w in limit_mask(scheme, m):
            if not (w.is_number and w > 0):
                raise NotApplicableError(
                    f"support classification needs a positive limit mask; {scheme.name!r} has {w} at valence {m}"
                )


@dataclass(frozen=True)
class SupportClassification:
    """The vertices of a mesh classified against the support of ``phi_P``."""

    #: The control mesh.
    mesh: QuadMesh
    #: The vertex ``P`` whose basis function is examined.
    source: int
    #: Vertex -> its region (for the vertices that could be classified).
    regions: Mapping[int, Region]
    #: Vertex -> per sector (its faces in 1-ring order), whether the sector carries ``phi_P``.
    sectors: Mapping[int, tuple[bool, ...]]
    #: Vertex -> ``phi_P(Q)`` exactly (limit mask applied to the values of its 1-ring).
    limit_values: Mapping[int, sp.Expr]
    #: Number of exact refinement levels over which the sector tests were re-checked.
    levels_checked: int
    #: Whether every re-check at levels ``1..levels_checked`` agreed with level 0.
    stable: bool

    def count(self, region: Region) -> int:
        return sum(1 for r in self.regions.values() if r is region)

    def vertices_in(self, region: Region) -> frozenset:
        return frozenset(v for v, r in self.regions.items() if r is region)

    @property
    def consistent(self) -> bool:
        """Inside exactly where ``phi_P(Q) != 0`` (see the module docstring)."""
        return all((r is Region.INSIDE) == (self.limit_values[v] != 0) for v, r in self.regions.items())


def _n_of_face(mesh: QuadMesh, fi: int) -> set:
    """Vertices of the faces sharing a vertex with face ``fi``."""
    out: set[int] = set()
    for c in mesh.faces[fi]:
        for g in mesh.faces_of(c):
            out.update(mesh.faces[g])
    return out


def _classifiable(mesh: QuadMesh, q: int) -> bool:
    """Whether ``Q`` and the corners of its faces are interior (so ``N(F)`` is complete)."""
    if not mesh.is_interior(q):
        return False
    return all(mesh.is_interior(c) for fi in mesh.faces_of(q) for c in mesh.faces[fi])


def _sector_faces(mesh: QuadMesh, q: int) -> tuple[int, ...]:
    o, a, _ = mesh.one_ring(q)
    out = []
    for ai in a:
        for fi in mesh.faces_of(q):
            f = mesh.faces[fi]
            if f[(f.index(q) + 1) % 4] == ai:
                out.append(fi)
    return tuple(out)


def _sector_neighbourhoods(mesh: QuadMesh, q: int) -> tuple[frozenset, ...]:
    """``N(F_s)`` for the sectors ``s`` of ``q`` in 1-ring order."""
    return tuple(frozenset(_n_of_face(mesh, fi)) for fi in _sector_faces(mesh, q))


def _region(carried: tuple[bool, ...]) -> Region:
    return Region.INSIDE if all(carried) else Region.OUTSIDE if not any(carried) else Region.BOUNDARY


@cache
def _mask_fractions(scheme: Scheme, valence: int) -> tuple[Fraction, ...]:
    return tuple(to_fraction(w) for w in limit_mask(scheme, valence))


def _limit_value(data: QuadMesh, q: int, scheme: Scheme) -> sp.Rational:
    ring = data.one_ring_values(q)
    value = sum((w * x[0] for w, x in zip(_mask_fractions(scheme, data.valence(q)), ring)), Fraction(0))
    return to_sympy(value)


def support_relation(mesh: QuadMesh, scheme: Scheme, vertices: Iterable[int]) -> dict:
    """``{(P, Q): region of Q relative to the support of P}`` for all pairs of ``vertices``.

    The same decision as :func:`classify_support` (level 0), with the ``N(F)`` sets computed
    once for all sources.
    """
    vertices = list(vertices)
    for v in vertices:
        if not _classifiable(mesh, v):
            raise InvalidMeshError(f"vertex {v} is too close to the mesh boundary to be classified (add rings)")
    check_positive_scheme(scheme, {mesh.valence(v) for v in mesh.vertices() if mesh.is_interior(v)})
    hoods = {q: _sector_neighbourhoods(mesh, q) for q in vertices}
    return {(p, q): _region(tuple(p in nf for nf in hoods[q])) for p in vertices for q in vertices}


def _child_sectors(step, current: QuadMesh, q: int, v: int, faces) -> tuple[int, tuple[int, ...]]:
    """Follow vertex ``v`` (tracking candidate ``q``) and its sector faces through one refinement ``step``."""
    v2 = step.vertex_point.get(v)
    if v2 is None:
        raise InvalidMeshError(f"vertex {q} left the exactly refinable part of the mesh (add rings)")
    child_faces = []
    for fi in faces:
        f = current.faces[fi]
        k = f.index(v)
        want = {v2, step.edge_point.get(frozenset((v, f[(k + 1) % 4]))), step.face_point.get(fi)}
        match = [g for g in step.mesh.faces_of(v2) if want <= set(step.mesh.faces[g])]
        if len(match) != 1:
            raise InvalidMeshError(f"could not follow sector {fi} of vertex {q} (add rings)")
        child_faces.append(match[0])
    if not all(all(step.mesh.is_interior(c) for c in step.mesh.faces[g]) for g in step.mesh.faces_of(v2)):
        raise InvalidMeshError(f"vertex {q} is too close to the boundary at the refined level (add rings)")
    return v2, tuple(child_faces)


def classify_support(
    mesh: QuadMesh, source: int, scheme: Scheme, *, vertices: Iterable[int] | None = None, levels: int = 0
) -> SupportClassification:
    """Classify vertices of ``mesh`` against the support of the basis function of ``source``.

    ``vertices`` defaults to every vertex whose faces' corners are all interior (for the others
    ``N(F)`` is cut off by the mesh boundary and they are left out). With ``levels > 0`` the
    data ``e_P`` are refined exactly that many times and every sector test repeated on the
    child sectors (see the module docstring); :attr:`SupportClassification.stable` reports
    whether they all agreed.
    """
    check_scheme(scheme)
    if source not in mesh.values or not mesh.faces_of(source):
        raise InvalidMeshError(f"vertex {source!r} is not in the mesh")
    levels = check_levels(levels, maximum=8, reason="each level refines the whole mesh: four times the faces")
    candidates = [v for v in mesh.vertices() if _classifiable(mesh, v)] if vertices is None else list(vertices)
    for v in candidates:
        if not _classifiable(mesh, v):
            raise InvalidMeshError(f"vertex {v} is too close to the mesh boundary to be classified (add rings)")
    check_positive_scheme(scheme, {mesh.valence(v) for v in mesh.vertices() if mesh.is_interior(v)})
    data = mesh.with_values({v: (Fraction(1) if v == source else Fraction(0),) for v in mesh.values})

    regions, sectors, limits = {}, {}, {}
    for q in candidates:
        carried = tuple(source in nf for nf in _sector_neighbourhoods(mesh, q))
        sectors[q] = carried
        regions[q] = _region(carried)
        limits[q] = _limit_value(data, q, scheme)

    stable = True
    if levels:
        rules = mesh_rules(scheme)
        # follow each candidate: its vertex point, and the child of each sector face at it
        track = {q: (q, _sector_faces(data, q)) for q in candidates}
        current = data
        for _ in range(levels):
            step = refine(current, rules)
            new_track = {}
            for q, (v, faces) in track.items():
                v2, child_faces = _child_sectors(step, current, q, v, faces)
                new_track[q] = (v2, child_faces)
                vals = step.mesh.values
                again = tuple(any(vals[x][0] != 0 for x in _n_of_face(step.mesh, g)) for g in child_faces)
                if again != sectors[q]:
                    stable = False
            track = new_track
            current = step.mesh
    return SupportClassification(
        mesh, source, MappingProxyType(regions), MappingProxyType(sectors), MappingProxyType(limits), levels, stable
    )
