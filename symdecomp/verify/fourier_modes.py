"""The subdominant eigenvectors of a sharp sector in closed form, one derivation for every number of faces ``k``.

With Biermann-Levin-Zorin's near-edge rule the sine block ``j = 1`` of a boundary (or crease) sector has the eigenvalue
``1/2`` for every ``k``, the crease block's tangent eigenvalue (:mod:`symdecomp.analysis.mirror`). The two eigenvectors
of ``lambda_1 = lambda_2 = 1/2`` are then the real and imaginary parts of one complex vector ``v = x + i y`` (``x`` odd
under the sector's mirror, the crease block's; ``y`` even, the sine block's) that is a *Fourier mode* away from the sharp
rays: ``v(s, u, w) = F(u, w) omega^s`` with ``omega = e^(i pi/k)``, the frequency-1 mode of the interior at valence
``2 k``. Only the points next to ray 0 (faces ``0..depth``) carry values of their own, because there the crease rules
replace the regular ones; next to ray ``k`` the values are the mirror images, ``v(P p) = -conj(v(p))``.

**The derivation** (:func:`sector_modes`, once per scheme) is exact in ``Q(i)(tau)``, ``tau = tan(pi/(2 k))``, where
``omega = (1 + i tau)/(1 - i tau)`` and ``cos(pi/k) = (1 - tau^2)/(1 + tau^2)`` (so BLZ's weights are rational in
``tau``). It reads the exact rows of a sector of :data:`WINDOW` faces (the near-edge weight as a symbol,
:func:`~symdecomp.verify.mirror_parts.sector_matrices`): the unknowns are the values in faces ``0..depth`` and
the Fourier amplitudes ``F``, the equations ``S v = v/2`` on the rows of faces ``0..depth + 2`` (the last ones read
Fourier values only: the Fourier identity, the same in every face away from the rays), normalised by ``F(1, 0) = 1``.
The system is solved exactly (sympy's ``DomainMatrix`` over ``QQ_I(tau)``); a unique solution is required, and
``depth`` grows from 0 until there is one. The level-1 3-ring values ``R v`` (what the characteristic map's nets read)
follow from the refinement rows the same way.

**Why it holds for every k >= WINDOW.** A row reads its point's neighbours only, so the rows of faces
``0..depth + 2`` are the same at every ``k >= WINDOW`` (checked: identical at ``WINDOW`` and ``WINDOW + 1`` faces,
entry by entry), and a row of a face away from both rays is the row one face over, shifted (checked at the window).
The mirror commutes with the matrix (checked exactly by :func:`~symdecomp.verify.mirror_parts.sector_parts`) and
with the refinement to the 3-ring (checked entry by entry), and
the Fourier amplitudes satisfy the mirror's relation ``F(w, u) = omega conj(F(u, w))`` (``F(u, 0)`` real; checked
exactly), so the vector defined by the three pieces satisfies every row of the ``k``-sector: ``x = Re v`` and
``y = Im v`` are eigenvectors for ``1/2``, odd and even, hence (each ``1/2`` simple in its mirror part, which the blocks
prove) *the* subdominant eigenvectors.

>>> from symdecomp.schemes.files import load_scheme
>>> modes = sector_modes(load_scheme("catmull-clark-blz"))
>>> modes.depth, FIELD.to_sympy(modes.coarse[(1, 1)])   # b_s = (1 + omega) omega^s = 2/(1 - i tau) omega^s
(0, 2*I/(tau + I))
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import check_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.symbols import sector_faces, theta_k
from symdecomp.verify.mirror_parts import NEAR, mirror_label, sector_matrices, sector_parts

__all__ = ["TAU", "FIELD", "OMEGA", "WINDOW", "SectorModes", "sector_modes"]

#: ``tau = tan(pi/(2 k))``: the field's generator.
TAU = sp.Symbol("tau", real=True)
#: ``Q(i)(tau)``, where every value of the modes lies.
FIELD = sp.QQ_I.frac_field(TAU)
#: ``omega = e^(i pi/k) = (1 + i tau)/(1 - i tau)``.
OMEGA = FIELD.from_sympy((1 + sp.I * TAU) / (1 - sp.I * TAU))
#: Faces of the sector whose rows are read (and, with one more face, compared).
WINDOW = 8
#: Most faces next to ray 0 given values of their own (the window holds them and their generic neighbours).
MAX_DEPTH = 1
_HALF = sp.Rational(1, 2)


@dataclass(frozen=True)
class SectorModes:
    """The subdominant eigenvectors ``x + i y`` of a sector with ``k >= WINDOW`` faces, as level-1 3-ring values."""

    #: Faces ``0..depth`` next to ray 0 have coarse values of their own.
    depth: int
    #: ``{fine label: value}`` for the level-1 3-ring labels of faces ``0..depth + 1`` (and ``O``), in :data:`FIELD`.
    near: dict
    #: ``{(u, w): G(u, w)}``: a fine label ``(s, u, w)`` of a face ``s >= depth + 2`` has the value ``G(u, w) omega^s``.
    fourier: dict
    #: The coarse amplitudes ``F(u, w)`` (level 0, 2-ring), for the record.
    coarse: dict


def _face(label) -> int:
    return -1 if label == ORIGIN else label[0]


def _near_weight(scheme) -> sp.Expr | None:
    """BLZ's near-edge weight on the edge's other end as a rational function of ``tau`` (``None``: no such rule)."""
    rules = scheme.sharp
    if rules is None or rules.near_edge_centre is None:
        return None
    theta = sp.Symbol("theta", positive=True)
    end = rules.near_edge_end.xreplace({theta_k: theta})
    if end.has(sector_faces):
        raise NotApplicableError("the near-edge weight depends on k itself, not on cos(pi/k) alone: no closed form in tau")
    c, s = (1 - TAU**2) / (1 + TAU**2), 2 * TAU / (1 + TAU**2)
    out = sp.cancel(sp.expand_trig(end).subs({sp.cos(theta): c, sp.sin(theta): s}))
    if out.free_symbols - {TAU} or out.has(sp.cos, sp.sin):
        raise NotApplicableError(f"the near-edge weight {rules.near_edge_end} is not rational in cos(theta_k), sin(theta_k)")
    return out


def _rows(matrix, labels) -> dict:
    """``{row label: {column label: entry}}`` of a sparse sympy matrix."""
    out: dict = {}
    for (i, j), e in matrix.todok().items():
        if e != 0:
            out.setdefault(labels[0][i], {})[labels[1][j]] = e
    return out


def _shift(label, by: int):
    return label if label == ORIGIN else (label[0] + by, label[1], label[2])


def _check_window(small: dict, large: dict, depth: int, what: str) -> None:
    """The rows of faces ``<= depth + 2`` identical at the two windows; those of face ``depth + 2`` reading faces ``> depth``
    only, and the rows of face ``depth + 3`` their translates (module docstring)."""
    last = depth + 2
    for lab, row in small.items():
        if lab != ORIGIN and _face(lab) <= last and large.get(lab) != row:
            raise NotApplicableError(f"the {what} row of {lab} differs at {WINDOW} and {WINDOW + 1} faces: the rows are not local")
        if _face(lab) == last and any(c != ORIGIN and _face(c) <= depth for c in row):  # v(O) = 0: checked
            raise NotApplicableError(f"the {what} row of {lab} reads a point next to the sharp ray")
        if _face(lab) == last and small.get(_shift(lab, 1)) != {_shift(c, 1): e for c, e in row.items()}:
            raise NotApplicableError(f"the {what} rows of faces {last} and {last + 1} are not translates of each other")


def _check_mirror(rows: dict, k: int) -> None:
    """The refinement commutes with the mirror, entry by entry (the values next to ray ``k`` are the mirror images)."""
    for lab, row in rows.items():
        if rows.get(mirror_label(lab, k)) != {mirror_label(c, k): e for c, e in row.items()}:
            raise NotApplicableError(f"the refinement row of {lab} is not the mirror image of its partner's")


def _convert(weight):
    def entry(e):
        e = sp.sympify(e, strict=True)
        return FIELD.from_sympy(sp.cancel(e.subs(NEAR, weight)) if weight is not None else e)

    return entry


def _solve(rows: dict, labels, depth: int, entry) -> tuple[dict, dict] | None:
    """The coarse values (faces ``<= depth`` and ``O``) and amplitudes ``F`` solving ``S v = v/2`` (module docstring)."""
    own = [lab for lab in labels if _face(lab) <= depth]
    classes = sorted({lab[1:] for lab in labels if lab != ORIGIN})
    unknowns = own + [("F",) + c for c in classes]
    col = {u: i for i, u in enumerate(unknowns)}
    one = FIELD.one

    def terms(label):
        if _face(label) <= depth:
            return [(col[label], one)]
        return [(col[("F",) + label[1:]], OMEGA ** _face(label))]

    equations = []
    for lab in labels:
        if _face(lab) > depth + 2 or lab == ORIGIN:  # O reads ray k too: checked after the solve (_origin_row)
            continue
        eq = [FIELD.zero] * (len(unknowns) + 1)
        for c, e in rows.get(lab, {}).items():
            for i, w in terms(c):
                eq[i] += entry(e) * w
        for i, w in terms(lab):
            eq[i] -= FIELD.from_sympy(_HALF) * w
        equations.append(eq)
    norm = [FIELD.zero] * (len(unknowns) + 1)
    norm[col[("F", 1, 0)]], norm[-1] = one, one  # F(1, 0) = 1
    equations.append(norm)
    reduced, pivots = DomainMatrix(equations, (len(equations), len(unknowns) + 1), FIELD).rref()
    if len(unknowns) in pivots or len(pivots) != len(unknowns):  # inconsistent, or a free unknown left
        return None
    solution = {u: reduced[r, len(unknowns)].element for r, u in enumerate(unknowns)}
    return ({u: solution[u] for u in own}, {u[1:]: solution[u] for u in unknowns if u[0] == "F"})


def _conj(z):
    return FIELD.from_sympy(sp.conjugate(FIELD.to_sympy(z)))


def _origin_row(row: dict, own: dict, k: int, entry) -> bool:
    """Whether ``O``'s row holds, its columns next to ray ``k`` read as mirror images ``v(P p) = -conj(v(p))``."""
    total = FIELD.zero
    for c, e in row.items():
        if c in own:
            total += entry(e) * own[c]
        elif mirror_label(c, k) in own:
            total -= entry(e) * _conj(own[mirror_label(c, k)])
        else:
            return False
    return total == FIELD.from_sympy(_HALF) * own[ORIGIN]


def _mirror_consistent(amplitudes: dict) -> bool:
    """``F(w, u) = omega conj(F(u, w))`` and ``F(u, 0)`` real: the Fourier part is the mirror's (module docstring)."""
    for (u, w), z in amplitudes.items():
        if (amplitudes.get((w, u)) != OMEGA * _conj(z)) if w else z != _conj(z):
            return False
    return True


def sector_modes(scheme) -> SectorModes:
    """The closed form of the subdominant eigenvectors of a boundary or crease sector (module docstring); refused
    (:class:`~symdecomp.errors.NotApplicableError`, one line) where no such form is found."""
    return _sector_modes(check_scheme(scheme))


@functools.lru_cache(maxsize=8)
def _sector_modes(scheme) -> SectorModes:
    lattice, weight = scheme.lattice, _near_weight(scheme)
    small, large = (sector_matrices(scheme, SharpVertex.boundary(k, lattice)) for k in (WINDOW, WINDOW + 1))
    if {p.name for p in sector_parts(small)} != {"even", "odd"}:
        raise NotApplicableError("the sector's rules are not mirror symmetric: no Fourier modes")
    coarse_rows = _rows(small.matrix, (small.labels, small.labels))
    fine_rows = _rows(small.refine, (small.fine_labels, small.labels))
    _check_mirror(fine_rows, WINDOW)
    entry = _convert(weight)
    for depth in range(MAX_DEPTH + 1):
        _check_window(coarse_rows, _rows(large.matrix, (large.labels, large.labels)), depth, "2-ring")
        _check_window(fine_rows, _rows(large.refine, (large.fine_labels, large.labels)), depth, "refinement")
        found = _solve(coarse_rows, small.labels, depth, entry)
        if found is not None:
            break
    else:
        raise NotApplicableError(f"1/2 has no eigenvector of Fourier form past {MAX_DEPTH + 1} faces from the rays")
    own, amplitudes = found
    if not _mirror_consistent(amplitudes):
        raise NotApplicableError("the Fourier amplitudes are not the mirror's: x + i y is not odd plus even")
    if own[ORIGIN] != FIELD.zero or not _origin_row(coarse_rows.get(ORIGIN, {}), own, WINDOW, entry):
        raise NotApplicableError("the modes do not vanish at O, or the row of O does not hold for them")

    def coarse(label):
        if _face(label) <= depth:
            return own[label]
        if mirror_label(label, WINDOW) in own:
            return -_conj(own[mirror_label(label, WINDOW)])
        return amplitudes[label[1:]] * OMEGA ** _face(label)

    def fine(label):
        return sum((entry(e) * coarse(c) for c, e in fine_rows.get(label, {}).items()), FIELD.zero)

    near = {lab: fine(lab) for lab in small.fine_labels if _face(lab) <= depth + 1}
    ray = [lab for lab in near if lab != ORIGIN and lab[0] == 0 and lab[2] == 0]
    if any(near[lab] != lab[1] * near[(0, 1, 0)] for lab in ray):  # the map's phantoms read the rays to distance 5
        raise NotApplicableError("the modes are not linear along the sharp ray: it is not the crease curve's tangent")
    last = depth + 2
    generic = {lab[1:]: fine(lab) / OMEGA ** last for lab in small.fine_labels if _face(lab) == last}
    if not _mirror_consistent(generic):
        raise NotApplicableError("the refined Fourier amplitudes are not the mirror's")
    return SectorModes(depth, near, generic, amplitudes)
