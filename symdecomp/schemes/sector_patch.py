"""Regular patches next to a boundary or crease: the spline of the control net extended by phantom points.

A sector of ``k`` faces at a boundary, crease or corner vertex ``O`` is an *open* fan: faces (quads)
or wedges (triangles) ``s = 0..k-1`` between the sharp rays ``0`` and ``k``. Its lattice points are
labelled ``(s, u, v)`` as in the interior (:mod:`symdecomp.schemes.mesh`: ``u`` along ray ``s``,
``v`` along ray ``s + 1``, canonical ``u >= 1``), and the points of the last ray are ``(k, u, 0)``.
A regular patch whose control net reaches across a sharp ray uses *phantom points* there, affine
combinations of real points, so that the spline of the extended net is the limit surface of the
scheme's sharp rules:

* **quads** (bicubic B-splines): reflect through the boundary point, ``p' = 2 p_b - p_i``: the point
  one step beyond the boundary is ``2 p(u, 0) - p(u, 1)``. Across the boundary the cubic B-spline's
  rules ``(1/8, 3/4, 1/8)`` and ``(1/2, 1/2)`` then give ``p_b`` at the boundary (the phantom cancels
  the interior point), so the tensor rules reduce to the crease rules ``3/4, 1/8`` and ``1/2`` along
  the boundary, and the refined phantom row is again the reflection of the refined real rows (the
  B-spline's masks are symmetric). This is the phantom point of production evaluators of
  Catmull-Clark boundary patches (``S_edge = 2 V_boundary - V_opposite``; a convex corner needs the
  diagonal one as well, a concave corner none that works: Nießner et al., *GPU Pro 7*, Ch. 2.2).
* **triangles** (quartic box splines): the point reflection does *not* reproduce the crease rules
  (its vertex rule is ``7/8, 1/16``). The *mirror* does: the geometric mirror image of ``(x - 1, 1)``
  in the boundary line is the lattice point ``(x, -1)``, the midpoint of the two lies on the boundary
  edge from ``(x - 1, 0)`` to ``(x, 0)``, and the phantom ``p(x, -1) = p(x - 1, 0) + p(x, 0) - p(x - 1, 1)``
  turns Loop's regular vertex rule ``5/8, 1/16 x 6`` into ``3/4, 1/8`` and its edge rule ``3/8, 3/8,
  1/8, 1/8`` into ``1/2, 1/2`` on the boundary. Beyond ray ``k`` the same with ``u`` and ``v``
  exchanged (the wedge's bisector is a lattice mirror).

Both statements are *derived*, not assumed: :func:`phantom_reproduction` refines a strip of the
lattice with the phantom row by the lattice's regular rules (exact sympy) and returns the residuals
against the sharp rules and against the phantom rule one level finer; the tests require them to be
0. So a sector's regular patches are the splines of :func:`sector_net` when the scheme's sharp rules
are the B-spline's (:func:`check_spline_sharp_rules` says in one line when they are not).

>>> from symdecomp.schemes.lattice import QUAD
>>> sector_point(QUAD, 2, 0, 2, -1)   # below ray 0: the reflection 2 p(0, 2, 0) - p(0, 2, 1)
((2, (0, 2, 0)), (-1, (0, 2, 1)))
>>> sector_point(QUAD, 2, 1, 0, 3), sector_point(QUAD, 2, 1, 2, -1)   # on ray 2; inside sector 0
(((1, (2, 3, 0)),), ((1, (0, 1, 2)),))
"""

from __future__ import annotations

import sympy as sp

from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice, lattice

__all__ = ["ORIGIN", "sector_point", "sector_net", "phantom_reproduction", "check_spline_sharp_rules", "modified_edges"]

#: The label of the sharp vertex ``O`` itself.
ORIGIN = (0, 0, 0)


def _quad_point(k: int, s: int, u: int, v: int):
    if u == 0 and v == 0:
        return ((1, ORIGIN),)
    if v < 0 and u < 0:
        raise InvalidInputError(f"sector point ({s}, {u}, {v}) lies beyond two rays")
    if v < 0:
        if s > 0:
            return _quad_point(k, s - 1, -v, u) if v == -1 else _bad(s, u, v)
        if v != -1:
            return _bad(s, u, v)
        return _scaled(2, _quad_point(k, 0, u, 0)) + _scaled(-1, _quad_point(k, 0, u, 1))  # reflection across ray 0
    if u < 0:
        if s < k - 1:
            return _quad_point(k, s + 1, v, -u) if u == -1 else _bad(s, u, v)
        if u != -1:
            return _bad(s, u, v)
        return _scaled(2, _quad_point(k, s, 0, v)) + _scaled(-1, _quad_point(k, s, 1, v))  # across ray k
    if u == 0:
        return ((1, (s + 1, v, 0)),)
    return ((1, (s, u, v)),)


def _triangle_point(k: int, s: int, u: int, v: int):
    if u == 0 and v == 0:
        return ((1, ORIGIN),)
    if v < 0:
        if s > 0:
            return _triangle_point(k, s - 1, -v, u + v)
        if v != -1:
            return _bad(s, u, v)
        # the mirror image of (u - 1, 1) in ray 0: p(u - 1, 0) + p(u, 0) - p(u - 1, 1)
        return _triangle_point(k, 0, u - 1, 0) + _triangle_point(k, 0, u, 0) + _scaled(-1, _triangle_point(k, 0, u - 1, 1))
    if u < 0:
        if s < k - 1:
            return _triangle_point(k, s + 1, u + v, -u)
        if u != -1:
            return _bad(s, u, v)
        return _triangle_point(k, s, 0, v - 1) + _triangle_point(k, s, 0, v) + _scaled(-1, _triangle_point(k, s, 1, v - 1))
    if u == 0:
        return ((1, (s + 1, v, 0)),)
    return ((1, (s, u, v)),)


def _bad(s, u, v):
    raise InvalidInputError(f"sector point ({s}, {u}, {v}) lies more than one step beyond a sharp ray")


def _scaled(c: int, terms):
    return tuple((c * w, lab) for w, lab in terms)


def _merge(terms) -> tuple:
    out: dict = {}
    for w, lab in terms:
        out[lab] = out.get(lab, 0) + w
    return tuple((w, lab) for lab, w in out.items() if w != 0)


#: The points of a face of an open sector, phantoms included, for each kind of regular patch.
_SECTOR_POINT = {BICUBIC: _quad_point, BOX_SPLINE: _triangle_point}


def sector_point(mesh: Lattice | str, k: int, s: int, u: int, v: int) -> tuple:
    """The lattice point ``(u, v)`` of face ``s`` of an open sector of ``k`` faces: ``((weight, label), ...)``.

    A real point is ``((1, label),)`` with its canonical label (``u >= 1``, or ``(k, u, 0)`` on the last
    ray, :data:`ORIGIN` for ``O``); a point one step beyond ray 0 or ray ``k`` is the phantom point of the
    module docstring, an integer combination of real points.
    """
    lat = lattice(mesh)
    if not (isinstance(k, int) and k >= 1 and isinstance(s, int) and 0 <= s < k):
        raise InvalidInputError(f"sector point: need 0 <= s < k, got s = {s!r}, k = {k!r}")
    point = lat.select(_SECTOR_POINT, "sector points beyond a sharp ray")
    return _merge(point(k, s, u, v))


def sector_net(mesh: Lattice | str, k: int, s: int, points, value):
    """The values at ``points`` (lattice points of face ``s``) with phantoms resolved: ``value(label)`` of real points.

    ``value`` returns anything that supports ``+`` and multiplication by an ``int`` (sympy, Arb balls, ...).
    """
    out = []
    for u, v in points:
        terms = sector_point(mesh, k, s, u, v)
        total = value(terms[0][1]) * terms[0][0]
        for w, lab in terms[1:]:
            total = total + value(lab) * w
        out.append(total)
    return out


def check_spline_sharp_rules(rules, owner: str = "scheme") -> None:
    """Raise :class:`~symdecomp.errors.NotApplicableError` unless the crease rules are the cubic B-spline's.

    The phantom construction reproduces exactly ``3/4, 1/8`` and ``1/2`` (:func:`phantom_reproduction`),
    so a sector's regular patches are splines only for those; other crease rules have no known patch.
    """
    have = (rules.crease_centre, rules.crease_end, rules.crease_edge)
    if tuple(sp.sympify(w, strict=True) for w in have) != (sp.Rational(3, 4), sp.Rational(1, 8), sp.Rational(1, 2)):
        raise NotApplicableError(
            f"{owner}: the crease rules {tuple(str(w) for w in have)} (vertex centre, vertex end, edge) are not the cubic "
            "B-spline's (3/4, 1/8, 1/2), so the regular patches at the boundary are not splines with phantom points")



def modified_edges(scheme, vertex, k: int) -> str | None:
    """Why a sector's regular patches next to ``O`` are not splines of their control points, or ``None``.

    A near-edge rule (Biermann-Levin-Zorin's) that differs from the smooth edge rule in a sector of ``k`` faces
    makes every level's points next to ``O`` by other weights than the spline's, so a patch whose refinement reads
    them (the ring of sub-patches at ``O``) is not the spline of its control points. At the regular boundary
    (``theta = pi/2`` on quads) the rules agree and the patches are splines.
    """
    theta = (vertex.angle if vertex.angle is not None else sp.pi) / k
    near = scheme.sharp.near_edge(theta, k)
    if near is None or k < 2:  # one face: no smooth edge at O
        return None
    smooth = (scheme.edge_rule.center, dict(scheme.edge_rule.a).get(0, sp.Integer(0)))
    if all(sp.simplify(a - b) == 0 for a, b in zip(near, smooth)):
        return None
    return (f"the near-edge rule ({near[0]}, {near[1]}) differs from the smooth edge rule ({smooth[0]}, {smooth[1]}) at "
            f"k = {k}: it makes the points next to O at every level, so the ring's patches there are not splines of their "
            "control points (the ring past them, at level-1 distance 2 to 4, is used instead)")

def _strip(lat: Lattice):
    """A strip of the lattice, ``|x| <= 4``, rows ``y = -1..3``, symbolic values at ``y >= 0`` and phantoms at ``y = -1``."""
    xs, ys = range(-4, 5), range(-1, 4)
    ids = {(x, y): i for i, (x, y) in enumerate((x, y) for y in ys for x in xs)}
    sym = {(x, y): sp.Symbol(f"p_{x}_{y}".replace("-", "m")) for x in xs for y in ys if y >= 0}

    def phantom(x):
        if any((x + dx, y) not in sym for _, (dx, y) in lat.phantom_stencil):
            return sp.Symbol(f"q_{x}")  # outside the strip: an independent value, never read near the middle
        return sum((w * sym[(x + dx, y)] for w, (dx, y) in lat.phantom_stencil), sp.Integer(0))

    values = {i: (sym[p] if p[1] >= 0 else phantom(p[0]),) for p, i in ids.items()}
    faces: list[tuple[int, ...]] = []
    for (x, y), i in ids.items():
        if (x + 1, y + 1) not in ids:
            continue
        a, b, c, d = i, ids[(x + 1, y)], ids[(x + 1, y + 1)], ids[(x, y + 1)]
        faces += lat.cell_faces(a, b, c, d)
    return lat.mesh(tuple(faces), values), ids, sym, phantom


def phantom_reproduction(mesh: Lattice | str, rules) -> dict[str, sp.Expr]:
    """Residuals (0 when the construction holds) of the phantom rule against the sharp ``rules``, exactly.

    A strip of the lattice with the phantom row is refined once by the lattice's regular rules
    (:meth:`~symdecomp.schemes.lattice.Lattice.reference`); returned, each ``expanded new - expected``:

    * ``vertex``: the new boundary vertex against ``crease_centre p_0 + crease_end (p_-1 + p_1)``;
    * ``edge``: the new boundary edge point against ``crease_edge (p_0 + p_1)``;
    * ``phantom``: the new phantom points against the phantom rule applied to the new real points
      (so the construction holds on every level, and the spline of the extended net is the limit).
    """
    lat = lattice(mesh)
    strip, ids, sym, _ = _strip(lat)
    step = lat.refine(strip, lat.mesh_rules(lat.reference()))
    face_of = {frozenset(f): i for i, f in enumerate(strip.faces)}
    by_id = {i: p for p, i in ids.items()}
    inv = {p: i for i, p in by_id.items()}

    def new(x, y):
        pid = lat.refined_point(step, lambda a, b: inv[(a, b)], x, y, face_of)
        return step.mesh.values[pid][0]

    p = lambda x, y: sym[(x, y)]  # noqa: E731
    out = {
        "vertex": sp.expand(new(0, 0) - rules.crease_centre * p(0, 0) - rules.crease_end * (p(-1, 0) + p(1, 0))),
        "edge": sp.expand(new(1, 0) - rules.crease_edge * (p(0, 0) + p(1, 0))),
    }
    expected = [(x, sum((w * new(x + dx, y) for w, (dx, y) in lat.phantom_stencil), sp.Integer(0))) for x in (-1, 0, 1, 2)]
    out["phantom"] = sum((sp.Abs(sp.expand(new(x, -1) - e)) for x, e in expected), sp.Integer(0))
    return out

