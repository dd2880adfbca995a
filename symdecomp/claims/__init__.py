"""The paper's claims, one module per section (``s2_*.py``, ``s4_*.py``, ...)."""

from symdecomp.claims.registry import (
    REGISTRY,
    CheckResult,
    Claim,
    Scope,
    ScopeSummary,
    Status,
    Step,
    Text,
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
    "Scope",
    "ScopeSummary",
    "Status",
    "Step",
    "Text",
    "all_claims",
    "check_claim",
    "claim",
    "erratum_scope",
    "get_claim",
    "is_zero",
    "scope_summary",
]
