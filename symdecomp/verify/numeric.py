"""Independent numeric spectra of the full subdivision matrix, matched with the closed forms.

The ``(2n+1) x (2n+1)`` matrix is built from the scheme's rules (no block structure) and its
eigenvalues are computed by mpmath's QR algorithm (``mpmath.eig``) at a working precision of
more than the requested ``dps`` digits. They are matched with the closed-form eigenvalues
(:mod:`symdecomp.analysis.closed_forms`) *with multiplicities*:

* every numeric eigenvalue goes to the nearest distinct closed-form value; each distinct
  value must receive exactly as many as its multiplicity (``n = 4`` has ``1/4`` three
  times: from ``k = 0`` and twice from ``k = n/2 = 2``, where ``M_k = I/4``);
* a value is compared through the *mean* of the eigenvalues it received. A defective
  eigenvalue (a Jordan block, e.g. of the Eq. 43 block for the weights of
  :mod:`symdecomp.analysis.defective`) splits under rounding into a cluster of radius about the
  square root of the working precision, but the mean of the cluster is accurate to the
  working precision. The cluster radius is reported as ``spread``;
* the computation is repeated at a higher precision until the matched means stop moving
  (agree to ``dps + 2`` digits). If they never do within ``max_dps``, the result is
  ``not converged``, which is a failure: an unconverged comparison never passes.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = numeric_check(catmull_clark(), 4, dps=20)
>>> r.status.value, [(m.eigenvalue.text, m.eigenvalue.multiplicity) for m in r.matches][:3]
('agree', [('1.0', 1), ('0.5', 2), ('0.25', 3)])

The same question at the other neighbourhoods, each against its own matrix built without block structure:

* an interior vertex with its ``K``-ring, any scheme (:func:`ring_numeric_check`): the full ``K``-ring matrix
  (exact refinement) rounded to doubles, its eigenvalues by LAPACK (``numpy.linalg.eigvals``), matched with
  multiplicities to the distinct values of :func:`~symdecomp.analysis.spectrum.ring_spectrum` (each value
  takes its ``m`` nearest unused eigenvalues) and compared through their mean; double precision limits the
  agreement to about 12 digits (``--certify`` proves it exactly);
* a boundary, crease or corner vertex (a sector, :func:`numeric_sharp`; ``check --k A:B --boundary`` without
  ``--certify``): the eigenvalues from the mirror decomposition's blocks
  (:mod:`symdecomp.analysis.block_values`, each with its exact multiplicity and a certified ball) against the
  eigenvalues of the vertex's matrix by exact refinement
  (:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, its entries at ``dps`` digits, its eigenvalues by
  Arb's approximate QR iteration, ``acb_mat.eig(algorithm="approx")``). Each of the matrix's eigenvalues is
  assigned to the nearest block value; they ``agree`` when every distance is below ``10^-(dps/2)`` (a multiple
  eigenvalue is only that accurate in floating point) and each block value gets exactly its multiplicity, else
  ``disagree``, naming the value.

>>> from symdecomp.schemes.loop import loop
>>> r = ring_numeric_check(loop(), 7, 2, digits=10)
>>> r.status.value, [m.eigenvalue.multiplicity for m in r.matches]
('agree', [1, 2, 2, 1, 2, 7, 7])
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from typing import ClassVar

import flint
import mpmath
import numpy as np

from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.analysis.eigenvalue import ClosedFormLabel, Eigenvalue
from symdecomp.analysis.spectrum import format_value, ring_spectrum
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.full_matrix import parameter_values, sparse_subdivision_matrix
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import MAX_DOUBLE_DIGITS, MAX_DPS, check_int, check_memory, check_precision, check_valence
from symdecomp.verify.result import CrossCheckResult, CrossCheckStatus

__all__ = ["EigenvalueMatch", "NumericCheck", "numeric_check", "full_matrix_eigenvalues", "group_values",
           "ring_numeric_check", "SharpNumericRow", "numeric_sharp", "numeric_row"]


@dataclass(frozen=True)
class EigenvalueMatch:
    """One distinct closed-form eigenvalue and the numeric eigenvalues of the full matrix matched with it.

    A match between two spectra, not an eigenvalue: the eigenvalue is :attr:`EigenvalueMatch.eigenvalue` (the one type,
    :class:`~symdecomp.analysis.eigenvalue.Eigenvalue`); the other fields say how the full matrix's
    eigenvalues fell around it (how many, their mean's deviation, their spread), facts of the comparison
    that a spectrum does not have.
    """

    #: The closed-form eigenvalue (value at the working precision, text to ``dps`` digits, multiplicity, closed forms).
    eigenvalue: Eigenvalue
    #: How many eigenvalues of the full matrix were nearest to it.
    matched: int
    #: ``|mean of the matched eigenvalues - value|`` (distance to the nearest eigenvalue if none matched).
    deviation: object
    #: ``max |matched eigenvalue - value|``: about ``eps^(1/m)`` for an ``m x m`` Jordan block.
    spread: object


@dataclass(frozen=True)
class NumericCheck(CrossCheckResult):
    """The numeric cross-check of one valence (status: agree, disagree or not converged)."""

    #: Digits to which the closed forms must agree.
    dps: int
    #: Working precisions (decimal digits) of the eigenvalue computations, in order.
    precisions: tuple[int, ...]
    #: The largest deviation of a matched mean from its closed form (at the last precision).
    max_deviation: object
    #: The largest spread of a cluster (large for defective eigenvalues).
    max_spread: object
    #: One entry per distinct closed-form value.
    matches: tuple[EigenvalueMatch, ...]
    #: The eigen-solver: ``"mpmath"`` (``mpmath.eig``), ``"flint"`` (Arb, certified enclosures,
    #: :mod:`symdecomp.verify.arb_numeric`) or ``"numpy"`` (double precision, the K-ring route).
    solver: str = "mpmath"

    mode: ClassVar[str] = "numeric"

    def details(self) -> dict:
        return {
            "solver": self.solver,
            "dps": self.dps,
            "precisions": list(self.precisions),
            "max_deviation": mpmath.nstr(self.max_deviation, 3),
            "max_spread": mpmath.nstr(self.max_spread, 3),
            "distinct": len(self.matches),
        }


def _check_solve_memory(size: int, dps: int) -> None:
    """Refuse an eigenvalue solve whose estimated memory is too large (mpmath.eig keeps a few
    dense complex copies of the matrix, each entry an mpc of ``dps`` digits plus object overhead)."""
    check_memory(6 * size * size * (2 * (dps * 3.33 / 8 + 100)), f"the {size} x {size} eigenvalue solve at {dps} digits")


def full_matrix_eigenvalues(scheme: Scheme, n: int, dps: int, parameters: Mapping | None = None, *, eigensolver=None) -> list:
    """The ``2n+1`` eigenvalues of the full matrix by ``mpmath.eig`` at ``dps`` digits.

    The matrix is built from the exact rational entries given by the rules; ``eigensolver``
    (a function of an ``mpmath.matrix`` returning its eigenvalues) replaces ``mpmath.eig``.
    """
    n = check_valence(n)
    size = 2 * n + 1
    _check_solve_memory(size, dps)
    entries = sparse_subdivision_matrix(scheme, n, parameters)
    with mpmath.workdps(dps):
        A = mpmath.matrix(size, size)
        for (r, c), x in entries.items():
            A[r, c] = mpmath.mpf(int(x.p)) / int(x.q)
        if eigensolver is not None:
            return [+v for v in eigensolver(A)]
        # mpmath's shifted QR occasionally stalls on these highly structured matrices
        # ("failed to converge"); the transpose has the same eigenvalues and usually does not
        try:
            values = mpmath.eig(A, left=False, right=False)
        except RuntimeError:
            values = mpmath.eig(A.T, left=False, right=False)
        return [+v for v in values]


def _frequencies(labels) -> tuple[int, ...]:
    """The n-gon frequencies of closed-form labels, ascending and distinct."""
    return tuple(sorted({lab.frequency for lab in labels}))


def group_values(values, labels, tol) -> list[tuple[object, list]]:
    """Group equal closed-form values (within ``tol``): ``[(value, [labels])]``, largest first."""
    order = sorted(range(len(values)), key=lambda i: (-abs(values[i]), -mpmath.re(values[i]), -mpmath.im(values[i])))
    groups: list[tuple[object, list]] = []
    for i in order:
        v = values[i]
        for g in groups:
            if abs(g[0] - v) <= tol * max(1, abs(v)):
                g[1].append(labels[i])
                break
        else:
            groups.append((v, [labels[i]]))
    return groups


def _match(groups, eigs, dps):
    assigned = [[] for _ in groups]
    for mu in eigs:
        best = min(range(len(groups)), key=lambda g: abs(groups[g][0] - mu))
        assigned[best].append(mu)
    matches = []
    for (value, labels), got in zip(groups, assigned):
        if got:
            mean = mpmath.fsum(got) / len(got)
            deviation = abs(mean - value)
            spread = max(abs(mu - value) for mu in got)
        else:
            deviation = min(abs(mu - value) for mu in eigs)
            spread = deviation
        matches.append(
            EigenvalueMatch(
                Eigenvalue(value, format_value(value, dps), len(labels), frequencies=_frequencies(labels), labels=tuple(labels)),
                matched=len(got),
                deviation=deviation,
                spread=spread,
            )
        )
    return matches, [mpmath.fsum(got) / len(got) if got else None for got in assigned]


def numeric_check(
    scheme: Scheme,
    n: int,
    *,
    dps: int = 50,
    parameters: Mapping | None = None,
    closed_forms: ClosedForms | None = None,
    max_dps: int | None = None,
    eigensolver: Callable | None = None,
    solver: str = "mpmath",
) -> NumericCheck:
    """Match the numeric spectrum of the full valence-``n`` matrix with the closed forms.

    ``dps``: the closed forms must agree to this many digits. ``closed_forms``: the closed
    forms under test (default: the derived ones; tests pass a wrong one). ``max_dps``: the highest
    working precision tried (default ``4 * dps + 40``). ``eigensolver``: replaces ``mpmath.eig``
    (:func:`full_matrix_eigenvalues`). ``solver``: ``"mpmath"``, ``"flint"`` (:mod:`.arb_numeric`) or ``"auto"`` (flint, and mpmath if flint
    leaves the valence undecided; the result's ``solver`` says which decided).
    """
    check_scheme(scheme)
    n, dps = check_valence(n), check_precision(dps)
    solver = _check_solver(solver, eigensolver)
    if solver != "mpmath":
        return _arb_route(scheme, n, solver, dps=dps, parameters=parameters, closed_forms=closed_forms, max_dps=max_dps)
    if max_dps is not None:
        max_dps = check_precision(max_dps, "max_dps", maximum=4 * MAX_DPS + 40)
    _check_solve_memory(2 * n + 1, max_dps or 4 * dps + 40)
    subs = parameter_values(scheme, parameters)
    cf = closed_forms or derived_closed_forms(scheme)
    max_dps = max_dps or 4 * dps + 40
    if max_dps < dps + 10:
        raise InvalidInputError(f"max_dps = {max_dps} leaves no room above dps = {dps} (need at least dps + 10)")
    labels = cf.eigenvalue_labels(n)
    # the closed forms are evaluated well beyond any working precision, so that their own
    # rounding never matters; values that agree to dps + 2 digits are one value for a
    # comparison to dps digits (a split finer than that could not be resolved anyway)
    reference = max_dps + 30
    with mpmath.workdps(reference):
        values = cf.values(n, subs)
        groups = group_values(values, labels, mpmath.mpf(10) ** (-(dps + 2)))
    precisions: list[int] = []
    previous = None
    matches: list[EigenvalueMatch] = []
    work = dps + 10
    while work <= max_dps:
        precisions.append(work)
        try:
            eigs = full_matrix_eigenvalues(scheme, n, work, subs, eigensolver=eigensolver)
        except RuntimeError:  # QR did not converge at this precision: try the next one
            previous = None
            work = _next_precision(work)
            continue
        with mpmath.workdps(reference):
            matches, means = _match(groups, [mpmath.mpmathify(e) for e in eigs], dps)
            converged = previous is not None and _same(previous, means, dps)
        if converged:
            return _verdict(scheme, n, dps, tuple(precisions), matches)
        previous = means
        work = _next_precision(work)
    return _not_converged(scheme, n, dps, tuple(precisions), matches, max_dps, reference)


def _arb_route(scheme, n, solver, **options) -> NumericCheck:
    """The flint route; with ``solver="auto"``, mpmath where flint leaves the valence undecided."""
    from symdecomp.verify.arb_numeric import arb_numeric_check

    first = arb_numeric_check(scheme, n, **options)
    if solver == "flint" or first.status is not CrossCheckStatus.UNDECIDED:
        return first
    # a cluster the enclosures cannot separate (a Jordan block): mpmath matches it by its mean
    return replace(numeric_check(scheme, n, **options), solver="mpmath (flint undecided)")


def _check_solver(solver, eigensolver) -> str:
    if solver not in ("mpmath", "flint", "auto"):
        raise InvalidInputError(f"solver: expected 'mpmath', 'flint' or 'auto', got {solver!r}")
    if solver != "mpmath" and eigensolver is not None:
        raise InvalidInputError("eigensolver: replaces mpmath.eig, so it needs solver='mpmath'")
    return solver


def _not_converged(scheme, n, dps, precisions, matches, max_dps, reference) -> NumericCheck:
    """The result when the matched means never stopped moving (or QR never converged): no verdict."""
    if not matches:
        message = f"n = {n}: mpmath's QR iteration failed at every working precision up to {max_dps} digits; no verdict"
        deviation = spread = mpmath.inf
    else:
        with mpmath.workdps(reference):
            worst = max(matches, key=lambda m: m.deviation)
        deviation, spread = worst.deviation, max(m.spread for m in matches)
        message = (
            f"n = {n}: the numeric spectrum did not converge to {dps} digits by {precisions[-1] if precisions else dps} "
            f"digits of working precision (worst eigenvalue {worst.eigenvalue.describe()}); no verdict"
        )
    return NumericCheck(
        n=n,
        scheme=scheme.name,
        dps=dps,
        precisions=precisions,
        status=CrossCheckStatus.NOT_CONVERGED,
        max_deviation=deviation,
        max_spread=spread,
        matches=tuple(matches),
        message=message,
    )


def _next_precision(work: int) -> int:
    """The next working precision: a quarter more (at least 10 digits), enough to see movement."""
    return work + max(10, work // 4)


def _same(previous, means, dps) -> bool:
    tol = mpmath.mpf(10) ** (-(dps + 2))
    for a, b in zip(previous, means):
        if (a is None) != (b is None):
            return False
        if a is not None and abs(a - b) > tol * max(1, abs(b)):
            return False
    return True


def _verdict(scheme, n, dps, precisions, matches) -> NumericCheck:
    tol = mpmath.mpf(10) ** (-dps)
    bad_count = [m for m in matches if m.matched != m.eigenvalue.multiplicity]
    bad_value = [m for m in matches if m.matched and m.deviation > tol * max(1, abs(m.eigenvalue.value))]
    max_dev = max(m.deviation for m in matches)
    max_spread = max(m.spread for m in matches)
    if bad_count:
        m = bad_count[0]
        message = (
            f"n = {n}: closed-form eigenvalue {m.eigenvalue.describe()} has {m.matched} eigenvalue(s) of the full matrix nearest "
            f"to it, not {m.eigenvalue.multiplicity} (nearest at distance {mpmath.nstr(m.deviation, 3)})"
        )
        status = CrossCheckStatus.DISAGREE
    elif bad_value:
        m = max(bad_value, key=lambda m: m.deviation)
        message = (
            f"n = {n}: closed-form eigenvalue {m.eigenvalue.describe()} differs from the full matrix's eigenvalue(s) by "
            f"{mpmath.nstr(m.deviation, 3)} (tolerance 1e-{dps})"
        )
        status = CrossCheckStatus.DISAGREE
    else:
        message = (
            f"n = {n}: {sum(m.eigenvalue.multiplicity for m in matches)} eigenvalues ({len(matches)} distinct) agree to {dps} digits; "
            f"largest deviation {mpmath.nstr(max_dev, 3)}"
        )
        status = CrossCheckStatus.AGREE
    return NumericCheck(
        n=n,
        scheme=scheme.name,
        dps=dps,
        precisions=precisions,
        status=status,
        max_deviation=max_dev,
        max_spread=max_spread,
        matches=tuple(matches),
        message=message,
    )


def _ring_matrix_doubles(scheme: Scheme, n: int, rings: int) -> np.ndarray:
    S = ring_subdivision_matrix(scheme, n, rings)
    exact = S.exact_matrix() if S.weights else None
    A = np.zeros((S.size, S.size))
    for r, row in enumerate(S.rows):
        for c, x in row.items():
            A[r, c] = float(exact[r, c]) if exact is not None and r == 0 else x.numerator / x.denominator
    return A


def ring_numeric_check(scheme: Scheme, n: int, rings: int = 1, *, digits: int = 10) -> NumericCheck:
    """Compare the frequency-factor spectrum with the full matrix's eigenvalues to ``digits`` digits."""
    n = check_valence(n)
    digits = check_int(digits, "digits", minimum=1, maximum=MAX_DOUBLE_DIGITS,
                       reason="the K-ring numeric check runs in double precision (or certify)")
    spectrum = ring_spectrum(scheme, n, rings, digits=digits + 5, exact=False, jordan=False)
    numeric = list(np.linalg.eigvals(_ring_matrix_doubles(scheme, n, rings)))
    tol = 10.0 ** (-digits)
    matches, failures = [], []
    for e in sorted(spectrum.eigenvalues, key=lambda e: -e.multiplicity):
        value = complex(float(e.value.real.mid()), float(e.value.imag.mid()))
        numeric.sort(key=lambda z: abs(z - value))
        mine, numeric = numeric[: e.multiplicity], numeric[e.multiplicity :]
        mean = sum(mine) / len(mine) if mine else complex("nan")
        deviation = abs(mean - value)
        spread = max((abs(z - value) for z in mine), default=float("nan"))
        labels = tuple(ClosedFormLabel(k, "frequency factor") for k in e.frequencies)
        matches.append(EigenvalueMatch(replace(e, value=value, labels=labels, hull=None), len(mine), mpmath.mpf(deviation), mpmath.mpf(spread)))
        if not deviation <= tol * max(1.0, abs(value)):
            failures.append(f"{e.text} (k = {', '.join(map(str, e.frequencies))}; multiplicity {e.multiplicity}): "
                            f"the full matrix's eigenvalues average {mean:.12g}, off by {deviation:.3g}")
    matches.sort(key=lambda m: -abs(m.eigenvalue.value))
    status = CrossCheckStatus.DISAGREE if failures else CrossCheckStatus.AGREE
    message = f"n = {n}: " + ("; ".join(failures) if failures else f"all {len(matches)} distinct values agree to {digits} digits (double precision)")
    return NumericCheck(
        n=n, scheme=scheme.name, dps=digits, precisions=(15,), status=status,
        max_deviation=max(m.deviation for m in matches), max_spread=max(m.spread for m in matches),
        matches=tuple(matches), message=message, solver="numpy",
    )


@dataclass(frozen=True)
class SharpNumericRow:
    """One vertex's numeric check."""

    #: Faces of the vertex's first sector (``K``).
    k: int
    #: The vertex, as printed (``boundary k=5``, ...).
    vertex: str
    status: CrossCheckStatus
    #: Eigenvalues (with multiplicity) and distinct values of the blocks.
    size: int
    distinct: int
    #: Digits the comparison was made at.
    dps: int
    #: What disagreed or could not be told apart (empty when they agree).
    message: str = ""
    #: What was compared with the blocks: the matrix's ``eigenvalues`` (solved densely) or, past that, its action on the
    #: sine ``polylines`` (:mod:`symdecomp.verify.sector_numeric`).
    compared: str = "eigenvalues"
    #: The largest deviation found, as text (``-`` where the comparison is a match of values to ``dps // 2`` digits).
    deviation: str = "-"

    @property
    def ok(self) -> bool:
        return self.status is CrossCheckStatus.AGREE

    def as_json(self) -> dict:
        return {"k": self.k, "vertex": self.vertex, "status": self.status.value, "size": self.size,
                "distinct": self.distinct, "dps": self.dps, "message": self.message, "compared": self.compared,
                "deviation": self.deviation}


def _matrix_values(scheme, vertex, prec: int) -> list:
    from symdecomp.schemes.sector import sharp_subdivision_matrix
    from symdecomp.verify.mirror_parts import ball_matrix

    S = sharp_subdivision_matrix(scheme, vertex)
    with flint.ctx.workprec(prec):
        return list(ball_matrix(S.tolist()).eig(algorithm="approx"))


def numeric_sharp(scheme, vertex, *, dps: int = 50) -> SharpNumericRow:
    """Compare the blocks' spectrum of ``vertex`` with its refined matrix's eigenvalues at ``dps`` digits (module docstring)."""
    from symdecomp.analysis.block_values import structural_values
    from symdecomp.verify.certify import describe_vertex

    scheme, dps = check_scheme(scheme), check_precision(dps)
    prec = math.ceil(dps * 3.33) + 32
    values, size = structural_values(scheme, vertex, prec=prec)
    name = describe_vertex(vertex)
    common = dict(k=vertex.sectors[0], vertex=name, size=size, distinct=len(values), dps=dps)
    with flint.ctx.workprec(prec):
        mids = [flint.acb(v.ball.real.mid(), v.ball.imag.mid()) for v in values]
        counts = [0] * len(values)
        tol = flint.arb(10) ** (-(dps // 2))
        for z in _matrix_values(scheme, vertex, prec):
            i = min(range(len(values)), key=lambda t: float(abs(z - mids[t]).mid()))
            if not abs(z - mids[i]) < tol:
                return SharpNumericRow(status=CrossCheckStatus.DISAGREE, message=f"{name}: the matrix's eigenvalue "
                                       f"{z.mid().str(12, radius=False)} is no block's value to {dps // 2} digits", **common)
            counts[i] += 1
    for v, count in zip(values, counts):
        if count != v.multiplicity:
            return SharpNumericRow(status=CrossCheckStatus.DISAGREE, message=f"{name}: the blocks' value {v.ball.mid().str(12, radius=False)} "
                                   f"has multiplicity {v.multiplicity}, the matrix {count} eigenvalues there", **common)
    return SharpNumericRow(status=CrossCheckStatus.AGREE, **common)


def numeric_row(vertex, *, scheme, dps: int) -> SharpNumericRow:
    """:func:`numeric_sharp` with the vertex first, for the shared pool (one vertex per item; a vertex that travelled to a
    worker is given the scheme's own lattice object again, which the matrix's assembly compares by identity)."""
    return numeric_sharp(scheme, dataclasses.replace(vertex, lattice=scheme.lattice.name), dps=dps)
