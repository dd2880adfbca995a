"""The paper's claims, one module per section (``s2_*.py``, ``s4_*.py``, ...), and their registry.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from symdecomp.claims.registry import (
    REGISTRY,
    CheckResult,
    Claim,
    Requirement,
    Scope,
    ScopeSummary,
    Status,
    Step,
    Text,
    Verbatim,
    all_claims,
    check_claim,
    claim,
    erratum_scope,
    get_claim,
    is_zero,
    scope_summary,
)

__all__ = [
    "REGISTRY",
    "CheckResult",
    "Claim",
    "Requirement",
    "Scope",
    "ScopeSummary",
    "Status",
    "Step",
    "Text",
    "Verbatim",
    "all_claims",
    "check_claim",
    "claim",
    "erratum_scope",
    "get_claim",
    "is_zero",
    "scope_summary",
]
