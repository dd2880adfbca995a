"""The refined mesh ``symdecomp refine --plot`` draws: the refined faces shaded, the control mesh's edges light.

:func:`refine_figure` takes the points and faces the command writes (the exact points as doubles) and the control
mesh it read, and draws them in 3-D from a fixed direction (:data:`VIEW`) with a fixed light
(:data:`~symdecomp.output.plotting.meshes.LIGHT`), so that the picture is the same every run. A refined mesh of more
than :data:`MAX_REFINED_FACES` faces is drawn from an even sample of them (one face in ``s``; the title says so), and
a control mesh of more than that many faces the same way, rather than spending minutes on a picture.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from symdecomp.output.plotting._mpl import new_figure
from symdecomp.output.plotting.meshes import equal_axes, even_sample, shaded_colors
from symdecomp.validate import MAX_REFINED_FACES

__all__ = ["MAX_REFINED_FACES", "VIEW", "refine_figure"]


#: The fixed view of the figures of meshes: elevation and azimuth in degrees.
VIEW = (28.0, -60.0)

#: The colour of the refined faces, before shading.
FACE_COLOUR = (0.55, 0.7, 0.95)


def _edges(faces: Sequence[Sequence[int]]) -> list[tuple[int, int]]:
    """The edges of ``faces``, each once, in the order they first appear."""
    seen: dict[tuple[int, int], None] = {}
    for face in faces:
        for u, v in zip(face, tuple(face[1:]) + (face[0],)):
            seen.setdefault((min(u, v), max(u, v)), None)
    return list(seen)


def refine_figure(points: Any, faces: Sequence[Sequence[int]], control_points: Any,
                  control_faces: Sequence[Sequence[int]], title: str) -> Any:
    """The refined mesh (``points``, ``faces``) shaded, the control mesh's edges over it in light grey."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    points = np.asarray(points, dtype=float).reshape(-1, 3)
    control = np.asarray(control_points, dtype=float).reshape(-1, 3)
    step = even_sample(len(faces), MAX_REFINED_FACES)
    polygons = [points[list(f)] for f in faces[::step]]
    fig = new_figure(7, 6)
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=shaded_colors(polygons, FACE_COLOUR),
                                         edgecolors=(0, 0, 0, 0.25), linewidths=0.2, label="refined faces"))
    control_step = even_sample(len(control_faces), MAX_REFINED_FACES)
    segments = [control[[u, v]] for u, v in _edges(control_faces[::control_step])]
    ax.add_collection3d(Line3DCollection(segments, colors=[(0.45, 0.45, 0.45, 0.6)], linewidths=0.8, label="control mesh"))
    equal_axes(ax, np.vstack([points, control]))
    ax.view_init(*VIEW)
    drawn = "" if step == 1 else f"\n({len(polygons)} of the {len(faces)} faces drawn: one in {step}, at most {MAX_REFINED_FACES})"
    ax.set_title(title + drawn, fontsize=10)
    return fig
