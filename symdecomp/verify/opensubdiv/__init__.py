"""A bridge to OpenSubdiv's Catmull-Clark refinement (optional; needs the built C++ library).

:func:`osd_central_rings` pushes a quad mesh through OpenSubdiv's uniform Catmull-Clark
refinement (``Far::TopologyRefiner`` and ``Far::PrimvarRefinerReal<double>``, double
precision) and reads back a vertex's 1-ring ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` at every level,
in the order of :func:`symdecomp.schemes.scheme.subdivision_matrix`, plus OpenSubdiv's own limit
position of the vertex. It is the outside reference the oracle comparisons
(:mod:`symdecomp.verify.oracle`) check the toolkit against.

The bridge is a small C++ library (``osd_bridge.cpp``) built with the system g++ by
``python symdecomp/verify/opensubdiv/build.py`` (CI does this). :func:`bridge_available` says whether
it can be used; :func:`load_bridge` builds it on demand when the compiler and the OpenSubdiv
headers are present. Nothing else in symdecomp needs it.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from __future__ import annotations

import ctypes
import threading
from dataclasses import dataclass

import numpy as np

from symdecomp.errors import BridgeUnavailableError, InternalError, InvalidInputError, SymdecompError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, lattice_of
from symdecomp.schemes.mesh import QuadMesh
from symdecomp.verify.opensubdiv import build as _build

__all__ = ["BridgeUnavailableError", "OsdRings", "bridge_available", "load_bridge", "osd_central_rings", "osd_limit_points", "osd_limit_frames"]


_lock = threading.Lock()
_lib = None


def load_bridge(build: bool = True):
    """The loaded bridge library, trusted only after a version check and a self-test.

    Builds it first if it is missing or stale (and ``build``). A library that does not load,
    reports another interface version or fails the self-test is rebuilt once; if it still
    fails, :class:`BridgeUnavailableError` says why and names the command that fixes it.
    """
    global _lib, _why_not
    with _lock:
        if _lib is not None:
            return _lib
        try:
            try:
                lib = _load_checked(build, force=False)
            except BridgeUnavailableError:
                if not build:
                    raise
                lib = _load_checked(build, force=True)  # a truncated or stale library: rebuild once
        except BridgeUnavailableError as exc:
            _why_not = str(exc)
            raise
        _lib = lib
        return lib


def _load_checked(build: bool, *, force: bool):
    fix = f"run: {_build.REBUILD_COMMAND}"
    try:
        path = _build.build(force=force) if build else _build.LIBRARY
    except _build.BridgeBuildError as exc:
        raise BridgeUnavailableError(f"OpenSubdiv bridge unavailable: {exc}") from None
    except OSError as exc:
        raise BridgeUnavailableError(f"OpenSubdiv bridge unavailable: cannot build it ({exc}); {fix}") from None
    if not path.exists():
        raise BridgeUnavailableError(f"the OpenSubdiv bridge is not built ({path}); {fix}")
    try:
        _build.check_build_dir()  # build() checked it too; a library found without building is checked here
    except _build.BridgeBuildError as exc:
        raise BridgeUnavailableError(f"OpenSubdiv bridge unavailable: {exc}") from None
    if not build and not _build.is_current():
        raise BridgeUnavailableError(f"the OpenSubdiv bridge library {path} is stale or damaged; {fix}")
    try:
        lib = ctypes.CDLL(str(path))
        version = lib.symdecomp_osd_bridge_version
        fn = lib.symdecomp_osd_refine_ring
    except (OSError, AttributeError) as exc:
        raise BridgeUnavailableError(f"the OpenSubdiv bridge library {path} does not load ({exc}); {fix}") from None
    version.restype = ctypes.c_int
    if version() != _build.BRIDGE_VERSION:
        raise BridgeUnavailableError(
            f"the OpenSubdiv bridge library {path} has interface version {version()}, not {_build.BRIDGE_VERSION}; {fix}"
        )
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ctypes.c_int, ctypes.c_int, ip, dp, ctypes.c_int, ctypes.c_int, ip, ip, ctypes.c_int, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    problem = _self_test(lib)
    if problem:
        raise BridgeUnavailableError(f"the OpenSubdiv bridge library {path} fails its self-test ({problem}); {fix}")
    return lib


def _self_test(lib) -> str | None:
    """Refine a small valence-5 mesh two levels in OpenSubdiv and compare with the exact rules."""
    from fractions import Fraction

    from symdecomp.schemes.mesh import ring_mesh
    from symdecomp.schemes.refinement import central_rings
    from symdecomp.schemes.scheme import catmull_clark

    mesh = ring_mesh(5, 3, lambda s, u, v: (Fraction(s + 2 * u), Fraction(u * v - s), Fraction(v * v + 1, 3)))
    try:
        got = _refine(lib, mesh, 0, 2, None)
    except SymdecompError as exc:
        return str(exc)
    want = np.array([[[float(x) for x in point] for point in ring] for ring in central_rings(mesh, catmull_clark(), 0, 2)])
    if got.rings.shape != want.shape or not np.all(np.isfinite(got.rings)):
        return "it returned no finite values"
    error = float(np.max(np.abs(got.rings - want)))
    return None if error < 1e-12 else f"its refinement differs from Catmull-Clark's rules by {error:.2e}"


def bridge_available(build: bool = True) -> bool:
    """Whether the OpenSubdiv bridge can be used (building it on demand if ``build``)."""
    try:
        load_bridge(build)
        return True
    except BridgeUnavailableError:
        return False


@dataclass(frozen=True)
class OsdRings:
    """What OpenSubdiv computed for one vertex."""

    #: ``(levels + 1, 2n + 1, 3)`` array: the 1-ring ``(O, a_0.., b_0..)`` at levels ``0..levels``.
    rings: np.ndarray
    #: OpenSubdiv's limit position of the vertex (its limit mask applied at the last level).
    limit: np.ndarray


def osd_central_rings(mesh: QuadMesh, center: int, levels: int, *, start: int | None = None) -> OsdRings:
    """Refine ``mesh`` (3-vector values) ``levels`` times in OpenSubdiv; the 1-ring of ``center`` per level.

    ``center`` must be an interior vertex. Its ring starts at ``start`` (default as in
    :meth:`~symdecomp.schemes.mesh.QuadMesh.one_ring`). Values are converted to double.
    """
    lib = load_bridge()
    return _refine(lib, mesh, center, levels, start)


def _refine(lib, mesh: QuadMesh, center: int, levels: int, start: int | None) -> OsdRings:
    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 0:
        raise InvalidInputError(f"levels must be a non-negative integer, got {levels!r}")
    o, a, _ = mesh.one_ring(center, start)
    n = len(a)
    ids = mesh.vertices()
    index = {v: i for i, v in enumerate(ids)}
    pos = np.array([[float(x) for x in mesh.values[v]] for v in ids], dtype=np.float64)
    if pos.shape[1] != 3:
        raise InvalidInputError(f"OpenSubdiv bridge needs 3-vector values, got length {pos.shape[1]}")
    faces = np.array([[index[v] for v in f] for f in mesh.faces], dtype=np.intc)
    # face i of the ring: the one where O is followed by a_i
    ring_faces = []
    for ai in a:
        for fi, f in enumerate(mesh.faces):
            k = f.index(o) if o in f else -1
            if k >= 0 and f[(k + 1) % 4] == ai:
                ring_faces.append(fi)
                break
    ring_a = np.array([index[x] for x in a], dtype=np.intc)
    ring_faces = np.array(ring_faces, dtype=np.intc)
    out = np.zeros((levels + 1, 2 * n + 1, 3), dtype=np.float64)
    limit = np.zeros(3, dtype=np.float64)
    err = ctypes.create_string_buffer(512)
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    pos = np.ascontiguousarray(pos)
    rc = lib.symdecomp_osd_refine_ring(
        len(ids), len(mesh.faces), faces.ctypes.data_as(ip), pos.ctypes.data_as(dp), index[o], n,
        ring_a.ctypes.data_as(ip), ring_faces.ctypes.data_as(ip), levels, out.ctypes.data_as(dp),
        limit.ctypes.data_as(dp), err, len(err),
    )
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    return OsdRings(out, limit)


#: The bridge's limit-point program for each kind of regular patch (OpenSubdiv's Catmark and Loop schemes).
_LIMIT_POINTS = {BICUBIC: "symdecomp_osd_limit_points", BOX_SPLINE: "symdecomp_osd_loop_limit_points"}


def osd_limit_points(mesh, levels: int) -> tuple[np.ndarray, np.ndarray]:
    """``(points, limits)``: every vertex of ``mesh`` refined ``levels`` times in OpenSubdiv, and its limit position.

    A :class:`~symdecomp.schemes.mesh.QuadMesh` goes through Catmull-Clark, a triangle mesh
    (:class:`~symdecomp.schemes.mesh.TriangleMesh`) through Loop. Both ``(V_L, 3)`` arrays
    in OpenSubdiv's vertex order of the last level (match the points to find a vertex).
    Boundary vertices use OpenSubdiv's edge-only boundary rules.
    """
    name = lattice_of(mesh).select(_LIMIT_POINTS, "an OpenSubdiv limit-point program")
    lib = load_bridge()
    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 0:
        raise InvalidInputError(f"levels must be a non-negative integer, got {levels!r}")
    try:
        fn = getattr(lib, name)
    except AttributeError:
        raise BridgeUnavailableError(f"the OpenSubdiv bridge has no limit-points function; run: {_build.REBUILD_COMMAND}") from None
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ctypes.c_int, ctypes.c_int, ip, dp, ctypes.c_int, ctypes.c_int, ip, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    ids = mesh.vertices()
    index = {v: i for i, v in enumerate(ids)}
    pos = np.ascontiguousarray([[float(x) for x in mesh.values[v]] for v in ids], dtype=np.float64)
    if pos.shape[1] != 3:
        raise InvalidInputError(f"OpenSubdiv bridge needs 3-vector values, got length {pos.shape[1]}")
    faces = np.ascontiguousarray([[index[v] for v in f] for f in mesh.faces], dtype=np.intc)
    capacity = len(ids) * 4**levels + len(mesh.faces) * 4**levels + 16
    points = np.zeros((capacity, 3))
    limits = np.zeros((capacity, 3))
    count = ctypes.c_int(0)
    err = ctypes.create_string_buffer(512)
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    rc = fn(
        len(ids), len(mesh.faces), faces.ctypes.data_as(ip), pos.ctypes.data_as(dp), levels, capacity,
        ctypes.byref(count), points.ctypes.data_as(dp), limits.ctypes.data_as(dp), err, len(err),
    )
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    return points[: count.value], limits[: count.value]


def osd_limit_frames(points, faces, *, loop: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(limits, du, dv)``: OpenSubdiv's limit position and first derivatives at every vertex of a whole mesh.

    ``points`` is a ``(V, 3)`` array of doubles, ``faces`` a ``(F, 4)`` (Catmull-Clark) or, with ``loop``,
    ``(F, 3)`` (Loop) array of 0-based vertex indices, counter-clockwise. Each result is ``(V, 3)``, in the
    vertex order of ``points`` (``Far::PrimvarRefiner::Limit`` on the unrefined mesh, double precision;
    boundary vertices use the edge-only boundary rules).
    """
    lib = load_bridge()
    try:
        fn = lib.symdecomp_osd_limit_frames
    except AttributeError:
        raise BridgeUnavailableError(f"the OpenSubdiv bridge has no limit-frames function; run: {_build.REBUILD_COMMAND}") from None
    pos = np.ascontiguousarray(points, dtype=np.float64)
    idx = np.ascontiguousarray(faces, dtype=np.intc)
    sides = 3 if loop else 4
    if pos.ndim != 2 or pos.shape[1] != 3 or idx.ndim != 2 or idx.shape[1] != sides:
        raise InvalidInputError(f"expected (V, 3) points and (F, {sides}) faces, got {pos.shape} and {idx.shape}")
    if idx.size and (idx.min() < 0 or idx.max() >= len(pos)):
        raise InvalidInputError("a face refers to a vertex outside the points")
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.c_int, ip, dp, dp, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    limits, du, dv = (np.zeros_like(pos) for _ in range(3))
    err = ctypes.create_string_buffer(512)
    rc = fn(int(loop), len(pos), len(idx), idx.ctypes.data_as(ip), pos.ctypes.data_as(dp), limits.ctypes.data_as(dp),
            du.ctypes.data_as(dp), dv.ctypes.data_as(dp), err, len(err))
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    return limits, du, dv
