"""When a claim's closed forms cannot be evaluated for a scheme: the ``not applicable`` results.

Section 5 writes its closed forms in ``c = cos(j pi/n)``, which needs mirror-symmetric rules (the
weight on ``a_{i+k}`` equal to that on ``a_{i-k}`` and so on, so that ``M_j`` depends on ``c``
alone). For a scheme without that symmetry those claims are reported as not applicable, with the
term that breaks it, instead of failing inside sympy.
"""

from __future__ import annotations

from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.claims.registry import CheckResult, Status, Text
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import sin_jtheta as SIN

__all__ = ["needs_mirror_symmetry"]


def needs_mirror_symmetry(scheme: Scheme) -> CheckResult | None:
    """``not applicable`` when the trace or determinant of ``M_j`` depends on ``sin(j pi/n)``, else ``None``."""
    ev = tangent_eigenvalues(scheme)
    for name, expr in (("trace", ev.trace), ("determinant", ev.determinant)):
        if expr.has(SIN):
            return CheckResult(
                Status.NOT_APPLICABLE,
                Text("the closed forms of Section 5 are written in c = cos(j pi/n) and need mirror-symmetric rules; for this "
                     "scheme the ", name, " of M_j is ", expr, " (s = sin(j pi/n))"),
            )
    return None
