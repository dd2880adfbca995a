"""The paper's claims, one module per section (``s2_*.py``, ``s4_*.py``, ...)."""

from symdecomp.claims.registry import (
    REGISTRY,
    CheckResult,
    Claim,
    Status,
    Step,
    Text,
    all_claims,
    check_claim,
    claim,
    get_claim,
    is_zero,
)

__all__ = [
    "REGISTRY",
    "CheckResult",
    "Claim",
    "Status",
    "Step",
    "Text",
    "all_claims",
    "check_claim",
    "claim",
    "get_claim",
    "is_zero",
]
