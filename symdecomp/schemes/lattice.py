"""The lattice a scheme lives on: one object per kind of neighbourhood (quad and triangle meshes).

Everything that depends on the kind of mesh is a fact of the lattice, and the code that needs
it asks the scheme's :attr:`~symdecomp.schemes.scheme.Scheme.lattice` instead of comparing
names: the regular valence (4 or 6), the 1-ring and its vertex order (``O, a_i, b_i`` on quads,
``O, a_i`` on triangles: there are no face neighbours and no face rule), the ``K``-ring labels
and sizes, the canonical name of a lattice point near a sector, one refinement of a whole mesh
by the scheme's rules, the regular patch (bicubic B-spline or quartic box spline) and the
patch matrices of Stam's evaluation, the reference scheme whose regular rules give that
patch, and how the patch's parameter domain splits into the sub-patches of one refinement.
A new neighbourhood (a boundary or crease, a dual lattice) is one new subclass.
No module outside this file asks which lattice it has: a higher layer that keeps something per kind
of regular patch (:data:`BICUBIC`, :data:`BOX_SPLINE`) reads it with :meth:`Lattice.select`, and a
fact a lattice does not state raises :class:`~symdecomp.errors.LatticeFactMissing` naming the fact,
never another lattice's answer.

The name (``"quad"``, ``"triangle"``) is the external spelling, in scheme files, JSON and
printed output; :func:`lattice` reads it.

>>> QUAD.regular_valence, TRIANGLE.regular_valence, lattice("triangle") is TRIANGLE
(4, 6, True)
>>> QUAD.vertex_order(3), TRIANGLE.ring_size(5, 2)
(('O', 'a_0', 'a_1', 'a_2', 'b_0', 'b_1', 'b_2'), 16)

The scheme holds its lattice, so the lattice reaches the schemes and patches built from
scheme data (the reference scheme, the patch matrices) only when called.
"""

from __future__ import annotations

from dataclasses import dataclass

from symdecomp.errors import InvalidSchemeError, LatticeFactMissing
from symdecomp.schemes import mesh as _mesh
from symdecomp.schemes import refinement as _refinement

__all__ = ["Lattice", "QuadLattice", "TriangleLattice", "QUAD", "TRIANGLE", "LATTICES", "PAPER_LATTICE", "BICUBIC", "BOX_SPLINE",
           "lattice", "lattice_of",
           "lattice_of_reference"]


#: The regular patch of the quad lattice: the bicubic B-spline (a :attr:`Lattice.patch` kind).
BICUBIC = "bicubic"
#: The regular patch of the triangle lattice: the quartic box spline (a :attr:`Lattice.patch` kind).
BOX_SPLINE = "box-spline"


@dataclass(frozen=True)
class Lattice:
    """A kind of neighbourhood of a vertex: what the code needs to know about the mesh around it."""

    #: The external spelling: ``"quad"`` or ``"triangle"``.
    name: str
    #: The valence of a regular vertex.
    regular_valence: int
    #: Whether the 1-ring has face neighbours ``b_i`` (and the scheme a face rule).
    face_neighbours: bool
    #: The regular patch, as named in reports.
    spline: str
    #: The regular patch's sub-patches, as named in claims and reports.
    subpatches_text: str
    #: The method of the certified C1 test on this lattice (reported with each verdict).
    c1_method: str
    #: Where the sub-patches' parameters live, when not on the lattice's own faces (for the claims' text).
    subpatches_where: str = ""

    def __str__(self) -> str:
        return self.name

    # -- the 1-ring and the K-ring -------------------------------------------------------------

    def one_ring_size(self, n: int) -> int:
        """Points of the 1-ring at valence ``n``: ``2n + 1`` with face neighbours, ``n + 1`` without."""
        return (2 * n if self.face_neighbours else n) + 1

    def vertex_order(self, n: int) -> tuple[str, ...]:
        """Names of the 1-ring points in matrix order: ``O, a_0..a_{n-1}`` and then the ``b_i``, if any."""
        b = tuple(f"b_{i}" for i in range(n)) if self.face_neighbours else ()
        return ("O",) + tuple(f"a_{i}" for i in range(n)) + b

    def ring_of(self, u: int, v: int) -> int:
        """The ring (``0`` for ``O``) of the point ``(s, u, v)`` of a sector."""
        raise LatticeFactMissing(self, "ring_of")

    def ring_size(self, n: int, rings: int) -> int:
        """Points of the closed ``rings``-ring at valence ``n``, the centre included."""
        raise LatticeFactMissing(self, "ring_size")

    def ring_labels(self, n: int, rings: int) -> tuple[tuple[int, int, int], ...]:
        """Labels ``(s, u, v)`` of the closed ``rings``-ring, in matrix order (the centre first)."""
        raise LatticeFactMissing(self, "ring_labels")

    def one_ring_labels(self, n: int) -> tuple[tuple[int, int, int], ...]:
        """The ring labels of the 1-ring points in :meth:`vertex_order`: ``a_i = (i, 1, 0)``, ``b_i = (i, 1, 1)``."""
        b = tuple((i, 1, 1) for i in range(n)) if self.face_neighbours else ()
        return ((0, 0, 0),) + tuple((i, 1, 0) for i in range(n)) + b

    def canonical(self, s: int, u: int, v: int) -> tuple[int, int, int] | None:
        """The label ``(sector, u, v)`` with ``u >= 1`` of a lattice point near sector ``s`` (``None``: ``O``)."""
        raise LatticeFactMissing(self, "canonical")

    # -- meshes and one refinement --------------------------------------------------------------

    #: Sides of every face of a mesh on this lattice (4 on quads, 3 on triangles).
    face_sides = 0  # set by each subclass (a class attribute: not a dataclass field)

    @property
    def regular_face_size(self) -> int:
        """Sides of a regular face (4 on quads, 3 on triangles): the regular valence of the dual mesh."""
        if not self.face_sides:
            raise LatticeFactMissing(self, "regular_face_size")
        return self.face_sides

    def mesh(self, faces, values):
        """A local mesh of this lattice's kind (:class:`~symdecomp.schemes.mesh.QuadMesh`, ``TriangleMesh``)."""
        raise LatticeFactMissing(self, "mesh")

    def ring_mesh(self, n: int, rings: int, values=None):
        """The mesh of ``rings`` rings around a valence-``n`` vertex, every other vertex regular."""
        raise LatticeFactMissing(self, "ring_mesh")

    def mesh_rules(self, scheme):
        """The scheme's 1-ring rules read as rules of the whole mesh (or :class:`InvalidSchemeError`)."""
        raise LatticeFactMissing(self, "mesh_rules")

    def refine(self, mesh, rules, *, vertex_weights=None):
        """One exact refinement of ``mesh`` by ``rules``; ``vertex_weights(valence)`` overrides the vertex rule's weights."""
        raise LatticeFactMissing(self, "refine")

    def refined_point(self, step, old, u: int, v: int, face_of: dict) -> int:
        """The id in ``step`` (a refinement) of the new point at the fine lattice point ``(u, v)``.

        ``old(a, b)`` is the id of the coarse point ``(a, b)`` of the same sector, ``face_of`` maps a
        coarse face (its corners as a frozenset) to its index.
        """
        if u % 2 == 0 and v % 2 == 0:
            return step.vertex_point[old(u // 2, v // 2)]
        if u % 2 == 0 or v % 2 == 0:
            du, dv = u % 2, v % 2
            return step.edge_point[frozenset((old((u - du) // 2, (v - dv) // 2), old((u + du) // 2, (v + dv) // 2)))]
        return self._odd_point(step, old, u, v, face_of)

    def _odd_point(self, step, old, u: int, v: int, face_of: dict) -> int:
        raise LatticeFactMissing(self, "refined_point")

    # -- the regular patch -----------------------------------------------------------------------

    def reference(self):
        """The scheme whose rules at the regular valence give :attr:`spline` (Catmull-Clark, Loop)."""
        raise LatticeFactMissing(self, "reference")

    def patch_matrices(self, scheme, n: int):
        """Stam's patch matrices of ``scheme`` at valence ``n`` (:class:`~symdecomp.schemes.patch.PatchMatrices`)."""
        raise LatticeFactMissing(self, "patch_matrices")

    def level_measure(self, u, v, xp):
        """The size of ``(u, v)`` that one refinement halves: the patch at level ``k`` is where it is in ``(2^-k, 2^(1-k)]``."""
        raise LatticeFactMissing(self, "level_measure")

    def in_domain(self, u, v) -> bool:
        """Whether ``(u, v)`` (each in ``[0, 1]``) is in the patch's parameter domain."""
        return True

    def locate(self, x, y, xp=None):
        """``(k, s, t, sigma)``: sub-patch, local parameters and orientation of ``(x, y)`` with measure in ``(1, 2]``.

        Scalars, or numpy arrays with ``xp=numpy``.
        """
        raise LatticeFactMissing(self, "locate")

    #: Whether the tangent masks turn from ``a_0`` to ``a_1`` in the sense of ``(u, v)`` (the normal is their cross product).
    tangents_along_parameters: bool = True

    # -- facts asked by the analysis, the checks and the commands ---------------------------------

    @property
    def patch(self) -> str:
        """The kind of the regular patch (:data:`BICUBIC`, :data:`BOX_SPLINE`): the key of the tables kept per kind of patch."""
        raise LatticeFactMissing(self, "patch")

    def select(self, table, fact: str):
        """This lattice's entry in ``table``, a higher layer's table keyed by :attr:`patch` kind; ``fact`` names the entry.

        A lattice without a patch kind, or of a kind the table does not hold, raises
        :class:`~symdecomp.errors.LatticeFactMissing` naming ``fact``: no other lattice's entry is taken.
        """
        kind = self.patch
        if kind not in table:
            raise LatticeFactMissing(self, fact, f" (nothing for {kind} patches)")
        return table[kind]

    def handled(self, fact: str, *kinds: str) -> str:
        """:attr:`patch`, which must be one of the ``kinds`` the caller's code for ``fact`` handles (else the fact is missing)."""
        return self.select({kind: kind for kind in kinds}, fact)

    @property
    def paper_claims(self) -> bool:
        """Whether the paper's claims (statements about quad meshes) and Stam's data file speak of this lattice's meshes."""
        raise LatticeFactMissing(self, "paper_claims")

    @property
    def one_ring_classes(self) -> tuple[tuple[str, tuple[int, int]], ...]:
        """The kinds of 1-ring neighbours as ``(name, (u, v))``: ``a`` at ``(1, 0)`` and the face neighbours ``b`` at ``(1, 1)``, if any."""
        return (("a", (1, 0)),) + ((("b", (1, 1)),) if self.face_neighbours else ())

    @property
    def stencil_sections(self) -> tuple[str, ...]:
        """The 1-ring stencils of a scheme on this lattice, named as in scheme files: ``edge``, and ``face`` with face neighbours."""
        return ("edge", "face") if self.face_neighbours else ("edge",)

    def sector_ring(self, r: int) -> tuple[tuple[int, int], ...]:
        """The points ``(u, v)`` of ring ``r`` in one sector of a fan (its first ray's point, not the next ray's), in matrix order."""
        raise LatticeFactMissing(self, "sector_ring")

    @property
    def neighbour_offsets(self) -> tuple[tuple[tuple[int, int], ...], tuple[tuple[int, int], ...]]:
        """``(edge, face)``: the offsets ``(du, dv)`` of a regular point's 1-ring neighbours, counter-clockwise from ``(1, 0)``."""
        raise LatticeFactMissing(self, "neighbour_offsets")

    @property
    def phantom_stencil(self) -> tuple[tuple[int, tuple[int, int]], ...]:
        """The phantom point ``(x, -1)`` beyond a sharp ray as ``((weight, (dx, y)), ...)`` on the real points ``(x + dx, y)``.

        The combination that the regular rules reproduce on every level, so that the spline of the
        extended net is the limit next to the ray (:mod:`symdecomp.schemes.sector_patch`).
        """
        raise LatticeFactMissing(self, "phantom_stencil")

    def cell_faces(self, a: int, b: int, c: int, d: int) -> tuple[tuple[int, ...], ...]:
        """The faces of the lattice cell with corners ``a, b, c, d`` counter-clockwise from ``(x, y)``."""
        raise LatticeFactMissing(self, "cell_faces")

    @property
    def regular_boundary_faces(self) -> int:
        """Faces at a regular boundary vertex (a half-plane): half the regular valence."""
        return self.regular_valence // 2

    def own_or_reference(self, scheme):
        """``scheme`` if it lives on this lattice, else this lattice's reference scheme (:meth:`reference`)."""
        return scheme if scheme.lattice == self else self.reference()

    def others(self) -> tuple[Lattice, ...]:
        """The other lattices (of :data:`LATTICES`), in their order."""
        return tuple(x for x in LATTICES.values() if x != self)


@dataclass(frozen=True)
class QuadLattice(Lattice):
    """Quad meshes (the paper's shape): valence 4 is regular, 1-ring ``(O, a_i, b_i)``, bicubic B-spline patches."""

    def ring_of(self, u, v):
        return max(u, v)

    def ring_size(self, n, rings):
        return 1 + n * rings * (rings + 1)

    def sector_ring(self, r):
        return tuple((u, v) for u in range(1, r + 1) for v in range(r + 1) if max(u, v) == r)

    #: Sides of every face of a mesh on this lattice.
    face_sides = 4
    patch = BICUBIC
    paper_claims = True
    phantom_stencil = ((2, (0, 0)), (-1, (0, 1)))
    neighbour_offsets = (((1, 0), (0, 1), (-1, 0), (0, -1)), ((1, 1), (-1, 1), (-1, -1), (1, -1)))
    #: The local mesh type of this lattice: ``mesh(faces, values)``.
    mesh = staticmethod(_mesh.QuadMesh)
    ring_labels = staticmethod(_mesh.ring_mesh_labels)
    ring_mesh = staticmethod(_mesh.ring_mesh)
    mesh_rules = staticmethod(_refinement.mesh_rules)
    refine = staticmethod(_refinement.refine)

    def canonical(self, s, u, v):
        # points just outside the sector: (s, u, -1) = (s - 1, 1, u) and (s, -1, v) = (s + 1, v, 1)
        if u == -1:
            s, u, v = s + 1, v, 1
        elif v == -1:
            s, u, v = s - 1, 1, u
        if u == 0 and v == 0:
            return None
        if u == 0:
            s, u, v = s + 1, v, 0
        return s, u, v

    def cell_faces(self, a, b, c, d):
        return ((a, b, c, d),)

    def _odd_point(self, step, old, u, v, face_of):  # both odd: the face point
        corners = frozenset(old((u + a) // 2, (v + b) // 2) for a in (-1, 1) for b in (-1, 1))
        return step.face_point[face_of[corners]]

    def reference(self):
        from symdecomp.schemes.scheme import catmull_clark

        return catmull_clark()

    def patch_matrices(self, scheme, n):
        from symdecomp.schemes.patch import quad_patch_matrices

        return quad_patch_matrices(scheme, n)

    def level_measure(self, u, v, xp):
        return xp.maximum(u, v) if xp is not None else max(u, v)

    def locate(self, x, y, xp=None):
        # x, y in [0, 2]: sub-patch 0 below v = 1, then 2 left of u = 1, then 1
        if xp is not None:
            k = xp.where(y < 1, 0, xp.where(x < 1, 2, 1))
            return k, xp.where(k == 2, x, x - 1), xp.where(k == 0, y, y - 1), 1
        if y < 1:
            return 0, x - 1, y, 1
        if x < 1:
            return 2, x, y - 1, 1
        return 1, x - 1, y - 1, 1


@dataclass(frozen=True)
class TriangleLattice(Lattice):
    """Triangle meshes (Loop's shape): valence 6 is regular, 1-ring ``(O, a_i)``, quartic box-spline patches."""

    def ring_of(self, u, v):
        return u + v

    def ring_size(self, n, rings):
        return 1 + n * rings * (rings + 1) // 2

    def sector_ring(self, r):
        return tuple((r - v, v) for v in range(r))

    face_sides = 3
    patch = BOX_SPLINE
    paper_claims = False
    phantom_stencil = ((1, (-1, 0)), (1, (0, 0)), (-1, (-1, 1)))
    neighbour_offsets = (((1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)), ())
    mesh = staticmethod(_mesh.TriangleMesh)
    ring_labels = staticmethod(_mesh.triangle_ring_labels)
    ring_mesh = staticmethod(_mesh.triangle_ring_mesh)
    mesh_rules = staticmethod(_refinement.triangle_mesh_rules)
    refine = staticmethod(_refinement.refine_triangles)

    def canonical(self, s, u, v):
        # sector s spans the lattice directions (1, 0) (ray s) and (0, 1) (ray s + 1); its neighbours are the
        # wedges of (1, -1), (1, 0) (sector s - 1: (u, v), v < 0, is (s - 1, -v, u + v) there) and of (0, 1),
        # (-1, 1) (sector s + 1: (s + 1, u + v, -u))
        if v < 0:
            s, u, v = s - 1, -v, u + v
        elif u < 0:
            s, u, v = s + 1, u + v, -u
        if u < 0 or v < 0:
            raise InvalidSchemeError(f"lattice point ({u}, {v}) lies beyond the neighbouring sectors")
        if u == 0 and v == 0:
            return None
        if u == 0:
            s, u, v = s + 1, v, 0
        return s, u, v

    def cell_faces(self, a, b, c, d):  # split along the diagonal b-d
        return ((a, b, d), (b, c, d))

    def _odd_point(self, step, old, u, v, face_of):  # both odd: the midpoint of the diagonal edge
        return step.edge_point[frozenset((old((u - 1) // 2, (v + 1) // 2), old((u + 1) // 2, (v - 1) // 2)))]

    def reference(self):
        from symdecomp.schemes.loop import loop

        return loop()

    def patch_matrices(self, scheme, n):
        from symdecomp.schemes.patch import triangle_patch_matrices

        return triangle_patch_matrices(scheme, n)

    def level_measure(self, u, v, xp):
        return u + v

    def in_domain(self, u, v):
        return u + v <= 1

    def locate(self, x, y, xp=None):
        # x >= 1: next to a_0; y >= 1: next to a_1; else the middle triangle, upside down (sigma = -1)
        if xp is not None:
            k = xp.where(x >= 1, 0, xp.where(y >= 1, 2, 1))
            s = xp.where(k == 0, x - 1, xp.where(k == 2, x, 1 - x))
            t = xp.where(k == 0, y, xp.where(k == 2, y - 1, 1 - y))
            return k, s, t, xp.where(k == 1, -1.0, 1.0)
        if x >= 1:
            return 0, x - 1, y, 1
        if y >= 1:
            return 2, x, y - 1, 1
        return 1, 1 - x, 1 - y, -1


#: The quad lattice (Catmull-Clark's meshes): regular valence 4.
QUAD = QuadLattice(
    "quad", 4, True, "bicubic B-spline", "three bicubic sub-patches",
    "Reif's test: spectrum per frequency (Arb, exact at frequency 0); Jacobian of the three bicubic "
    "sub-patches in Bernstein-Bezier form (bidegree 5x5, Arb, de Casteljau); winding number of the inner boundary",
    tangents_along_parameters=False,
)
#: The triangle lattice (Loop's meshes): regular valence 6.
TRIANGLE = TriangleLattice(
    "triangle", 6, False, "quartic box-spline", "three quartic box-spline sub-patches (degree-6 Jacobian)",
    "Reif's test: spectrum per frequency (Arb, exact in Q(e^{2 pi i/n}) at frequency 0 and at ties); Jacobian of the "
    "three quartic box-spline sub-patches in triangular Bernstein-Bezier form (degree 6, Arb, de Casteljau bisection); "
    "winding number of the inner boundary",
    ", in the local parameters of the level-1 lattice triangles",
)
#: The lattices, by name.
LATTICES = {x.name: x for x in (QUAD, TRIANGLE)}
#: The lattice of the paper's claims (statements about quad meshes) and of Stam's Catmull-Clark data file.
PAPER_LATTICE = QUAD


def lattice(name: str | Lattice) -> Lattice:
    """The lattice called ``name`` (a :class:`Lattice` is returned as it is); :class:`InvalidSchemeError` if unknown."""
    if isinstance(name, Lattice):
        return name
    if not isinstance(name, str) or name not in LATTICES:
        raise InvalidSchemeError(f"mesh must be one of {tuple(LATTICES)}, got {name!r}")
    return LATTICES[name]


def lattice_of(mesh) -> Lattice:
    """The lattice whose local meshes (:meth:`Lattice.mesh`) ``mesh`` is one of; :class:`LatticeFactMissing` if none."""
    found = [x for x in LATTICES.values() if isinstance(mesh, x.mesh)]  # type: ignore[arg-type]  # x.mesh is the mesh class
    if not found:
        raise LatticeFactMissing(type(mesh).__name__, "mesh", " (no lattice has meshes of this type)")
    return found[0]


def lattice_of_reference(name: str) -> Lattice:
    """The lattice whose reference scheme (:meth:`Lattice.reference`) is called ``name``; :class:`LatticeFactMissing` if none."""
    found = [x for x in LATTICES.values() if x.reference().name == name]
    if not found:
        raise LatticeFactMissing(repr(name), "lattice", " (no lattice has it as its reference scheme)")
    return found[0]
