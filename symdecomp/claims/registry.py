"""The registry of the paper's claims and the results of checking them.

A claim is one numbered equation, proposition or remark of the paper. Each is registered
with the paper's label, its section, its statement, and a *check*: a function returning a
:class:`CheckResult` that says what was shown and how, together with the derivation steps
(sympy objects, so that LaTeX comes from sympy's printer).

Statuses:

``proved``     shown symbolically, for every valence ``n`` (and every frequency).
``verified``   shown for each ``n`` in a stated range, exactly or in certified interval arithmetic.
``numeric``    agrees to a stated number of digits.
``refuted``    false; the result carries a counterexample.
``corrected``  false as printed; a corrected statement is proved, and the correction is shown.
``undecided``  the check ran but could not decide (a sufficient test failed, intervals overlapped).
``not applicable``  the statement cannot be evaluated for the given scheme (it is about Catmull-Clark
               by name, or needs rules the scheme does not have); the evidence says why.
``error``      the check itself failed to run (never a finding about the paper).

Every claim is checked *for a scheme* (:func:`check_claim`, default Catmull-Clark): the printed
statement of the paper is one input, the scheme the other, and the status follows from both.
Statements that do not involve the scheme (Section 2, the CB-matrix algebra of Section 6) have the
same status for every scheme.

Registering a claim (later issues add modules ``symdecomp/claims/s*.py``; they are found
automatically)::

    @claim("Eq. 34", section="5.1", title="Eigenvalues of M_j", statement="...")
    def eq34(scheme: Scheme) -> CheckResult:
        ...
        return CheckResult(Status.PROVED, "char. polynomial vanishes identically", steps=(...))
"""

from __future__ import annotations

import enum
import importlib
import pkgutil
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache

import sympy as sp
from sympy.printing.str import StrPrinter

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.scheme import Scheme, catmull_clark

__all__ = [
    "Text",
    "Status",
    "Step",
    "CheckResult",
    "Claim",
    "claim",
    "all_claims",
    "get_claim",
    "check_claim",
    "REGISTRY",
]


class Status(str, enum.Enum):
    """What a check established (see the module docstring)."""

    PROVED = "proved"
    VERIFIED = "verified"
    NUMERIC = "numeric"
    REFUTED = "refuted"
    CORRECTED = "corrected"
    UNDECIDED = "undecided"
    NOT_APPLICABLE = "not applicable"
    ERROR = "error"

    def __str__(self) -> str:
        return self.value


class _TextPrinter(StrPrinter):
    """sympy's ``str`` printer, with relations and intervals written as in prose (``x = 1``, ``[0, 1)``)."""

    def _print_Relational(self, expr):
        op = "=" if expr.rel_op == "==" else expr.rel_op
        return "%s %s %s" % (self._print(expr.lhs), op, self._print(expr.rhs))

    def _print_MatrixBase(self, expr):
        return "[%s]" % ", ".join("[%s]" % ", ".join(self._print(e) for e in row) for row in expr.tolist())

    def _print_Derivative(self, expr):
        variables = "".join(" d%s" % self._print(v) for v in expr.variables)
        return "d%s/%s" % (self._print(expr.expr), variables.strip())

    def _print_Product(self, expr, name="prod"):
        limits = ", ".join("%s=%s..%s" % tuple(self._print(x) for x in lim) for lim in expr.limits)
        return "%s_{%s} %s" % (name, limits, self.parenthesize(expr.function, 50))

    def _print_Sum(self, expr):
        return self._print_Product(expr, "sum")

    def _print_Abs(self, expr):
        return "|%s|" % self._print(expr.args[0])

    def _print_Interval(self, expr):
        left = "(" if expr.left_open else "["
        right = ")" if expr.right_open else "]"
        return "%s%s, %s%s" % (left, self._print(expr.start), self._print(expr.end), right)


@dataclass(frozen=True, init=False)
class Text:
    """Prose with mathematics in it: words (``str``) and computed objects (sympy), in order.

    The findings of a check (evidence, counterexample, corrected statement) are ``Text``, so
    that LaTeX typesets the objects as formulas (:func:`symdecomp.output.latex.aslatex`) and a
    terminal prints them readably (``str``), from the same source. A plain ``str`` part is
    prose and is never parsed as mathematics.

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> str(Text("the root ", sp.sqrt(x) / 2, " is simple"))
    'the root sqrt(x)/2 is simple'
    >>> str(Text("where ", sp.Eq(x, 1, evaluate=False), " in ", sp.Interval.Ropen(0, 1)))
    'where x = 1 in [0, 1)'
    """

    #: The words and objects, in reading order.
    parts: tuple

    def __init__(self, *parts):
        flat = []
        for part in parts:
            flat.extend(part.parts if isinstance(part, Text) else (part,))
        object.__setattr__(self, "parts", tuple(flat))

    def __str__(self) -> str:
        return "".join(part if isinstance(part, str) else _TextPrinter().doprint(part) for part in self.parts)

    def __bool__(self) -> bool:
        return bool(self.parts)

    def __add__(self, other) -> Text:
        return Text(self, other)

    def __radd__(self, other) -> Text:
        return Text(other, self)


@dataclass(frozen=True)
class Step:
    """One displayed step of a derivation: a sentence and, optionally, a sympy object."""

    #: What the step says, in words (may contain inline LaTeX between ``$``).
    text: str
    #: The object computed at this step (an expression, an equation, a matrix), or ``None``.
    expr: object = None
    #: Optional left-hand side, displayed as ``lhs = expr``.
    lhs: object = None


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one claim."""

    #: What was established.
    status: Status
    #: One line saying how (the range of ``n`` checked, the identity that vanished, ...).
    evidence: str | Text
    #: The derivation, as displayed steps.
    steps: tuple[Step, ...] = ()
    #: For ``refuted``/``corrected``: a concrete counterexample, in words.
    counterexample: str | Text | None = None
    #: For ``corrected``: the corrected statement.
    correction: str | Text | None = None
    #: For ``numeric``: the number of significant digits of agreement.
    digits: int | None = None
    #: For ``verified``: the valences checked, as ``(first, last)`` inclusive.
    valences: tuple[int, int] | None = None

    def __post_init__(self):
        if self.status is Status.REFUTED and not self.counterexample:
            raise ValueError("a refuted claim needs a counterexample")
        if self.status is Status.CORRECTED and not self.correction:
            raise ValueError("a corrected claim needs the corrected statement")
        if self.status is Status.NUMERIC and self.digits is None:
            raise ValueError("a numeric claim needs the digits it was checked to")
        if self.status is Status.VERIFIED and self.valences is None:
            raise ValueError("a verified claim needs the range of valences it was checked for")


@dataclass(frozen=True)
class Claim:
    """A claim of the paper, with the function that checks it."""

    #: The paper's label, e.g. ``"Eq. 34"`` or ``"Proposition 5.1"``.
    label: str
    #: The paper's section, e.g. ``"5.1"``.
    section: str
    #: A short title.
    title: str
    #: The statement as the paper makes it (LaTeX allowed between ``$``).
    statement: str
    #: Returns the :class:`CheckResult` for a scheme; pure, may be slow (results are cached per scheme).
    check: Callable[[Scheme], CheckResult] = field(repr=False, compare=False)
    #: Registration order, to list claims in the paper's order within a section.
    order: int = 0

    def sort_key(self):
        """Paper order: by section, then in the order the section's module registers its claims."""
        section = tuple(int(p) for p in self.section.split("."))
        return (section, self.order)


REGISTRY: dict[str, Claim] = {}


def claim(label: str, *, section: str, title: str, statement: str):
    """Decorator registering ``check`` as the check of the claim ``label``."""

    def register(check: Callable[[Scheme], CheckResult]) -> Callable[[Scheme], CheckResult]:
        if label in REGISTRY:
            raise ValueError(f"claim {label!r} is registered twice")
        REGISTRY[label] = Claim(label, section, title, statement, check, order=len(REGISTRY))
        return check

    return register


def _load_sections() -> None:
    from symdecomp import claims as package

    for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda m: m.name):
        if info.name.startswith("s") and info.name[1:2].isdigit():
            importlib.import_module(f"{package.__name__}.{info.name}")


def all_claims() -> list[Claim]:
    """Every registered claim, in the paper's order."""
    _load_sections()
    return sorted(REGISTRY.values(), key=Claim.sort_key)


def get_claim(label: str) -> Claim:
    """The claim with the given label (``"Eq. 34"``, ``"Proposition 5.1"``...)."""
    _load_sections()
    try:
        return REGISTRY[label]
    except KeyError:
        raise KeyError(f"no claim labelled {label!r}; known: {', '.join(c.label for c in all_claims())}") from None


def check_claim(label: str, scheme: Scheme | None = None) -> CheckResult:
    """Check a claim for ``scheme`` (default: standard Catmull-Clark), once per scheme.

    An exception inside the check becomes status ``error`` with its message.
    """
    return _check_claim(label, catmull_clark() if scheme is None else scheme)


@cache
def _check_claim(label: str, scheme: Scheme) -> CheckResult:
    c = get_claim(label)
    try:
        result = c.check(scheme)
    except InvalidSchemeError as exc:  # the scheme is outside what the claim's derivation covers
        return CheckResult(Status.NOT_APPLICABLE, f"not applicable to the scheme {scheme.name!r}: {exc}")
    except Exception as exc:  # the registry reports, the caller decides
        tb = traceback.format_exception_only(type(exc), exc)[-1].strip()
        return CheckResult(Status.ERROR, f"check raised {tb}")
    if not isinstance(result, CheckResult):
        return CheckResult(Status.ERROR, f"check returned {type(result).__name__}, not CheckResult")
    return result


def is_zero(expr) -> bool:
    """True when ``expr`` simplifies to exactly zero (a matrix: every entry)."""
    if isinstance(expr, sp.MatrixBase):
        return all(is_zero(e) for e in expr)
    return sp.simplify(sp.expand(expr)) == 0
