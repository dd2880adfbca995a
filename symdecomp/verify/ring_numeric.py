"""Numeric check of a K-ring spectrum for any scheme, against the full matrix in double precision.

The full ``K``-ring matrix (built by exact refinement, no block structure) is rounded to
doubles and its eigenvalues computed by LAPACK (``numpy.linalg.eigvals``); they are matched,
with multiplicities, to the distinct values of :func:`~symdecomp.analysis.spectrum.ring_spectrum`
(each value takes its ``m`` nearest unused eigenvalues) and compared through their mean (a
Jordan block splits into a cluster of radius about ``eps^(1/m)``, but its mean is accurate).
Double precision limits the agreement to about 12 digits; ``--certify`` proves it exactly.

>>> from symdecomp.schemes.loop import loop
>>> r = ring_numeric_check(loop(), 7, 2, digits=10)
>>> r.status.value, [m.eigenvalue.multiplicity for m in r.matches]
('agree', [1, 2, 2, 1, 2, 7, 7])
"""

from __future__ import annotations

from dataclasses import replace

import mpmath
import numpy as np

from symdecomp.analysis.eigenvalue import ClosedFormLabel
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import MAX_DOUBLE_DIGITS, check_int, check_valence
from symdecomp.verify.numeric import EigenvalueMatch, NumericCheck
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["MAX_DOUBLE_DIGITS", "ring_numeric_check"]



def _full_matrix(scheme: Scheme, n: int, rings: int) -> np.ndarray:
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
    numeric = list(np.linalg.eigvals(_full_matrix(scheme, n, rings)))
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
        matches.append(EigenvalueMatch(replace(e, value=value, labels=labels), len(mine), mpmath.mpf(deviation), mpmath.mpf(spread)))
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
