"""The paper's claims, one module per section (``s2_*.py``, ``s4_*.py``, ...), the toolkit's own (``b1_*.py``, ...), and their registry.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from symdecomp.claims.registry import (
    BEYOND,
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
    section_key,
)

__all__ = [
    "BEYOND",
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
    "section_key",
]
