"""Figures for Sections 5.2-5.3: the ellipses ``E_a``, ``E_b`` (Fig. 7), hyperbolic rings (Fig. 8), defects.

The geometry comes from :mod:`symdecomp.analysis.evolution` (rings iterated by the exact subdivision
matrix); the closed forms from the scheme's derived matrices.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np

from symdecomp.analysis.evolution import EllipticProfile, ring_polygon, split_ring
from symdecomp.errors import InvalidInputError
from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.output.plotting.polygons import _few_ticks, draw_one_ring_3d, draw_polygon_3d, set_equal_3d

__all__ = [
    "ellipses_figure",
    "nested_rings_figure",
    "hyperbolic_rates_figure",
    "mesh_surface_figure",
    "defect_figure",
    "tuned_weights_figure",
]


def _paraboloid(ax, ellipse, distance: float, reach: float, color: str = "C2") -> None:
    """The elliptic paraboloid with apex at the origin through ``ellipse`` at height ``distance``.

    Points ``s (U cos t + V sin t) + s^2 distance N`` (``N`` the ellipse's normal), ``0 <= s <= reach``.
    """
    s = np.linspace(0, reach, 20)
    t = np.linspace(0, 2 * np.pi, 48)
    S, T = np.meshgrid(s, t)
    N = ellipse.normal()
    X, Y, Z = (S * (ellipse.u[k] * np.cos(T) + ellipse.v[k] * np.sin(T)) + S**2 * distance * N[k] for k in range(3))
    ax.plot_surface(X, Y, Z, color=color, alpha=0.15, linewidth=0)


def ellipses_figure(profile: EllipticProfile, steps: Iterable[int] = range(1, 6), *, title: str = ""):
    """Fig. 7: the ellipses ``E_a``, ``E_b`` after several steps, each relative to that step's ``O``.

    Left (3-D): for each step ``k`` in ``steps``, ``E_a`` and ``E_b`` translated so that ``O_k`` is at
    the origin, with the elliptic paraboloid with apex ``O`` through the last ``E_a`` (its
    horizontal sections are scaled copies of ``E_a``, at heights growing with the square of the
    scale). With nice elliptic properties every ellipse lies on it. Right: ``kappa_a`` and ``kappa_b`` at every step; nice
    elliptic properties make both curves flat (subdominant eigenvalue of Eq. 43 = ``lambda_1^2``)
    and equal (Eq. 44 = the squared scale ratio of Eq. 39).
    """
    steps = [k for k in steps if 0 <= k < len(profile.rings)]
    if not steps:
        raise InvalidInputError(f"no step to show: the profile has steps 0..{len(profile.rings) - 1}")
    fig = new_figure(12, 5.2)
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    for index, k in enumerate(steps):
        O, _, _ = split_ring(profile.rings[k])
        for ellipse, color, name in ((profile.ellipses_a[k], "C0", "$E_a$"), (profile.ellipses_b[k], "C3", "$E_b$")):
            p = ellipse.points() - O
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color=color, lw=1.2, label=name if index == 0 else None)
    ax.scatter([0], [0], [0], color="black", s=20, label="$O_k$ (each step's O, at the origin)")
    last = steps[-1]
    reach = 1.05 * max(profile.ellipses_b[k].scale() for k in steps) / profile.ellipses_a[last].scale()
    _paraboloid(ax, profile.ellipses_a[last], float(profile.distance_a[last]), reach)
    ax.plot([], [], color="C2", alpha=0.5, lw=6, label=f"paraboloid through $E_a$ of step {last}")
    # Equal x and y scales, so that the ellipses keep their shape.
    half = 1.1 * max(float(np.abs(profile.ellipses_b[k].points()[:, :2] - split_ring(profile.rings[k])[0][:2]).max()) for k in steps)
    ax.set_xlim(-half, half)
    ax.set_ylim(-half, half)
    ax.set_box_aspect((1, 1, 0.8))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("height above $O_k$")
    ax.set_title(f"$E_a$, $E_b$ at steps {steps[0]}..{steps[-1]}, relative to $O_k$")
    ax.legend(fontsize=7, loc="upper left")
    ax.view_init(elev=14, azim=-60)
    _few_ticks(ax)

    right = fig.add_subplot(1, 2, 2)
    k = np.arange(len(profile.rings))
    right.plot(k[1:], profile.kappa_a[1:], marker="o", color="C0", label=r"$\kappa_a = d_a / \mathrm{scale}(E_a)^2$")
    right.plot(k[1:], profile.kappa_b[1:], marker="s", color="C3", label=r"$\kappa_b = d_b / \mathrm{scale}(E_b)^2$")
    right.set_xlabel("subdivision step k")
    right.set_ylabel(r"$\kappa$")
    right.set_title("Nice elliptic properties: both flat and equal")
    right.legend(fontsize=8)
    right.grid(alpha=0.3, which="both")
    fig.suptitle(title or "The ellipses $E_a$, $E_b$ over several steps (Fig. 7)")
    return fig


def nested_rings_figure(rings: Sequence, *, title: str, initial=None, initial_label: str = "the initial 1-ring"):
    """Fig. 8: the 1-rings of successive steps drawn together in 3-D, with a surface through them.

    The 1-ring of step ``k`` covers a neighbourhood of ``O`` that shrinks with ``lambda_1^k``; drawn
    together, relative to the last ``O``, their vertices trace the shape of the limit surface
    near ``O`` (a hyperbolic paraboloid when only the hyperbolic components leave the tangent
    plane). ``initial`` (a ``(2n+1, 3)`` ring) is drawn on the left with its quads.
    """
    panels = 2 if initial is not None else 1
    fig = new_figure(12 if initial is not None else 6.5, 5.4)
    if initial is not None:
        left = fig.add_subplot(1, panels, 1, projection="3d")
        O, a, b = split_ring(np.asarray(initial, dtype=float))
        draw_one_ring_3d(left, O, a, b)
        for p in np.vstack([a, b]):
            left.plot([p[0], p[0]], [p[1], p[1]], [0, p[2]], color="0.75", lw=0.6)
        set_equal_3d(left, np.asarray(initial, dtype=float))
        left.set_xlabel("x")
        left.set_ylabel("y")
        left.set_zlabel("z")
        left.set_title(initial_label)
        left.legend(fontsize=8, loc="upper left")
        left.view_init(elev=22, azim=-50)
        _few_ticks(left)
    ax = fig.add_subplot(1, panels, panels, projection="3d")
    origin = split_ring(rings[-1])[0]
    points = np.vstack([np.asarray(r, dtype=float) - origin for r in rings])
    # The vertices of all the rings, triangulated over the tangent plane (x, y): near O they
    # lie on the limit surface's graph, so the triangulation shows its shape.
    ax.plot_trisurf(points[:, 0], points[:, 1], points[:, 2], cmap="coolwarm", alpha=0.6, linewidth=0.1, edgecolor="0.5")
    for ring in rings:
        polygon = ring_polygon(np.asarray(ring, dtype=float) - origin)
        draw_polygon_3d(ax, polygon, color="0.15", lw=0.8)
    ax.set_box_aspect((1, 1, 0.6))
    ax.scatter([0], [0], [0], color="black", s=20)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(f"The 1-rings ($2n$-gons) of {len(rings)} steps, and a surface through their vertices", fontsize=10)
    ax.view_init(elev=22, azim=-50)
    _few_ticks(ax)
    fig.suptitle(title)
    return fig


def mesh_surface_figure(mesh, *, initial=None, title: str, view=(24, -55)):
    """A refined quad mesh (:class:`symdecomp.schemes.mesh.QuadMesh` with ``(x, y, z)`` values) as a surface.

    Faces are coloured by height; ``initial`` (the control mesh) is drawn as a wireframe beside it.
    """
    from matplotlib import colormaps
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    panels = 2 if initial is not None else 1
    fig = new_figure(6.0 * panels, 5.4)
    for k, (m, label) in enumerate(([(initial, "control mesh")] if initial is not None else []) + [(mesh, "refined mesh")]):
        ax = fig.add_subplot(1, panels, k + 1, projection="3d")
        quads = [np.array([m.values[v] for v in f], dtype=float) for f in m.faces]
        points = np.vstack(quads)
        if m is mesh:
            heights = np.array([q[:, 2].mean() for q in quads])
            scale = max(float(np.abs(points[:, 2]).max()), 1e-300)
            colors = colormaps["coolwarm"](0.5 + 0.5 * heights / scale)
            ax.add_collection3d(Poly3DCollection(quads, facecolors=colors, edgecolors="0.3", linewidths=0.15))
        else:
            for q in quads:
                loop = np.vstack([q, q[:1]])
                ax.plot(loop[:, 0], loop[:, 1], loop[:, 2], color="0.35", lw=0.7)
        if m is initial and 0 in m.values:  # ring meshes number the central vertex 0
            ax.scatter(*np.asarray(m.values[0], dtype=float), color="black", s=20)
        lo, hi = points.min(axis=0), points.max(axis=0)
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect((1, 1, 0.6))
        ax.view_init(*view)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        ax.set_title(f"{label}: {len(m.faces)} quads", fontsize=10)
        _few_ticks(ax)
    fig.suptitle(title)
    return fig


def hyperbolic_rates_figure(scheme, valences: Iterable[int]):
    """The eigenvalues of ``M_2`` (the hyperbolic components, Section 5.3) against ``lambda_1^2`` over ``n``.

    The hyperbolic components have to shrink like ``lambda_1^2`` for the surface near ``O`` to be
    a quadric; both come from the closed forms of Eq. 34.
    """
    import sympy as sp

    from symdecomp.analysis.tangent import tangent_eigenvalues
    from symdecomp.validate import check_valence

    ev = tangent_eigenvalues(scheme)
    ns, lam1_sq, m2 = [], [], []
    for n in valences:
        n = check_valence(n)
        ns.append(n)
        lam1_sq.append(max(abs(complex(sp.N(v, 20))) for v in ev.at(n, 1)) ** 2)
        m2.append(max(abs(complex(sp.N(v, 20))) for v in ev.at(n, 2)))
    fig = new_figure(9, 4.6)
    ax = fig.add_subplot()
    ax.plot(ns, lam1_sq, marker="s", ms=4, label=r"$\lambda_1^2$")
    ax.plot(ns, m2, marker="o", ms=4, label=r"largest eigenvalue of $M_2$ (hyperbolic components)")
    label_axes(ax, "valence n", "eigenvalue", f"{scheme.name}: hyperbolic rate against the square of the tangent-plane rate")
    return fig


def defect_figure(rows, *, title: str = "How far Catmull-Clark is from nice elliptic properties"):
    """The defect of each elliptic condition over ``n``, from rows of an elliptic defect table.

    ``rows`` have attributes ``n``, ``subdominant``, ``lambda1_squared``, ``eigenvalue_defect``,
    ``eq44_ratio``, ``scale_ratio_squared``, ``ratio_defect`` (numbers).
    """
    ns = [r.n for r in rows]
    fig = new_figure(12, 4.6)
    left, right = fig.subplots(1, 2)
    left.plot(ns, [float(r.subdominant) for r in rows], marker="o", ms=4, label=r"$\mu$, subdominant eigenvalue of Eq. 43")
    left.plot(ns, [float(r.lambda1_squared) for r in rows], marker="s", ms=4, label=r"$\lambda_1^2$ (Eq. 34)")
    left.plot(ns, [float(r.eigenvalue_defect) for r in rows], color="C3", ls="--", label=r"defect $\mu - \lambda_1^2$")
    left.axhline(0, color="0.6", lw=0.8)
    label_axes(left, "valence n", "eigenvalue", r"Condition 1: $\mu = \lambda_1^2$")
    right.plot(ns, [float(r.eq44_ratio) for r in rows], marker="o", ms=4, label=r"$d_b/d_a$ (Eq. 44)")
    right.plot(ns, [float(r.scale_ratio_squared) for r in rows], marker="s", ms=4, label=r"$|B^1/A^1|^2$ (Eq. 39 squared)")
    right.plot(ns, [float(r.ratio_defect) for r in rows], color="C3", ls="--", label="defect (difference)")
    right.axhline(0, color="0.6", lw=0.8)
    label_axes(right, "valence n", "ratio", "Condition 2: Eq. 44 = squared scale ratio")
    fig.suptitle(title)
    return fig


def tuned_weights_figure(valences: Sequence[int], series: dict, *, standard: Sequence | None = None, note: str = "",
                         title: str = "Vertex-rule weight tuned for each elliptic condition"):
    """The vertex-rule weight ``alpha`` over ``n`` for each tuning in ``series`` (label -> values).

    Shown as ``n alpha``, the total weight of the ``a_i`` in the new ``O``, which stays of order 1
    as ``n`` grows; ``None`` marks a valence without a value. ``standard`` adds the scheme's own.
    """
    fig = new_figure(9, 4.8)
    ax = fig.add_subplot()
    ns = np.array(valences, dtype=float)
    markers = "os^Dv"
    for k, (label, values) in enumerate(series.items()):
        a = np.array([np.nan if x is None else float(x) for x in values])
        ax.plot(ns, ns * a, marker=markers[k % len(markers)], ms=5, color=f"C{k}", label=label)
    if standard is not None:
        ax.plot(ns, ns * np.array([float(x) for x in standard]), color="0.3", ls=":", marker=".", label="standard Catmull-Clark")
    ax.set_xlabel("valence n")
    ax.set_ylabel(r"$n\,\alpha$ (total weight of the $a_i$ in the new O)")
    ax.set_title(title + (f"\n({note})" if note else ""), fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig
