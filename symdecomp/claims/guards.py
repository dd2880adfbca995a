"""What every verdict of the registry is guarded by: a time budget, concrete counterexamples, defined values.

* :func:`time_budget`: a check still running after its budget (``DEFAULT_BUDGET`` seconds, ``--budget``)
  is stopped and reported ``undecided``, saying so; ``claims`` on any valid scheme file ends.
* :func:`unbound_parameters`: a counterexample that is an expression in free parameters is no concrete
  case; the registry checks again at :func:`generic_parameter_values` and names those values.
* :func:`undefined_values`: ``nan``, ``zoo`` (``0/0`` from a zero vector taken as an eigenvector, say)
  in a finding means the verdict rests on nothing; the registry reports ``undecided``.

Findings are :class:`~symdecomp.claims.registry.Text` (read here through their ``parts``).
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

import sympy as sp

from symdecomp.validate import DEFAULT_BUDGET

__all__ = ["DEFAULT_BUDGET", "BudgetExceeded", "time_budget", "unbound_parameters", "generic_parameter_values",
           "at_parameter_values", "undefined_values"]


class BudgetExceeded(BaseException):
    """Raised inside a check when its time budget runs out (a ``BaseException``, so that no ``except Exception``
    inside a check or inside sympy can swallow it)."""


_ARMED = [False]


@contextmanager
def time_budget(seconds: float | None):
    """Raise :class:`BudgetExceeded` in the enclosed code after ``seconds`` of wall-clock time.

    A real-time interval timer (``SIGALRM``): it interrupts Python code, sympy's included, between two
    bytecodes; a single long call into a C library is interrupted when it returns. Only in the main thread
    (elsewhere, and for ``None``, there is no budget); a budget inside a budget is the outer one.
    """
    if (seconds is None or _ARMED[0] or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
        yield
        return

    def expire(signum, frame):
        raise BudgetExceeded

    previous = signal.signal(signal.SIGALRM, expire)
    _ARMED[0] = True
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        _ARMED[0] = False


def unbound_parameters(finding, parameters) -> set:
    """The parameters that occur in ``finding`` (a counterexample) other than as the left side of an assignment
    ``p = value``: a counterexample in which they occur is an expression, not a concrete case."""
    if not parameters or not hasattr(finding, "parts"):
        return set()
    wanted, found = set(parameters), set()

    def visit(obj) -> None:
        if isinstance(obj, sp.Eq) and obj.lhs.is_Symbol:
            visit(obj.rhs)
        elif isinstance(obj, sp.MatrixBase):
            for entry in obj:
                visit(entry)
        elif isinstance(obj, sp.Tuple):
            for entry in obj.args:
                visit(entry)
        elif isinstance(obj, sp.Basic):
            found.update(obj.free_symbols & wanted)

    for part in finding.parts:
        visit(part)
    return found


def generic_parameter_values(parameters) -> dict:
    """A concrete point for free parameters at which a statement that fails as an expression is tested: distinct
    small rationals ``1/11, 1/13, 1/17, ...`` (reciprocal primes, so that no parameter is 0 and no two agree)."""
    primes = sp.sieve.primerange(11, 10**6)
    return {p: sp.Rational(1, next(primes)) for p in parameters}


def undefined_values(*findings) -> str:
    """The undefined values (``nan``, ``zoo``, a float ``nan`` or ``inf``) in findings, as text (empty if none).

    No verdict may rest on one: ``0/0`` from a zero vector taken as an eigenvector is ``nan``."""
    found = set()

    def visit(obj) -> None:
        if hasattr(obj, "parts") and not isinstance(obj, sp.Basic):
            for part in obj.parts:
                visit(part)
        elif isinstance(obj, float) and (obj != obj or obj in (float("inf"), float("-inf"))):
            found.add(repr(obj))
        elif isinstance(obj, sp.MatrixBase):
            for entry in obj:
                visit(entry)
        elif isinstance(obj, (tuple, list)):
            for entry in obj:
                visit(entry)
        elif isinstance(obj, sp.Basic):
            if obj.has(sp.nan):
                found.add("nan")
            if obj.has(sp.zoo):
                found.add("zoo")
            if any(f.is_finite is False or f != f for f in obj.atoms(sp.Float)):
                found.add("a float nan or inf")

    for finding in findings:
        visit(finding)
    return ", ".join(sorted(found))


def at_parameter_values(scheme, symbolic, rerun):
    """A refutation whose counterexample is an expression in free parameters, made concrete.

    The statement fails as an identity in the parameters; it may hold at some values (where the scheme is
    Catmull-Clark, say). The check runs again with the parameters at :func:`generic_parameter_values`: a
    refutation there, with a counterexample free of parameters, refutes the statement for the scheme (a
    universal statement over the parameters), scope ``single case`` (one point of the family). Otherwise
    the verdict depends on the values and is ``undecided``. ``rerun(scheme)`` is the check on another scheme.
    """
    from symdecomp.claims.registry import CheckResult, Scope, Status, Text, Verbatim
    from symdecomp.errors import InvalidSchemeError

    values = generic_parameter_values(scheme.parameters)
    where = Text(*[part for k, (p, v) in enumerate(values.items())
                   for part in ((", " if k else ""), sp.Eq(p, v, evaluate=False))])
    try:
        concrete_scheme = scheme.substitute(values, name=f"{scheme.name} at {where}")
    except InvalidSchemeError as exc:
        return CheckResult(Status.UNDECIDED, Text("the counterexample is an expression in the parameters (", symbolic.counterexample,
                                                  "), and the scheme is not defined at ", where, ": ", Verbatim(exc)))
    concrete = rerun(concrete_scheme)
    if concrete.status in (Status.REFUTED, Status.CORRECTED) and not unbound_parameters(concrete.counterexample, scheme.parameters):
        return CheckResult(
            concrete.status,
            Text("with the parameters at ", where, " (the statement fails as an identity in them): ", concrete.evidence),
            steps=symbolic.steps,
            counterexample=Text(where, ": ", concrete.counterexample),
            correction=concrete.correction,
            scope=Scope.SINGLE_CASE,
        )
    return CheckResult(
        Status.UNDECIDED,
        Text("the verdict depends on the values of the parameters: as an expression in them the statement fails (",
             symbolic.counterexample, "), but at ", where, " the check gives ", concrete.status.value),
    )
