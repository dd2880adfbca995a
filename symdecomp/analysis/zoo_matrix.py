"""The subdivision matrix of a StencilScheme at valence ``n``, read from its refined neighbourhood.

The engine builds the :class:`~symdecomp.schemes.neighbourhood.Neighbourhood` of the centre
(a vertex of valence ``n``, or an ``n``-sided face for a dual scheme), refines its explicit mesh
by the scheme's rules :attr:`~symdecomp.schemes.stencils.StencilScheme.steps` times
(:func:`~symdecomp.schemes.topology.refine_step`: sqrt(3) is analysed over two steps), finds the
centre again by tracking the start halfedge, labels the refined neighbourhood of the same depth by
the same canonical traversal, and reads the rows: entry ``(i, j)`` is the exact weight of old
point ``j`` in new point ``i``, both in the neighbourhood's order. The ring depth is the smallest
for which every point of the new neighbourhood is computable from the old one (closure), or the
caller's.

>>> import sympy as sp
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> zm = zoo_matrix(ds, 4)
>>> zm.depth, zm.matrix.shape, zm.matrix[0, :4]
(1, (16, 16), Matrix([[9/16, 3/16, 1/16, 3/16]]))
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.halfedge import HalfedgeMesh, halfedge_mesh
from symdecomp.schemes.lattice import lattice as lattice_named
from symdecomp.schemes.neighbourhood import Neighbourhood, label_points, local_faces, neighbourhood
from symdecomp.schemes.stencil_rows import Row
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.schemes.topology import refine_step, topology_of
from symdecomp.validate import check_int, check_type, check_valence

__all__ = ["ZooMatrix", "zoo_matrix", "compose_rows", "MAX_DEPTH", "MAX_GIVEN_DEPTH"]

#: The deepest neighbourhood the closure tries before giving up.
MAX_DEPTH = 4
#: The deepest neighbourhood asked for by depth (Zorin's test solves its net on one as deep as its regular stencils reach).
MAX_GIVEN_DEPTH = 8


@dataclass(frozen=True)
class ZooMatrix:
    """The subdivision matrix of a StencilScheme on its neighbourhood of one valence."""

    #: The scheme's name.
    scheme: str
    #: The valence (or the centre face's number of sides).
    n: int
    #: The neighbourhood (its orbit labelling orders the rows and columns).
    neighbourhood: Neighbourhood
    #: How many steps of the scheme the matrix is (2 for sqrt(3): the lattice comes back after two).
    steps: int
    #: The exact matrix, rows and columns in :attr:`Neighbourhood.order`.
    matrix: sp.ImmutableMatrix

    @property
    def depth(self) -> int:
        """The ring depth of the neighbourhood."""
        return self.neighbourhood.depth


def compose_rows(rows: dict[int, Row], previous: dict[int, Row] | None) -> dict[int, Row]:
    """The rows of a later step on the vertices before an earlier one (``previous``; ``None``: the identity)."""
    if previous is None:
        return rows
    out = {}
    for i, row in rows.items():
        acc: Row = {}
        for v, w in row.items():
            for u, x in previous[v].items():
                acc[u] = acc.get(u, 0) + w * x
        out[i] = {u: sp.expand(x) for u, x in acc.items()}
    return out


def _refined(scheme: StencilScheme, nb: Neighbourhood) -> tuple[HalfedgeMesh, int, dict[int, Row]] | None:
    """``(mesh, start, rows)`` after the scheme's steps, or ``None`` when the centre is lost at this depth."""
    topology = topology_of(scheme)
    mesh, start = nb.mesh, nb.start
    rows: dict[int, Row] | None = None
    for step in range(scheme.steps):
        st = refine_step(scheme, mesh, regular=nb.regular_valence)
        origin, tip = topology.track(mesh, start, step)
        if origin not in st.ids or tip not in st.ids or (st.ids[origin], st.ids[tip]) not in st.mesh.by_edge:
            return None
        rows = compose_rows(st.rows, rows)
        mesh, start = st.mesh, st.mesh.by_edge[(st.ids[origin], st.ids[tip])]
    assert rows is not None  # a scheme has at least one step
    return mesh, start, rows


def _matrix_at(scheme: StencilScheme, nb: Neighbourhood) -> sp.ImmutableMatrix | None:
    """The matrix on ``nb`` if its depth is invariant (every new neighbourhood point computable), else ``None``."""
    refined = _refined(scheme, nb)
    if refined is None:
        return None
    mesh, start, rows = refined
    if mesh.ring(start) is None and nb.centred == "vertex":
        return None
    faces = local_faces(mesh, start, nb.depth, nb.centred)
    if len(faces) != len(nb.mesh.faces):
        return None
    sub = halfedge_mesh(tuple(mesh.faces[f] for f in faces))
    sub_start = sub.halfedge(mesh.origin[start], mesh.tip(start))
    _, classes, _, order = label_points(sub, sub_start, nb.n, nb.centred)
    if classes != nb.classes:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the refined neighbourhood is not labelled like the old one "
                                 f"(the topology's track of the centre is inconsistent)")
    old = nb.index()
    entries = {}
    for i, v in enumerate(order):
        for u, w in rows[v].items():
            entries[(i, old[u])] = w
    return sp.ImmutableMatrix(sp.SparseMatrix(len(order), len(old), entries))


def zoo_matrix(scheme: StencilScheme, n: int, depth: int | None = None) -> ZooMatrix:
    """The exact subdivision matrix of ``scheme`` at valence ``n`` on its neighbourhood.

    ``depth``: the ring depth (default: the smallest invariant one, up to :data:`MAX_DEPTH`).
    """
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    n = check_valence(n)
    lat = lattice_named(scheme.lattice)
    centred = topology_of(scheme).centre
    depths = [check_int(depth, "depth", minimum=1, maximum=MAX_GIVEN_DEPTH)] if depth is not None else range(1, MAX_DEPTH + 1)
    for d in depths:
        nb = neighbourhood(lat, n, d, centred=centred)
        S = _matrix_at(scheme, nb)
        if S is not None:
            return ZooMatrix(scheme.name, n, nb, scheme.steps, S)
    where = f"depth {depth}" if depth is not None else f"any depth up to {MAX_DEPTH}"
    raise InvalidSchemeError(f"scheme {scheme.name!r}: the neighbourhood of {where} is not invariant "
                             f"(the new neighbourhood needs points beyond it)")
