"""A mesh written with double coordinates, with a colour and a quality value per vertex: PLY or OBJ for Blender and MeshLab.

:func:`vertex_colors` turns per-vertex values into colours: a verdict or a regime (text) by a fixed table
(green for ``c1`` and ``bounded``, red for ``not-c1`` and ``unbounded``, blue for ``zero``, amber for
``undecided``, grey for a vertex not analysed or ``n/a``), a number by a blue-white-red ramp over its range
(``NaN`` grey). :func:`colored_ply` writes binary little-endian PLY with ``red green blue`` (uchar) and
``quality`` (float) vertex properties; :func:`colored_obj` writes ``v x y z r g b`` lines (colours in
``[0, 1]``, the extension Blender and MeshLab read). Coordinates are written as float64 (PLY ``double``) and
in OBJ with ``repr`` precision, so a double reads back unchanged.

>>> import numpy as np
>>> vertex_colors(np.array(["c1", "not-c1", "n/a"], dtype=object))[:, :3].tolist()
[[46, 160, 67], [214, 39, 40], [160, 160, 160]]
>>> colored_obj(np.zeros((3, 3)), [(0, 1, 2)], np.array([[255, 0, 0]] * 3, dtype=np.uint8)).splitlines()[0]
'v 0.0 0.0 0.0 1 0 0'
"""

from __future__ import annotations

import numpy as np

__all__ = ["CATEGORY_COLORS", "vertex_colors", "colored_ply", "colored_obj"]

#: The colour of each verdict and regime word (RGB, 0..255).
CATEGORY_COLORS = {
    "c1": (46, 160, 67), "bounded": (46, 160, 67), "not-c1": (214, 39, 40), "unbounded": (214, 39, 40),
    "zero": (31, 119, 180), "undecided": (255, 170, 0), "n/a": (160, 160, 160), "not analysed": (160, 160, 160),
}
_GREY = (160, 160, 160)


def _ramp(values: np.ndarray) -> np.ndarray:
    """Blue (lowest) through white to red (highest); ``NaN`` grey."""
    out = np.tile(np.array(_GREY, dtype=np.float64), (len(values), 1))
    finite = np.isfinite(values)
    if finite.any():
        low, high = float(values[finite].min()), float(values[finite].max())
        t = (values[finite] - low) / (high - low) if high > low else np.full(finite.sum(), 0.5)
        blue, white, red = np.array([59, 76, 192.0]), np.array([245, 245, 245.0]), np.array([180, 4, 38.0])
        lower = t[:, None] < 0.5
        s = np.where(lower, 2 * t[:, None], 2 * t[:, None] - 1)
        out[finite] = np.where(lower, blue + s * (white - blue), white + s * (red - white))
    return out


def vertex_colors(values: np.ndarray) -> np.ndarray:
    """``(V, 3)`` uint8 colours of per-vertex ``values`` (words by :data:`CATEGORY_COLORS`, numbers by a ramp)."""
    values = np.asarray(values)
    if values.dtype.kind in "fiub":
        return np.rint(_ramp(values.astype(np.float64))).astype(np.uint8)
    return np.array([CATEGORY_COLORS.get(str(v), _GREY) for v in values], dtype=np.uint8).reshape(-1, 3)


def colored_ply(points: np.ndarray, faces, colors: np.ndarray | None = None, quality: np.ndarray | None = None) -> bytes:
    """Binary PLY: ``x y z`` doubles, then (with ``colors``) ``red green blue`` uchar and ``quality`` float per vertex."""
    V = len(points)
    colored = colors is not None
    extra = "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\n" if colored else ""
    header = ("ply\nformat binary_little_endian 1.0\ncomment written by symdecomp\n"
              f"element vertex {V}\nproperty double x\nproperty double y\nproperty double z\n{extra}"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n").encode("ascii")
    vertex = np.zeros(V, dtype=[("p", "<f8", 3), ("c", "u1", 3), ("q", "<f4")] if colored else [("p", "<f8", 3)])
    vertex["p"] = points
    if colored:
        quality = np.zeros(V) if quality is None else np.asarray(quality, dtype=np.float64)
        vertex["c"], vertex["q"] = colors, np.nan_to_num(quality, nan=0.0)
    body = [header, vertex.tobytes()]
    for f in faces:
        body.append(np.uint8(len(f)).tobytes() + np.asarray(f, dtype="<i4").tobytes())
    return b"".join(body)


def colored_obj(points: np.ndarray, faces, colors: np.ndarray | None = None, creases: dict | None = None) -> str:
    """OBJ with ``v x y z`` (and ``r g b`` in ``[0, 1]`` with ``colors``), 1-based ``f`` lines, and OpenSubdiv's
    ``t crease 2 1 u v s`` lines for ``creases`` (``(u, v)`` -> sharpness; infinite written as 10)."""
    xyz = np.asarray(points, dtype=np.float64).tolist()
    if colors is None:
        lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in xyz]
    else:
        lines = [f"v {x!r} {y!r} {z!r} {r / 255:.6g} {g / 255:.6g} {b / 255:.6g}"
                 for (x, y, z), (r, g, b) in zip(xyz, np.asarray(colors).tolist())]
    lines += ["f " + " ".join(str(v + 1) for v in f) for f in faces]
    lines += [f"t crease 2/1/0 {u} {v} {10.0 if s == float('inf') else float(s)!r}" for (u, v), s in (creases or {}).items()]
    return "\n".join(lines) + "\n"
