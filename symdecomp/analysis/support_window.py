"""Section 3 for every valence: the support relation near a vertex of valence ``n``, from one window of sectors.

The ring mesh of valence ``n`` (:func:`symdecomp.schemes.mesh.ring_mesh`) is ``n`` copies of one sector
glued cyclically around the centre; the rotation ``s -> s + 1`` is an automorphism. Every vertex but the
centre has valence 4 and its faces lie in two consecutive sectors. Write ``N(F)`` for the corners of the
faces sharing a vertex with ``F`` (the set the support test of :mod:`symdecomp.analysis.support` reads) and
``N_loc(F)`` for the same with the faces at the centre left out. Then

    ``N(F) = N_loc(F)``, plus the star of the centre (the centre and all ``a_k``, ``b_k``) when ``F`` has the centre as a corner.

``N_loc(F)`` is local: for ``F`` at a vertex ``Q`` of sector 0 it only holds vertices of sectors
``-NEAR..NEAR``. It is computed once on the *window*, the sectors ``-WINDOW..WINDOW`` of the mesh
unrolled around the centre (no wrap-around; labels ``(s, u, v)`` as in ``ring_mesh``). For ``n >= 2 NEAR + 1``
the labels of sectors ``-NEAR..NEAR`` are distinct modulo ``n``, so a vertex ``P`` is in ``N_loc(F)`` on the
valence-``n`` mesh iff its one label in that range is in the window's ``N_loc(F)``: the support test of every
pair ``(P, Q)`` is the window's, up to relabelling, for every such ``n``. Pairs farther apart (sector offset
``> NEAR``) only meet through the star of the centre (:func:`far_region`), and the centre's own ``n`` sectors
carry a vertex off the star only for the few sectors near it (:func:`centre_region`). Valences below
``FIRST_VALENCE`` are computed directly by the callers.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import partial

from symdecomp.analysis.support import Region
from symdecomp.schemes.mesh import QuadMesh
from symdecomp.validate import cached, check_int

__all__ = [
    "WINDOW", "NEAR", "FIRST_VALENCE", "Window", "window", "region", "far_region", "centre_region", "ring_of",
    "centre_hoods_local", "hypotheses_for_every_valence", "CENTRE", "predicted_region",
]

#: Sectors ``-WINDOW..WINDOW`` are unrolled; ``N_loc`` of the faces at a vertex of sector 0 is complete there.
WINDOW = 3
#: ``N_loc(F)`` for ``F`` at a vertex of sector 0 holds labels of sectors ``-NEAR..NEAR`` only (checked).
NEAR = 2
#: From this valence on, labels of sectors ``-NEAR..NEAR`` are distinct modulo ``n``.
FIRST_VALENCE = 2 * NEAR + 1
CENTRE = (0, 0, 0)


def ring_of(label) -> int:
    """The ring of a vertex: ``max(u, v)`` (0 for the centre)."""
    return max(label[1], label[2])


def _star(label) -> bool:
    return ring_of(label) <= 1


@dataclass(frozen=True)
class Window:
    """The unrolled sectors, with the sets ``N_loc`` the argument needs."""

    mesh: QuadMesh
    #: vertex id -> label ``(s, u, v)`` (``u >= 1`` except the centre).
    labels: dict
    #: The labels of sector 0 within ``rings - 2`` rings: the vertex types (one per rotation orbit, the centre aside).
    types: tuple
    #: type -> per face at that vertex: (labels of ``N_loc(F)``, whether the centre is a corner of ``F``).
    hoods: dict
    #: for the centre's faces ``k = -NEAR..NEAR``: labels of ``N_loc``.
    centre_hoods: dict

    def local_labels_within(self, bound: int) -> bool:
        """Whether every ``N_loc`` computed holds labels of sectors ``-bound..bound`` only (for the types)."""
        return all(abs(lab[0]) <= bound for hood in self.hoods.values() for labels, _ in hood for lab in labels)


@cached(rings=partial(check_int, argument="rings", minimum=1, maximum=20))
def window(rings: int = 5) -> Window:
    """The window of sectors ``-WINDOW..WINDOW`` with ``rings`` rings (no wrap-around)."""
    ident = {CENTRE: 0}

    def vid(s, u, v):
        if u == 0 and v == 0:
            return 0
        label = (s + 1, v, 0) if u == 0 else (s, u, v)
        return ident.setdefault(label, len(ident))

    faces = [
        (vid(s, u, v), vid(s, u + 1, v), vid(s, u + 1, v + 1), vid(s, u, v + 1))
        for s in range(-WINDOW, WINDOW + 1) for u in range(rings) for v in range(rings)
    ]
    labels = {i: lab for lab, i in ident.items()}
    mesh = QuadMesh(tuple(faces), {i: (Fraction(0),) for i in labels})

    def n_loc(fi):
        out = set()
        for c in mesh.faces[fi]:
            if c != 0:
                for g in mesh.faces_of(c):
                    out.update(labels[x] for x in mesh.faces[g])
        return frozenset(out)

    types = tuple(lab for lab in sorted(ident) if lab[0] == 0 and lab[1] >= 1 and ring_of(lab) <= rings - 2)
    hoods = {t: tuple((n_loc(fi), 0 in mesh.faces[fi]) for fi in mesh.faces_of(ident[t])) for t in types}
    centre_faces = {k: next(fi for fi in mesh.faces_of(0) if mesh.faces[fi][1] == ident[(k, 1, 0)]) for k in range(-NEAR, NEAR + 1)}
    return Window(mesh, labels, types, hoods, {k: n_loc(fi) for k, fi in centre_faces.items()})


def region(w: Window, p, q) -> Region:
    """Region of ``Q`` (a type, in sector 0) relative to the support of ``P`` (the centre, or a label of sector
    ``-NEAR..NEAR``), on the valence-``n`` mesh for every ``n >= FIRST_VALENCE``."""
    if p == CENTRE:
        carried = tuple(CENTRE in labels or has_centre for labels, has_centre in w.hoods[q])
    else:
        carried = tuple(p in labels or (has_centre and _star(p)) for labels, has_centre in w.hoods[q])
    return _region(carried)


def far_region(w: Window, p_type, q) -> Region:
    """Region of ``Q`` relative to the support of a ``P`` of type ``p_type`` more than ``NEAR`` sectors away."""
    return _region(tuple(has_centre and _star(p_type) for _, has_centre in w.hoods[q]))


def centre_region(w: Window, p_type) -> tuple[Region, int]:
    """Region of the centre relative to the support of ``P`` (type ``p_type``), for every ``n >= FIRST_VALENCE``,
    and the number of the centre's sectors near ``P`` that carry it (the others carry it only if ``P`` is in the star)."""
    if _star(p_type):
        return Region.INSIDE, len(w.centre_hoods)
    near = sum(1 for labels in w.centre_hoods.values() if p_type in labels)
    # the centre has n >= FIRST_VALENCE > near sectors, and the far ones do not carry P
    return (Region.BOUNDARY if near else Region.OUTSIDE), near


def predicted_region(w: Window, p_label, q_label, valence: int) -> Region:
    """The window's region of ``Q`` relative to the support of ``P`` on the valence-``n`` ring mesh, ``n >= FIRST_VALENCE``
    (``P``, ``Q`` labels ``(s, u, v)`` of :func:`symdecomp.schemes.mesh.ring_mesh_labels`, within ``rings - 2`` rings)."""
    if q_label == CENTRE:
        return Region.INSIDE if p_label == CENTRE else centre_region(w, (0, *p_label[1:]))[0]
    q_type = (0, *q_label[1:])
    if p_label == CENTRE:
        return region(w, CENTRE, q_type)
    t = (p_label[0] - q_label[0]) % valence
    t = t - valence if t > valence // 2 else t
    return region(w, (t, *p_label[1:]), q_type) if abs(t) <= NEAR else far_region(w, (0, *p_label[1:]), q_type)


def _region(carried) -> Region:
    return Region.INSIDE if all(carried) else Region.OUTSIDE if not any(carried) else Region.BOUNDARY


def centre_hoods_local(w: Window) -> bool:
    """Whether ``N_loc`` of the centre's face ``k`` is the rotation by ``k`` of that of face 0, with sectors ``-1..2``
    (so a vertex of sector 0 is in it only for ``k = -2..1``, all computed)."""
    base = w.centre_hoods[0]
    shifted = all(w.centre_hoods[k] == frozenset(lab if lab == CENTRE else (lab[0] + k, *lab[1:]) for lab in base) for k in w.centre_hoods)
    return shifted and all(-1 <= s <= 2 for s, _, _ in base)


def hypotheses_for_every_valence(scheme) -> tuple[list[str], list]:
    """The hypotheses of the propagation argument (:func:`symdecomp.analysis.support.check_positive_scheme`) for every
    valence ``n >= 3`` at once, exactly: the failures (empty: they hold) and ``(what, expression)`` pairs shown.

    Face and edge weights ``>= 0``; the vertex weights and the limit mask (the left eigenvector of the Eq. 43 matrix
    for 1, :func:`symdecomp.analysis.masks.limit_masks`) positive as rational functions of ``n`` on ``[3, oo)``; the
    eigenvalue 1 simple: ``det(xI - T)/(x - 1)`` nonzero at ``x = 1`` for every integer ``n >= 3`` and
    ``det(I - M(omega))``, a polynomial in ``c = cos(k pi/n)``, without a root in ``[-1, 1]``."""
    import sympy as sp

    from symdecomp.algebra.valence_signs import integer_zeros, positive_from
    from symdecomp.analysis.frequency import laurent_to_cos, per_frequency_matrix, recursion_matrix
    from symdecomp.analysis.masks import limit_masks
    from symdecomp.errors import InvalidInputError, InvalidSchemeError
    from symdecomp.schemes.refinement import mesh_rules
    from symdecomp.symbols import cos_jtheta
    from symdecomp.symbols import n as N

    failures, shown = [], []
    rules = mesh_rules(scheme)
    for label, w in (("face", rules.face_corner), ("edge end", rules.edge_end), ("edge side", rules.edge_side)):
        if not (w.is_number and w >= 0):
            failures.append(f"the {label} weight {w} is not a nonnegative number")
    v = scheme.vertex_rule
    try:
        mask = limit_masks(scheme).position
    except InvalidSchemeError as exc:
        return failures + [str(exc)], shown
    x = sp.Symbol("x")
    rest = sp.cancel(sp.expand((x * sp.eye(3) - sp.Matrix(recursion_matrix(scheme))).det()) / (x - 1)).subs(x, 1)
    q_one = laurent_to_cos(sp.expand((sp.eye(2) - sp.Matrix(per_frequency_matrix(scheme))).det()))
    try:
        for name, w in (("vertex rule, centre", v.center), ("vertex rule, each a", v.each_a), ("vertex rule, each b", v.each_b),
                        ("limit mask, centre", mask[0]), ("limit mask, each a", mask[1]), ("limit mask, each b", mask[2])):
            shown.append((f"{name}, positive", w))
            if not positive_from(w, N, 3):
                failures.append(f"the {name} weight {w} is not positive for every n >= 3")
        shown.append(("$\\det(I-E_0)$ (so the eigenvalue 1 of the Eq. 43 matrix is simple)", rest))
        if integer_zeros(rest, N, 3) != ():
            failures.append(f"det(I - E_0) = {rest} vanishes at some n >= 3")
        shown.append(("$\\det(I-M(\\omega))$ in $c=\\cos(k\\pi/n)$, no root in $[-1,1]$", q_one))
        free = q_one.free_symbols - {cos_jtheta}
        if free or sp.Poly(q_one, cos_jtheta).count_roots(-1, 1) > 0:
            failures.append(f"det(I - M(omega)) = {q_one} may vanish for some frequency")
    except InvalidInputError as exc:
        failures.append(str(exc))
    return failures, shown
