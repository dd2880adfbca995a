"""Boundary, crease and corner vertices (issue 20): the mirror decomposition's polylines, the characteristic
map of a sector, and where the standard rules fail.

The numbers behind the figures come from the package; nothing is typed in:

* :func:`sector_modes`: the eigenvectors of the 1-ring matrix of a sector, block by block, from
  :func:`symdecomp.analysis.mirror.sector_decomposition` (the similarity transform's columns are the sine
  polylines ``a_i = sin(j pi i/k)``, ``b_i = sin(j pi (i + 1/2)/k)``; a block's eigenvector ``(A, B)`` weights
  them) and :func:`~symdecomp.analysis.mirror.sector_spectrum` (the exact eigenvalues). The crease block's
  eigenvectors live on ``O`` and the sharp-edge points; each continues into the interior by solving
  ``(T - lambda) x = -X c`` in the block lower-triangular matrix ``[[C, 0], [X, T]]``
  (:func:`~symdecomp.analysis.mirror_threshold.crease_eigenvectors`): these are the cosine-type
  (mirror-symmetric or antisymmetric) polylines. Where ``lambda`` is also an eigenvalue of ``T`` the matrix may
  have a Jordan block instead, decided exactly; the figure then draws the chain's generalised eigenvector.
* :func:`sector_characteristic_map`: the image of the sector's faces under two eigenvectors of its ``rings``-ring
  matrix (:func:`symdecomp.schemes.sector.sharp_subdivision_matrix`), refined ``levels`` times by the tagged
  refinement of the whole mesh (:func:`symdecomp.schemes.tagged_refinement.refine_tagged`).
* :func:`subdominant_eigenvalues`: the two largest eigenvalues below the dominant 1 of the exact 1-ring matrix.

The figures: :func:`sector_polylines_figure` (part 1 of notebook 10), :func:`corner_maps_figure` (part 2),
:func:`subdominant_figure` (part 3).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> [round(m.value_float, 6) for m in sector_modes(catmull_clark(), 2)[:3]]   # the crease block: the B-spline's 1, 1/2, 1/4
[1.0, 0.5, 0.25]
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import sympy as sp

from symdecomp.analysis.eigenvalue import MirrorBlock
from symdecomp.analysis.mirror import sector_decomposition, sector_matrix, sector_spectrum
from symdecomp.analysis.mirror_threshold import crease_eigenvectors
from symdecomp.errors import NotApplicableError
from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix
from symdecomp.schemes.tagged_refinement import refine_tagged
from symdecomp.validate import cached, check_int, check_levels, check_type

__all__ = [
    "SectorMode", "sector_modes", "mode_residual", "sector_polylines_figure",
    "SectorMap", "sector_characteristic_map", "sector_map_panel", "corner_maps_figure",
    "SECTOR_KINDS", "subdominant_eigenvalues", "subdominant_figure",
]

#: Digits of the numeric evaluation of exact entries (the figures need a few; the margin keeps cancellations away).
_DIGITS = 30


def _floats(matrix: sp.Matrix) -> np.ndarray:
    return np.array(matrix.evalf(_DIGITS).tolist(), dtype=float)


@dataclass(frozen=True)
class SectorMode:
    """One eigenvector of a sector's 1-ring matrix, with the block of the mirror decomposition it comes from."""

    #: ``"crease"`` (cosine-type: lives on ``O`` and the sharp edges, continued into the interior), ``"sine"`` or ``"face"``.
    block: str
    #: The frequency ``j`` of a sine or face block (``theta = pi j/k``); ``None`` for the crease block.
    j: int | None
    #: The exact eigenvalue (from the block's closed form).
    value: sp.Expr
    #: The eigenvector in the 1-ring order ``O, a_0..a_k, b_0..b_{k-1}`` (floats, largest entry 1 in modulus).
    vector: np.ndarray
    #: False for a crease mode whose eigenvalue has a Jordan block: ``vector`` is then a generalised eigenvector.
    eigenvector: bool = True

    @property
    def value_float(self) -> float:
        """The eigenvalue as a float."""
        return float(sp.N(self.value, _DIGITS))


def _null_vector(matrix: np.ndarray) -> np.ndarray:
    """The right singular vector of the smallest singular value (a kernel vector of a singular matrix)."""
    return np.linalg.svd(matrix)[2][-1]


def _normalised(v: np.ndarray) -> np.ndarray:
    """``v`` scaled to largest entry 1 in modulus, its first entry that is not 0 positive (a fixed sign)."""
    v = np.where(np.abs(v) < 1e-13 * np.max(np.abs(v)), 0.0, v)
    v = v / np.max(np.abs(v))
    first = v[np.flatnonzero(np.abs(v) > 1e-9)[0]]
    return v * np.sign(first)


def _singular_continuation(P: sp.Matrix, crease_rows: list[int], c: sp.Matrix, lam: sp.Expr) -> tuple[np.ndarray, bool]:
    """A crease eigenvector ``c`` (on ``crease_rows``) continued into the interior where ``lambda`` is also an eigenvalue
    of the interior part ``T`` (so :func:`~symdecomp.analysis.mirror_threshold.crease_eigenvectors` gives none):
    ``(v, True)`` with ``S v = lambda v`` when ``(T - lambda) x = -X c`` has solutions (the least-squares one), else
    ``(v, False)`` with ``(S - lambda) v`` an eigenvector of the interior: a Jordan chain, no eigenvector continues
    ``c``. Which of the two is decided exactly, by the ranks of the exact matrices."""
    inner = [r for r in range(P.rows) if r not in crease_rows]
    A = P.extract(inner, inner) - lam * sp.eye(len(inner))
    rhs = -P.extract(inner, crease_rows) * c
    v = np.zeros(P.rows)
    v[crease_rows] = _floats(c).ravel()
    An, b = _floats(A), _floats(rhs).ravel()
    if A.rank(simplify=True) == A.row_join(rhs).rank(simplify=True):
        v[inner] = np.linalg.lstsq(An, b, rcond=None)[0]
        return v, True
    u = np.linalg.svd(An)[2][-1]  # the interior eigenvector (A is singular: the system has no solution)
    v[inner] = np.linalg.lstsq(np.column_stack([An, -u]), b, rcond=None)[0][:-1]
    return v, False


def _crease_modes(scheme: Scheme, vertex, d) -> list[SectorMode]:
    """The crease block's modes: :func:`~symdecomp.analysis.mirror_threshold.crease_eigenvectors` where the
    continuation is unique, :func:`_singular_continuation` where it is not."""
    Q = _floats(d.transform)
    crease_rows = [int(np.flatnonzero(Q[:, c])[0]) for c in range(d.crease.shape[0])]
    exact: dict = {}
    for lam, vector, _ in crease_eigenvectors(scheme, vertex):
        exact.setdefault(lam, []).append(vector)
    modes = []
    for lam, vectors in sorted(exact.items(), key=lambda item: -float(sp.N(item[0], _DIGITS))):
        if all(v is not None for v in vectors):
            modes += [SectorMode("crease", None, lam, _normalised(_floats(v).ravel())) for v in vectors]
            continue
        for c in (d.crease - lam * sp.eye(d.crease.rows)).nullspace(simplify=True):
            v, proper = _singular_continuation(d.matrix, crease_rows, c, lam)
            modes.append(SectorMode("crease", None, lam, _normalised(v), proper))
    return modes


def _sector(vertex):
    """A SharpVertex, or ``k`` (the faces of a boundary sector) as an ``int``."""
    if isinstance(vertex, SharpVertex):
        return vertex
    return check_int(vertex, "vertex (a SharpVertex, or the faces k of a boundary sector)", minimum=1)


def _sharp_vertex(vertex) -> SharpVertex:
    return check_type(vertex, SharpVertex, "vertex", hint="SharpVertex.boundary(k, lattice), .corner(k, lattice, angle)")


@cached(maxsize=16, scheme=check_scheme, vertex=_sector)
def sector_modes(scheme: Scheme, vertex) -> tuple[SectorMode, ...]:
    """The eigenvectors of the 1-ring matrix of ``vertex`` (a SharpVertex, or ``k`` faces of a boundary sector), block by block.

    The sine and face blocks' eigenvectors are their polylines (the transform's columns) weighted by the block's
    eigenvector; the crease block's are continued into the interior (module docstring), or, where the eigenvalue
    has a Jordan block and no eigenvector continues the crease one, the chain's generalised eigenvector
    (``SectorMode.eigenvector`` False).
    """
    d = sector_decomposition(scheme, vertex)
    spectrum = sector_spectrum(scheme, vertex)
    Q = _floats(d.transform)
    modes = _crease_modes(scheme, vertex, d)
    column = d.crease.shape[0]
    for blk in d.blocks:
        width = blk.matrix.shape[0]
        M = _floats(blk.matrix)
        for ev in (e for e in spectrum if e.blocks[0] == MirrorBlock(blk.kind, blk.sector, blk.j)):
            w = _null_vector(M - float(sp.N(ev.value, _DIGITS)) * np.eye(width))
            modes.append(SectorMode(blk.kind, blk.j, ev.value, _normalised(Q[:, column:column + width] @ w)))
        column += width
    return tuple(modes)


def mode_residual(scheme: Scheme, vertex, mode: SectorMode) -> float:
    """``max |S v - lambda v|`` for the exact 1-ring matrix ``S`` of ``vertex``: 0 (to rounding) for an eigenvector."""
    S = _floats(sector_decomposition(scheme, vertex).matrix)
    return float(np.max(np.abs(S @ mode.vector - mode.value_float * mode.vector)))


def _polylines(mode: SectorMode, k: int, quad: bool) -> tuple[tuple[np.ndarray, np.ndarray], ...]:
    """The polylines of the 1-ring's outer points at their angle around ``O`` (in units of the sector's angle):
    ``a_0..a_k`` at ``i/k``, and on quads ``b_0..b_{k-1}`` half way between."""
    a = (np.arange(k + 1) / k, mode.vector[1:k + 2])
    return (a, ((np.arange(k) + 0.5) / k, mode.vector[k + 2:2 * k + 2])) if quad else (a,)


def _value_label(value: sp.Expr) -> str:
    text = sp.latex(value)
    number = f"{float(sp.N(value, _DIGITS)):.6g}"
    return f"$\\lambda = {text}$" if len(text) <= 28 else f"$\\lambda \\approx {number}$"


def sector_polylines_figure(scheme: Scheme, k: int = 5):
    """The eigenvectors of a boundary sector of ``k`` faces as polylines over the sector, one panel per block.

    Each eigenvector is drawn over the sector's angle: its entries on the edge neighbours ``a_0..a_k`` (at ``i/k`` of
    the sector, circles, solid) and on quads on the face neighbours ``b_0..b_{k-1}`` (half way between, squares,
    dashed), with the exact eigenvalue in the legend and the value at ``O`` after it: the crease block's
    cosine-type polylines first (not 0 on the sharp edges), then the sine polylines of frequency ``j``
    (0 on both sharp edges and at ``O``).
    """
    k = check_int(k, "k (the faces of the boundary sector)", minimum=1, maximum=64)
    modes = sector_modes(scheme, k)
    quad = scheme.face_rule is not None
    groups: dict = {}
    for m in modes:
        groups.setdefault((m.block, m.j), []).append(m)
    cols = min(3, len(groups))
    rows = -(-len(groups) // cols)
    fig = new_figure(4.0 * cols, 2.9 * rows)
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False).ravel())
    for ax, ((block, j), group) in zip(axes, groups.items()):
        for index, m in enumerate(group):
            lines = _polylines(m, k, quad)
            note = "" if m.eigenvector else " (Jordan block: generalised)"
            style = "-" if m.eigenvector else ":"
            ax.plot(*lines[0], marker="o", ms=3.5, color=f"C{index}", ls=style,
                    label=f"{_value_label(m.value)}, O: {m.vector[0] + 0.0:.3g}{note}")
            for x, y in lines[1:]:
                ax.plot(x, y, marker="s", ms=3, color=f"C{index}", ls="--", lw=0.8)
        ax.axhline(0.0, color="0.5", lw=0.6)
        title = "crease block (cosine-type)" if block == "crease" else f"{block} block, j = {j}: theta = {j}pi/{k}"
        label_axes(ax, "angle around O (fraction of the sector)", "eigenvector entry", title, loc="best")
    for ax in axes[len(groups):]:
        ax.set_axis_off()
    fig.suptitle(f"{scheme.name}: boundary sector of k = {k} faces, the eigenvectors of the 1-ring matrix by block")
    return fig


# --------------------------------------------------------------------------------------------
# the characteristic map of a sector


@dataclass(frozen=True)
class SectorMap:
    """A sector's characteristic map drawn by refinement (:func:`sector_characteristic_map`)."""

    #: The two eigenvalues of the map's eigenvectors (``x`` and ``y``), as floats: ``lambda_1 >= lambda_2``.
    eigenvalues: tuple[float, float]
    #: The eigenvalues of the ``rings``-ring matrix below the dominant 1, largest first (floats, with multiplicity).
    spectrum: tuple[float, ...]
    #: The refined faces' images, each a closed polygon of complex points ``x + i y``.
    faces: tuple[np.ndarray, ...]
    #: Each face's signed area (positive: the orientation of the sector is kept).
    areas: np.ndarray
    #: The images of the sharp (boundary, crease) edges of the refined mesh, each a complex 2-array.
    sharp_edges: tuple[np.ndarray, ...]
    #: Whether ``lambda_1`` or ``lambda_2`` has a Jordan block (fewer eigenvectors than its multiplicity in the 1-ring).
    defective: bool = False
    #: The map's values ``x + i y`` on the ``rings``-ring (matrix order) before refinement.
    ring: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0, dtype=complex))

    @property
    def folded(self) -> int:
        """The number of faces whose image is reversed against the majority (0 for a map that keeps orientation)."""
        signs = np.sign(self.areas[np.abs(self.areas) > 1e-14 * np.max(np.abs(self.areas))])
        return int(min(np.sum(signs > 0), np.sum(signs < 0)))


def _eigenspace(S: np.ndarray, lam: float, tol: float = 1e-8) -> np.ndarray:
    """An orthonormal basis (columns) of the kernel of ``S - lam I``: singular values below ``tol``."""
    _, sv, vt = np.linalg.svd(S - lam * np.eye(S.shape[0]))
    return vt[sv < tol].T


def _clusters(values: np.ndarray, tol: float = 1e-6) -> list[float]:
    """The distinct values of ``values`` (sorted, largest first) to ``tol`` (a Jordan block splits at ``sqrt(eps)``)."""
    out: list[float] = []
    for v in sorted(values, reverse=True):
        if not out or abs(out[-1] - v) > tol:
            out.append(float(v))
    return out


def _extended(S: np.ndarray, inner: int, v: np.ndarray, lam: float) -> np.ndarray:
    """An eigenvector ``v`` of the leading ``inner x inner`` block of the block lower-triangular ``S`` continued to all of
    ``S``'s points: ``(S_outer - lam) x = -X v`` (least squares: the part along outer modes of ``lam`` is left 0)."""
    X, outer = S[inner:, :inner], S[inner:, inner:] - lam * np.eye(S.shape[0] - inner)
    return np.concatenate([v, np.linalg.lstsq(outer, -X @ v, rcond=None)[0]])


def _map_vector(S: np.ndarray, vertex) -> tuple[np.ndarray, tuple[float, float], bool]:
    """The characteristic map's complex values on the ring (see :func:`sector_characteristic_map`)."""
    inner = vertex.one_ring_size()
    S1 = S[:inner, :inner]
    distinct = _clusters(np.linalg.eigvals(S1).real[np.abs(np.linalg.eigvals(S1).real - 1) > 1e-9])
    k = sum(vertex.sectors)
    angle = float(sp.N(sp.pi if vertex.angle is None else vertex.angle))
    a = slice(1, vertex.edge_count() + 1)
    target = np.exp(1j * angle * (np.arange(vertex.edge_count()) / k - 0.5))
    first = _eigenspace(S1, distinct[0])
    if first.shape[1] >= 2:
        z = first @ np.linalg.lstsq(first[a].astype(complex), target, rcond=None)[0]
        return _extended(S, inner, z, distinct[0]), (distinct[0], distinct[0]), _defective(S1, distinct[:1], first)
    second = _eigenspace(S1, distinct[1])
    x = _extended(S, inner, first @ np.linalg.lstsq(first[a], target.real, rcond=None)[0], distinct[0])
    y = _extended(S, inner, second @ np.linalg.lstsq(second[a], target.imag, rcond=None)[0], distinct[1])
    return x + 1j * y, (distinct[0], distinct[1]), _defective(S1, distinct[:2], first, second)


def _defective(S1: np.ndarray, values: list[float], *spaces: np.ndarray) -> bool:
    """Whether one of ``values`` has fewer eigenvectors (``spaces``) than its multiplicity among ``S1``'s eigenvalues."""
    ev = np.linalg.eigvals(S1).real
    return any(np.sum(np.abs(ev - v) < 1e-6) > E.shape[1] for v, E in zip(values, spaces))


def _signed_area(z: np.ndarray) -> float:
    return 0.5 * float(np.sum(z.real * np.roll(z.imag, -1) - np.roll(z.real, -1) * z.imag))


def sector_characteristic_map(scheme: Scheme, vertex, *, rings: int = 3, levels: int = 3) -> SectorMap:
    """The characteristic map of the sector of ``vertex`` (a SharpVertex), drawn as the image of its refined faces.

    The matrix is the exact ``rings``-ring matrix (:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`,
    evaluated in floats); it is block lower-triangular with the 1-ring matrix first. ``lambda_1 >= lambda_2`` are the
    two largest eigenvalues of the 1-ring matrix below the dominant 1. The map is ``x + i y`` with ``x`` an
    eigenvector of ``lambda_1`` and ``y`` one of ``lambda_2`` on the 1-ring, continued to the outer rings by the
    eigen-equation. Where an eigenvalue is multiple, the eigenvectors are the ones closest (least squares on the edge
    neighbours ``a_0..a_m``) to the sector's regular fan ``a_i -> exp(i alpha (i/k - 1/2))`` of its angle ``alpha``
    (the vertex's angle, ``pi`` if it has none; the mirror axis of the sector on the x axis); when ``lambda_1`` is
    multiple both come from its eigenspace (a complex fit). ``SectorMap.spectrum`` is the whole ``rings``-ring
    matrix's. These values on the tagged ``rings``-ring mesh are refined ``levels`` times with the scheme's rules
    (:func:`~symdecomp.schemes.tagged_refinement.refine_tagged`); the refined faces of the sector's own ``k`` faces
    (those within ``2**levels`` rings of ``O``) are the map's image. (A modified rule at a sharp vertex needs to know
    whether each edge's ends are sharp, which a cut-out ring cannot tell at its rim: each level loses one more ring
    there, hence 3 rings by default.)
    """
    scheme, vertex = check_scheme(scheme), _sharp_vertex(vertex)
    levels = check_levels(levels, "levels", maximum=6)
    S = _floats(sharp_subdivision_matrix(scheme, vertex, rings=rings))
    z, pair, defective = _map_vector(S, vertex)
    ev = np.linalg.eigvals(S)
    below = tuple(float(x) for x in np.sort(ev.real[np.abs(ev.imag) < 1e-9])[::-1] if abs(x - 1) > 1e-9)
    tagged, ids = vertex.tagged_mesh(rings)
    tagged = dataclasses.replace(tagged, mesh=tagged.mesh.with_values({i: (complex(w),) for i, w in enumerate(z)}))
    centre = ids[(0, 0, 0)]
    for _ in range(levels):
        tagged, _, new_ids = refine_tagged(tagged, scheme)
        centre = new_ids[("vertex", centre)]
    mesh = tagged.mesh.neighbourhood(centre, 2**levels)  # the refined faces of the sector's own k faces
    values = mesh.values
    faces = tuple(np.array([values[v][0] for v in f], dtype=complex) for f in mesh.faces)
    inside = {frozenset(e) for e in mesh._directed}
    sharp = [e for e in tagged.boundary_edges() | {e for e, s in tagged.edge_sharpness.items() if s > 0} if e in inside]
    edges = tuple(np.array([values[v][0] for v in sorted(e)], dtype=complex) for e in sharp)
    return SectorMap(pair, below, faces, np.array([_signed_area(f) for f in faces]), edges, defective, z)


def _map_title(scheme: Scheme, k: int, angle, m: SectorMap) -> str:
    l1, l2 = m.eigenvalues
    l3 = m.spectrum[2] if len(m.spectrum) > 2 else 0.0
    third = "lambda_3 = lambda_2: no gap" if abs(l3 - l2) < 1e-6 else f"lambda_3 = {l3:.4f}"
    notes = (f"; {m.folded} faces reversed" if m.folded else "") + ("; Jordan block" if m.defective else "")
    return f"{scheme.name}, k = {k}, angle {sp.sstr(angle)}\nlambda_1, lambda_2 = {l1:.4f}, {l2:.4f}\n{third}{notes}"


def sector_map_panel(ax, m: SectorMap) -> None:
    """Draw a :class:`SectorMap` on ``ax``: the refined faces' images (grey; filled red where a face's image is
    reversed), the sharp edges (blue) and ``O``."""
    for z in m.faces:
        closed = np.append(z, z[:1])
        ax.plot(closed.real, closed.imag, color="0.55", lw=0.4)
    reversed_sign = -1 if np.sum(m.areas > 0) >= np.sum(m.areas < 0) else 1
    for z in (z for z, area in zip(m.faces, m.areas) if np.sign(area) == reversed_sign):
        ax.fill(z.real, z.imag, color="C3", alpha=0.6)
    for e in m.sharp_edges:
        ax.plot(e.real, e.imag, color="C0", lw=1.8)
    ax.plot([0], [0], "k+")
    ax.set_aspect("equal")
    ax.set_xlabel("x (eigenvector of lambda_1)")
    ax.set_ylabel("y (eigenvector of lambda_2)")


def corner_maps_figure(schemes, corners=((2, sp.pi / 2), (3, 3 * sp.pi / 2)), *, levels: int = 3):
    """The characteristic maps of corners, one row per scheme, one column per corner ``(k faces, angle)``.

    Each panel is :func:`sector_characteristic_map` of ``SharpVertex.corner(k, lattice, angle)``: the refined
    faces' images (grey; filled red where a face's image is reversed), the sharp edges (the two boundary curves,
    blue) and ``O``; the title gives the map's eigenvalues and the next one in the spectrum.
    """
    schemes, corners = [check_scheme(x) for x in schemes], list(corners)
    fig = new_figure(4.4 * len(corners), 3.9 * len(schemes))
    axes = fig.subplots(len(schemes), len(corners), squeeze=False)
    for row, scheme in zip(axes, schemes):
        for ax, (k, angle) in zip(row, corners):
            m = sector_characteristic_map(scheme, SharpVertex.corner(k, scheme.lattice, angle), levels=levels)
            sector_map_panel(ax, m)
            ax.set_title(_map_title(scheme, k, angle, m), fontsize=8)
    fig.suptitle("Characteristic maps of corners: the sector's faces refined, boundary curves in blue, reversed faces in red")
    return fig


# --------------------------------------------------------------------------------------------
# where the standard rules fail: the subdominant eigenvalues over k


@cached(maxsize=512, scheme=check_scheme, vertex=_sharp_vertex)
def subdominant_eigenvalues(scheme: Scheme, vertex) -> tuple[float, float]:
    """``(lambda_1, lambda_2)``: the two largest eigenvalues below the dominant 1 of the exact 1-ring matrix of ``vertex``
    (a SharpVertex; :func:`~symdecomp.analysis.mirror.sector_matrix`, the 1-ring matrix assembled from the stencils,
    equal to :func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`'s; evaluated in floats; with multiplicity)."""
    ev = np.linalg.eigvals(_floats(sector_matrix(scheme, vertex)))
    values = sorted((float(x.real) for x in ev), reverse=True)
    if abs(values[0] - 1) > 1e-9:
        raise NotApplicableError(f"scheme {scheme.name!r}: the sector's largest eigenvalue is {values[0]}, not 1")
    return values[1], values[2]


#: The sector kinds of :func:`subdominant_figure`: a title and the vertex of ``k`` faces on a lattice.
SECTOR_KINDS = (
    ("boundary", lambda k, lat: SharpVertex.boundary(k, lat)),
    ("convex corner, angle pi/2", lambda k, lat: SharpVertex.corner(k, lat, sp.pi / 2)),
    ("concave corner, angle 3pi/2", lambda k, lat: SharpVertex.corner(k, lat, 3 * sp.pi / 2)),
)


def subdominant_figure(pairs, ks=range(1, 17)):
    """Where the standard rules fail: ``lambda_1`` and ``lambda_2`` over the sector's faces ``k``, one row per
    ``(standard, modified)`` pair of schemes, one column per kind of sector (:data:`SECTOR_KINDS`).

    The standard rules' eigenvalues are solid, the modified ones dashed; the boundary curve's eigenvalue
    (:func:`~symdecomp.analysis.mirror_threshold.boundary_eigenvalue`, 1/2) is the dotted line: a ``lambda_1`` above
    it means the surface's tangent plane at the vertex is not spanned by the boundary curves' tangents.
    """
    from symdecomp.analysis.mirror_threshold import boundary_eigenvalue

    pairs, ks = [tuple(p) for p in pairs], [int(k) for k in ks]
    fig = new_figure(4.2 * len(SECTOR_KINDS), 3.2 * len(pairs))
    axes = fig.subplots(len(pairs), len(SECTOR_KINDS), squeeze=False)
    for row, schemes in zip(axes, pairs):
        curve = float(sp.N(boundary_eigenvalue(schemes[0])))
        for ax, (kind, make) in zip(row, SECTOR_KINDS):
            for scheme, style in zip(schemes, ("-", "--")):
                values = np.array([subdominant_eigenvalues(scheme, make(k, scheme.lattice)) for k in ks])
                ax.plot(ks, values[:, 0], ls=style, marker="o", ms=3, color="C0", label=f"{scheme.name}: lambda_1")
                ax.plot(ks, values[:, 1], ls=style, marker="s", ms=3, color="C1", label=f"{scheme.name}: lambda_2")
            ax.axhline(curve, color="k", ls=":", lw=1, label=f"boundary curve: {sp.sstr(boundary_eigenvalue(schemes[0]))}")
            label_axes(ax, "faces k of the sector", "eigenvalue", f"{schemes[0].lattice} lattice, {kind}", loc="lower right")
    fig.suptitle("The subdominant eigenvalues against k: standard rules solid, modified rules dashed")
    return fig
