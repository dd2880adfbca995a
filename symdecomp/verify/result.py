"""The verdict vocabularies of the checks: what a cross-check of one valence returns, and Reif's C1 test's verdicts.

The numeric check (:mod:`.numeric`) and the certified one (:mod:`.certify`) share the
wrapper :class:`CrossCheckResult`, so that the command line reads both the same way. The C1
test (:mod:`.c1`, and its spectral part in :mod:`.c1_spectrum`) reports a :class:`C1Verdict`.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import ClassVar

__all__ = ["C1Verdict", "CrossCheckStatus", "CrossCheckResult"]


class C1Verdict(str, enum.Enum):
    """The verdict of Reif's C1 test at one valence (:func:`symdecomp.verify.c1.c1_test`), printed and in JSON as its value.

    The spectral part alone (:func:`symdecomp.verify.c1_spectrum.spectral_conditions`) uses the same
    words: ``C1`` there means that the spectral conditions hold, so the characteristic map decides.
    """

    #: Every condition is certified.
    C1 = "c1"
    #: A condition is shown to fail (the reason names it, with its numbers).
    NOT_C1 = "not-c1"
    #: Neither (the reason says what would decide).
    UNDECIDED = "undecided"

    def __str__(self) -> str:
        return self.value


class CrossCheckStatus(str, enum.Enum):
    """The outcome of a cross-check at one valence (not to be confused with a claim's status)."""

    #: The closed forms agree with the full matrix (to ``dps`` digits, or exactly if certified).
    AGREE = "agree"
    #: They do not: the message names the valence and the eigenvalue.
    DISAGREE = "disagree"
    #: The numeric spectrum did not stop moving within the precision limit: no verdict (a failure).
    NOT_CONVERGED = "not converged"
    #: Certified mode could neither prove nor refute (a failure).
    UNDECIDED = "undecided"


@dataclass(frozen=True)
class CrossCheckResult:
    """The fields every cross-check result has; subclasses add their own details."""

    #: The valence.
    n: int
    #: The scheme's name.
    scheme: str
    #: The verdict.
    status: CrossCheckStatus
    #: A one-line verdict; on failure it names the valence and the eigenvalue.
    message: str

    #: ``"numeric"`` or ``"certified"``, in the JSON output.
    mode: ClassVar[str] = ""

    @property
    def ok(self) -> bool:
        """Only agreement passes: disagreement, no convergence and undecided all fail."""
        return self.status is CrossCheckStatus.AGREE

    def details(self) -> dict:
        """The check's own fields for :meth:`as_json` (between the status and the message)."""
        return {}

    def as_json(self) -> dict:
        return {
            "n": self.n,
            "scheme": self.scheme,
            "mode": self.mode,
            "status": self.status.value,
            **self.details(),
            "message": self.message,
        }
