"""The registry of the paper's claims and the results of checking them.

A claim is one numbered equation, proposition or remark of the paper. Each is registered
with the paper's label, its section, its statement, and a *check*: a function returning a
:class:`CheckResult` that says what was shown and how, together with the derivation steps
(sympy objects, so that LaTeX comes from sympy's printer).

Statuses:

==================  ======================================================================================
``proved``          shown symbolically, for every valence ``n`` (and every frequency).
``verified``        shown for each ``n`` in a stated range, exactly or in certified interval arithmetic.
``numeric``         agrees to a stated number of digits.
``refuted``         false; the result carries a counterexample.
``corrected``       false as printed; a corrected statement is proved, and the correction is shown.
``undecided``       the check ran but could not decide (a sufficient test failed, intervals overlapped).
``not applicable``  the statement cannot be evaluated for the given scheme (it is about Catmull-Clark
                    by name, or needs rules the scheme does not have); the evidence says why.
``error``           the check itself failed to run (never a finding about the paper).
==================  ======================================================================================

Each result also says the *scope* of its evidence (:class:`Scope`): ``every n`` (symbolic, for every
valence the statement is about), ``range of n`` (each valence of a finite range), or ``single case``.
A check computes it: ``proved`` is ``every n``; ``verified`` is a range or a single case by its
valences; a refutation is ``every n`` when its counterexample is exact (no floating-point number in
it) and a ``single case`` otherwise (a check may state ``every n`` when it decided the refutation
symbolically and the numbers only illustrate it); a ``corrected`` check states the scope of its corrected
statement (``single case`` when it does not), lowered to ``single case`` when the counterexample is not
exact (:func:`erratum_scope`).

Every claim is checked *for a scheme* (:func:`check_claim`, default Catmull-Clark): the printed
statement of the paper is one input, the scheme the other, and the status follows from both.
Statements that do not involve the scheme (Section 2, the CB-matrix algebra of Section 6: their checks declare
``reads_scheme=False`` and require nothing, :attr:`Claim.involves_no_scheme`) have the same status for every
scheme, of the zoo too.

Registering a claim (later issues add modules ``symdecomp/claims/s*.py``, and ``b*.py`` for the toolkit's
own claims beyond the paper, sections ``"B.<k>"`` after the paper's: :func:`section_key`; they are found
automatically)::

    @claim("Eq. 34", section="5.1", title="Eigenvalues of M_j", statement="...", requires=(MIRROR_SYMMETRIC,))
    def eq34(scheme: Scheme) -> CheckResult:
        ...
        return CheckResult(Status.PROVED, "char. polynomial vanishes identically", steps=(...))

When a check does not apply to a scheme:

* a claim declares the hypotheses its derivation needs (``requires=``, :class:`Requirement`; the shared
  ones are in :mod:`symdecomp.claims.applicability`); the registry tests them in order before running
  the check, of each scheme the check reads (:meth:`Claim.unmet`: a claim declaring ``reads_on=`` reads a
  lattice's reference scheme where the scheme given is not on it), and the first one unmet gives
  ``not applicable`` with its reason;
* inside a check, :class:`~symdecomp.errors.NotApplicableError` (raised by an analysis whose
  hypotheses the scheme does not meet) gives ``not applicable`` with its message;
* any other :class:`~symdecomp.errors.InvalidSchemeError` also gives ``not applicable``: the scheme was
  validated when it was built, so such an error inside a check means that the scheme is outside
  what this claim's derivation covers (e.g. stencils wider than the 1-ring at the valences the claim
  is about), not that the scheme is broken;
* any other exception gives ``error`` (a failure of the check, never a finding about the paper).
"""

from __future__ import annotations

import dataclasses
import enum
import importlib
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache

import sympy as sp

from symdecomp.analysis.display import NotebookDisplay
from symdecomp.claims.guards import DEFAULT_BUDGET, BudgetExceeded, at_parameter_values, time_budget, unbound_parameters, undefined_values
from symdecomp.claims.order import BEYOND, module_ranks, section_key, section_modules
from symdecomp.claims.steps import LazySteps, Step
from symdecomp.claims.text import Text, Verbatim
from symdecomp.errors import InvalidInputError, InvalidSchemeError, InvalidTypeError
from symdecomp.schemes.lattice import LATTICES, Lattice, lattice
from symdecomp.schemes.scheme import Scheme, catmull_clark, check_scheme
from symdecomp.schemes.stencils import StencilScheme

__all__ = [
    "Text", "Verbatim", "Status", "Scope", "erratum_scope", "ScopeSummary", "scope_summary", "Step", "LazySteps", "CheckResult", "Claim",
    "Requirement", "claim", "all_claims", "get_claim", "check_claim", "REGISTRY", "BEYOND", "section_key",
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


class Scope(str, enum.Enum):
    """For which valences a verdict is established (see the module docstring)."""

    #: Symbolically, for every valence the statement is about (a statement about n = 4 alone: that case, exactly).
    EVERY_N = "every n"
    #: For each valence of a finite range, exactly or in certified arithmetic.
    RANGE = "range of n"
    #: One valence or one example (or a numeric counterexample).
    SINGLE_CASE = "single case"

    def __str__(self) -> str:
        return self.value

    @property
    def strength(self) -> int:
        return {"every n": 2, "range of n": 1, "single case": 0}[self.value]


def is_exact(finding) -> bool:
    """True when a finding (a counterexample) holds only exact objects: computed sympy objects or
    integers, and no floating-point number. Words alone (a ``str``) are not an exact counterexample."""
    if not isinstance(finding, Text):
        return False
    for part in finding.parts:
        if isinstance(part, str):
            continue
        if isinstance(part, float) or (isinstance(part, sp.Basic) and part.atoms(sp.Float)):
            return False
        if isinstance(part, sp.MatrixBase) and any(e.atoms(sp.Float) for e in part):
            return False
    return True


def erratum_scope(correction: Scope, counterexample) -> Scope:
    """The scope of a ``corrected`` verdict: the corrected statement's (``correction``), lowered to
    ``single case`` when the counterexample is not exact (:func:`is_exact`)."""
    return correction if is_exact(counterexample) else Scope.SINGLE_CASE


@dataclass(frozen=True)
class CheckResult(NotebookDisplay):
    """The outcome of checking one claim."""

    #: What was established.
    status: Status
    #: One line saying how (the range of ``n`` checked, the identity that vanished, ...).
    evidence: str | Text
    #: The derivation, as displayed steps (:class:`LazySteps` when they are built only if read).
    steps: tuple[Step, ...] | LazySteps = ()
    #: For ``refuted``/``corrected``: a concrete counterexample, in words.
    counterexample: str | Text | None = None
    #: For ``corrected``: the corrected statement.
    correction: str | Text | None = None
    #: For ``numeric``: the number of significant digits of agreement.
    digits: int | None = None
    #: For ``verified``: the valences checked, as ``(first, last)`` inclusive.
    valences: tuple[int, int] | None = None
    #: For which valences the verdict is established (:class:`Scope`); computed from the status, the
    #: valences and the counterexample unless the check states it (a ``corrected`` check states its correction's).
    scope: Scope | None = None
    #: What the scope and the valences range over: ``"n"``, or ``"k"`` (faces of a sector); from :attr:`Claim.parameter`.
    parameter: str = "n"

    def __post_init__(self):
        object.__setattr__(self, "scope", self._computed_scope())
        if self.status is Status.REFUTED and not self.counterexample:
            raise ValueError("a refuted claim needs a counterexample")
        if self.status is Status.CORRECTED and not self.correction:
            raise ValueError("a corrected claim needs the corrected statement")
        if self.status is Status.NUMERIC and self.digits is None:
            raise ValueError("a numeric claim needs the digits it was checked to")
        if self.status is Status.VERIFIED and self.valences is None:
            raise ValueError("a verified claim needs the range of valences it was checked for")

    scope_text = property(lambda self: None if self.scope is None else self.scope.value.replace(" n", " " + self.parameter),
                          doc="The scope as printed: ``every n``, or ``every k`` for a claim about sectors of ``k`` faces.")

    def _computed_scope(self) -> Scope | None:
        stated, status = self.scope, self.status
        if status in (Status.UNDECIDED, Status.NOT_APPLICABLE, Status.ERROR):
            return None
        if status is Status.PROVED:
            if stated not in (None, Scope.EVERY_N):
                raise ValueError(f"a proved claim holds for every n, not for a {stated}")
            return Scope.EVERY_N
        if status in (Status.VERIFIED, Status.NUMERIC):
            lo, hi = self.valences if self.valences is not None else (0, 0)
            computed = Scope.RANGE if hi > lo else Scope.SINGLE_CASE
            if stated is not None and stated is not computed:
                raise ValueError(f"valences {self.valences} are a {computed}, not {stated}")
            return computed
        if status is Status.CORRECTED:  # unstated: nothing shown beyond the counterexample
            return erratum_scope(stated or Scope.SINGLE_CASE, self.counterexample)
        computed = Scope.EVERY_N if is_exact(self.counterexample) else Scope.SINGLE_CASE  # refuted
        return computed if stated is None else stated


@dataclass(frozen=True)
class ScopeSummary:
    """How many verdicts are established for every n, for a range, in a single case (:class:`Scope`)."""

    #: The number of results counted.
    total: int
    #: ``proved`` (every n).
    proved: int
    #: ``corrected`` or ``refuted`` with scope every n: the correction proved for every n, the counterexample exact.
    errata_every_n: int
    #: Any status with scope ``range of n``.
    range_of_n: int
    #: Any status with scope ``single case``.
    single_case: int
    #: No verdict (undecided, not applicable, error).
    no_verdict: int

    @property
    def every_n(self) -> int:
        return self.proved + self.errata_every_n

    def as_json(self) -> dict:
        return {"total": self.total, "every n": self.every_n, "proved": self.proved, "errata for every n": self.errata_every_n,
                "range of n": self.range_of_n, "single case": self.single_case, "no verdict": self.no_verdict}

    def __str__(self) -> str:
        share = f" ({100 * self.every_n / self.total:.0f} %)" if self.total else ""
        return (f"verdict for every n: {self.every_n} of {self.total}{share} ({self.proved} proved, {self.errata_every_n} errata "
                f"with the correction proved for every n and an exact counterexample); for a range of n only: "
                f"{self.range_of_n}; single case: {self.single_case}; no verdict: {self.no_verdict}")


def scope_summary(results) -> ScopeSummary:
    """Tally :class:`CheckResult` objects by the scope of their verdicts."""
    results = list(results)
    scopes = [r.scope for r in results]
    return ScopeSummary(
        total=len(results),
        proved=sum(r.status is Status.PROVED for r in results),
        errata_every_n=sum(r.status in (Status.CORRECTED, Status.REFUTED) and r.scope is Scope.EVERY_N for r in results),
        range_of_n=scopes.count(Scope.RANGE),
        single_case=scopes.count(Scope.SINGLE_CASE),
        no_verdict=scopes.count(None),
    )


@dataclass(frozen=True)
class Requirement:
    """A hypothesis a claim's derivation needs of the scheme, declared with the claim (``requires=``).

    ``unmet(scheme)`` is ``None`` when the scheme meets it, else the reason (words, or :class:`Text`),
    which becomes the evidence of the ``not applicable`` result; the check then does not run.
    """

    #: A short name, e.g. ``"mirror-symmetric rules"``.
    name: str
    #: ``None`` when the scheme meets the requirement, else the reason it does not. Part of equality: two requirements
    #: are equal when they test with the same function, never by name alone (two tests may share a name).
    unmet: Callable[[Scheme], str | Text | None] = field(repr=False)


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
    #: Registration order within its module, to list claims in the paper's order within a section.
    order: int = 0
    #: What the check needs of the scheme, tested in order before it runs (:class:`Requirement`).
    requires: tuple[Requirement, ...] = ()
    #: What the claim's scope ranges over: ``"n"`` (the valence) or ``"k"`` (the faces of a sector at a sharp vertex).
    parameter: str = "n"
    #: The module that registers it (a section's claims may come from several; see :meth:`sort_key`).
    module: str = ""
    #: ``False`` when the check never reads the scheme it is given (declared with ``reads_scheme=False``; a test runs
    #: each such check on an object that fails on any use): its verdict is that of the printed statement alone.
    reads_scheme: bool = True
    #: The lattices on which the check reads the scheme it is given (declared with ``reads_on=``): given a scheme on
    #: another lattice it reads these lattices' reference schemes instead (Catmull-Clark, Loop), so the verdict there
    #: is theirs (:meth:`reads_instead`). Empty: the scheme given, on any lattice.
    reads_on: tuple[Lattice, ...] = ()

    def reads_instead(self, scheme: Scheme | StencilScheme) -> Scheme | None:
        """The scheme the check reads in place of ``scheme`` (``scheme`` on a lattice outside :attr:`reads_on`: the
        reference scheme of the first lattice it reads, and through it of the others), or ``None`` where it reads
        ``scheme`` itself. The one test of both routes (:func:`check_claim` and
        :func:`~symdecomp.claims.zoo_claims.zoo_claim_result`): a triangle scheme of the zoo gets Catmull-Clark's
        regimes as Loop does."""
        if not self.reads_on or lattice(scheme.lattice) in self.reads_on:
            return None
        return self.reads_on[0].reference()

    def schemes_read(self, scheme: Scheme) -> tuple[Scheme, ...]:
        """The schemes the check reads when given ``scheme``: on each lattice of :attr:`reads_on`, the scheme given (after
        :meth:`reads_instead`) when it lives there, else that lattice's reference scheme (the shape claim, reading quad and
        triangle meshes, given Loop reads Catmull-Clark and Loop); with no :attr:`reads_on`, the scheme given."""
        given = self.reads_instead(scheme) or scheme
        return tuple(x.own_or_reference(given) for x in self.reads_on) if self.reads_on else (given,)

    def unmet(self, scheme: Scheme) -> str | Text | None:
        """The reason of the first requirement (in the order of :attr:`requires`) that a scheme the check reads
        (:meth:`schemes_read`) does not meet, or ``None``: a requirement is asked of what the check computes with, never
        of a scheme it does not read. The one test of both routes (:func:`check_claim`, and through it
        :func:`~symdecomp.claims.zoo_claims.zoo_claim_result`)."""
        read = self.schemes_read(scheme)
        return next((reason for requirement in self.requires for s in read if (reason := requirement.unmet(s)) is not None), None)

    @property
    def lattices(self) -> tuple[Lattice, ...]:
        """The lattices whose 1-ring the check computes with: of those it reads (:attr:`reads_on`; every lattice when it
        declares none), each whose reference scheme meets the claim's requirements (:meth:`unmet`: a claim needing face
        neighbours, quad meshes only; Loop's claims, triangle meshes); all of them if no reference does."""
        return _lattices(self.label)

    @property
    def involves_no_scheme(self) -> bool:
        """The check reads no scheme and the claim requires nothing of one: the same verdict for every scheme, a scheme
        of the zoo or a 1-ring scheme on any lattice (the one test both routes ask, :func:`check_claim` and
        :func:`~symdecomp.claims.zoo_claims.zoo_claim_result`). A check that reads no scheme but whose statement is
        about the quad 1-ring declares that (``requires=``), and it is not applicable where the 1-ring is not the paper's."""
        return not self.reads_scheme and not self.requires

    def sort_key(self):
        """Paper order: by section (:func:`section_key`), then by the module's place in the canonical load order
        (:func:`~symdecomp.claims.order.module_ranks`), then in the order the module registers its claims; independent of which module
        some caller happened to import first."""
        ranks = module_ranks()
        return (section_key(self.section), ranks.get(self.module, len(ranks)), self.order)


REGISTRY: dict[str, Claim] = {}


@cache
def _lattices(label: str) -> tuple[Lattice, ...]:
    """:attr:`Claim.lattices` of the registered claim ``label`` (computed once: it tests reference schemes)."""
    c = REGISTRY[label]
    candidates = c.reads_on or tuple(LATTICES.values())
    return tuple(x for x in candidates if c.unmet(x.reference()) is None) or candidates


def claim(label: str, *, section: str, title: str, statement: str, requires: tuple[Requirement, ...] = (),
          parameter: str = "n", reads_scheme: bool = True,
          reads_on: tuple[Lattice, ...] = ()) -> Callable[[Callable[[Scheme], CheckResult]], Callable[[Scheme], CheckResult]]:
    """Decorator registering ``check`` as the check of the claim ``label``, for schemes meeting ``requires``;
    ``reads_scheme=False`` declares that the check never reads the scheme it is given (:attr:`Claim.reads_scheme`),
    ``reads_on`` the lattices on which it reads it (:attr:`Claim.reads_on`)."""

    def register(check: Callable[[Scheme], CheckResult]) -> Callable[[Scheme], CheckResult]:
        if label in REGISTRY:
            raise ValueError(f"claim {label!r} is registered twice")
        module = check.__module__
        order = sum(1 for c in REGISTRY.values() if c.module == module)
        REGISTRY[label] = Claim(label, section, title, statement, check, order, tuple(requires), parameter, module, reads_scheme,
                                tuple(reads_on))
        return check

    return register


def _load_sections() -> None:
    from symdecomp import claims as package

    for name in section_modules():  # the paper's sections, then the toolkit's
        importlib.import_module(f"{package.__name__}.{name}")


def all_claims() -> list[Claim]:
    """Every registered claim, in the paper's order (the toolkit's own claims after the paper's)."""
    _load_sections()
    return sorted(REGISTRY.values(), key=Claim.sort_key)


def get_claim(label: str) -> Claim:
    """The claim with the given label (``"Eq. 34"``, ``"Proposition 5.1"``...); an unknown label is an
    :class:`~symdecomp.errors.InvalidInputError` listing the known ones."""
    _load_sections()
    if not isinstance(label, str):
        raise InvalidTypeError(f"label must be a string such as 'Eq. 34', got {label!r:.60} ({type(label).__name__})")
    if label not in REGISTRY:
        raise InvalidInputError(f"no claim labelled {label!r:.60}; known: {', '.join(c.label for c in all_claims())}")
    return REGISTRY[label]


def check_claim(label: str, scheme: Scheme | StencilScheme | None = None, *,
                budget: float | None = DEFAULT_BUDGET) -> CheckResult:
    """Check a claim for ``scheme`` (default: standard Catmull-Clark), once per scheme.

    A requirement the scheme does not meet, or a :class:`~symdecomp.errors.NotApplicableError` (or
    other :class:`~symdecomp.errors.InvalidSchemeError`) inside the check, becomes ``not applicable``
    with the reason; any other exception inside the check becomes status ``error`` with its message
    (see the module docstring). A check that is still running after ``budget`` seconds (``None``: no
    limit) becomes ``undecided``, saying so. On a scheme with free parameters, a check that stops on
    them (a numeric comparison meeting a symbol) is ``not applicable`` with the reason, and a
    counterexample that is an expression in them is made concrete (:func:`unbound_parameters`).
    A scheme of the zoo is answered by :func:`symdecomp.claims.zoo_claims.zoo_claim_result`.
    """
    if budget is not None and not (isinstance(budget, (int, float)) and not isinstance(budget, bool) and 0 < budget < 10**6):
        raise InvalidInputError(f"budget must be a number of seconds between 0 and 1e6, got {budget!r}")
    get_claim(label)
    if isinstance(scheme, StencilScheme):
        from symdecomp.claims.zoo_claims import zoo_claim_result  # imports this module

        return zoo_claim_result(label, scheme, budget=budget)
    scheme = catmull_clark() if scheme is None else check_scheme(scheme)
    result = _check_claim(label, get_claim(label).reads_instead(scheme) or scheme, budget)
    return dataclasses.replace(result, parameter=get_claim(label).parameter)


@cache
def _check_claim(label: str, scheme: Scheme, budget: float | None) -> CheckResult:
    try:
        with time_budget(budget):
            return _run_check(label, scheme)
    except BudgetExceeded:
        return CheckResult(Status.UNDECIDED, f"the check did not finish within its budget of {budget:g} s (a longer budget may "
                                             "decide it: --budget)")


def _run_check(label: str, scheme: Scheme) -> CheckResult:
    c = get_claim(label)
    try:
        if (reason := c.unmet(scheme)) is not None:
            return CheckResult(Status.NOT_APPLICABLE, reason)
        result = c.check(scheme)
    # NotApplicableError (the scheme does not meet the hypotheses of an analysis the check uses) is an
    # InvalidSchemeError; another one means the scheme is outside what the claim's derivation covers (module docstring).
    except InvalidSchemeError as exc:
        why = Text(*exc.parts) if exc.parts else Verbatim(exc)
        return CheckResult(Status.NOT_APPLICABLE, Text("not applicable to the scheme ", Verbatim(repr(scheme.name)), ": ", why))
    except Exception as exc:  # the registry reports, the caller decides
        tb = Verbatim(traceback.format_exception_only(type(exc), exc)[-1].strip())
        if scheme.parameters:  # a numeric step met a free parameter: the check needs values, it did not fail
            return CheckResult(Status.NOT_APPLICABLE, Text(
                "not applicable to the scheme ", Verbatim(repr(scheme.name)), f" while its parameters "
                f"{', '.join(map(str, scheme.parameters))} are free: the check compares numbers (it stopped at ", tb,
                "); give the parameters values"))
        return CheckResult(Status.ERROR, Text("check raised ", tb))
    if not isinstance(result, CheckResult):
        return CheckResult(Status.ERROR, f"check returned {type(result).__name__}, not CheckResult")
    undefined = undefined_values(result.evidence, result.counterexample, result.correction)
    if undefined and result.status not in (Status.UNDECIDED, Status.NOT_APPLICABLE, Status.ERROR):
        return CheckResult(Status.UNDECIDED, Text(f"no verdict: the check's findings hold an undefined value ({undefined}), "
                                                  f"so its '{result.status.value}' rests on nothing: ", result.evidence))
    if result.status in (Status.REFUTED, Status.CORRECTED) and unbound_parameters(result.counterexample, scheme.parameters):
        return at_parameter_values(scheme, result, lambda concrete: _run_check(label, concrete))
    return result


def is_zero(expr) -> bool:
    """True when ``expr`` simplifies to exactly zero (a matrix: every entry)."""
    if isinstance(expr, sp.MatrixBase):
        return all(is_zero(e) for e in expr)
    return sp.simplify(sp.expand(expr)) == 0
