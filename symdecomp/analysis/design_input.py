"""The inputs of a design, read exactly and checked against stated bounds before any work.

:func:`~symdecomp.analysis.design.design_ring` and :func:`~symdecomp.analysis.redesign.redesign_vertex` build exact
rational nets, but they measure what the net achieves (tangents, normal, amounts) in doubles and 40-digit
arithmetic, and the designed heights are rounded to doubles. So every input has a bound that keeps those numbers
finite and meaningful:

* a position coordinate, an elliptic or hyperbolic amount: at most :data:`MAX_MAGNITUDE` in magnitude (the designed
  1-ring is about 1 across; the tangents, sums of its coordinates in doubles, keep about 10 significant digits);
* the hyperbolic angle: at most :data:`MAX_ANGLE` radians in magnitude (read as a double, whose spacing there is
  still far below a period);
* a normal or tangent direction: the primitive integer vector along it (the net's frame) has entries of at most
  :data:`MAX_DIRECTION` (15 significant digits, what a double carries);
* a mesh whose vertex is redesigned: the 1-ring's coordinates at most :data:`MAX_COORDINATE` in magnitude and the
  ring at least ``1/MAX_COORDINATE`` across (beyond, the tangents' product overflows or underflows in doubles).

Each refusal is :class:`~symdecomp.errors.InvalidInputError` naming the argument.

>>> frame((0, 0, 2))
((0, 1, 0), (-1, 0, 0), (0, 0, 1))
>>> amount("1e308", "elliptic")
Traceback (most recent call last):
...
symdecomp.errors.InvalidInputError: elliptic must be at most 1e+06 in magnitude, got 1e308
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

import sympy as sp

from symdecomp.errors import InvalidInputError
from symdecomp.expressions import MAX_DIGITS, exact_value
from symdecomp.validate import INPUT_LIMITS

__all__ = ["MAX_MAGNITUDE", "MAX_COORDINATE", "MAX_ANGLE", "MAX_DIRECTION", "amount", "vector", "frame", "check_ring_scale"]

#: The largest magnitude of a position coordinate and of an elliptic or hyperbolic amount (the limits table).
MAX_MAGNITUDE = INPUT_LIMITS["design --position, --elliptic, --hyperbolic: magnitude"][0]

#: The largest magnitude of a coordinate of a redesigned 1-ring (and the reciprocal of its smallest extent).
MAX_COORDINATE = INPUT_LIMITS["design --mesh: magnitude of a ring's coordinates (and 1/extent)"][0]

#: The largest magnitude of the hyperbolic angle (radians).
MAX_ANGLE = INPUT_LIMITS["design --angle: magnitude (radians)"][0]

#: The largest entry of the primitive integer vector along a normal or tangent.
MAX_DIRECTION = INPUT_LIMITS["design --normal, --tangent: integer entries of the direction"][0]

#: A decimal number as text: read as the rational it spells (the mesh files' grammar).
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]{1,4})?")


def _exact(x, argument: str) -> sp.Expr:
    """A number from outside: a decimal text (``0.25``) as the rational it spells, else :func:`exact_value` (never evaluated)."""
    if isinstance(x, str) and _DECIMAL.fullmatch(x.strip()):
        digits = sum(c.isdigit() for c in x.strip().lower().partition("e")[0])
        if digits > MAX_DIGITS:  # the expression budget's bound on a number, here too
            raise InvalidInputError(f"{argument}: a number has at most {MAX_DIGITS} digits, got one of {digits}")
        return sp.Rational(Fraction(x.strip()))
    return exact_value(x, argument=argument)


def _shown(x) -> str:
    text = str(x).strip()
    return text if len(text) <= 40 else text[:37] + "..."


def amount(x, argument: str) -> sp.Expr:
    """An amount (``elliptic``, ``hyperbolic``) or the ``angle``: a real number, exact, within its bound."""
    value = _exact(x, argument)
    if not (value.is_real and value.is_finite):
        raise InvalidInputError(f"{argument} must be a real number, got {_shown(x)}")
    bound = MAX_ANGLE if argument == "angle" else MAX_MAGNITUDE
    if abs(sp.N(value, 30)) > bound:
        raise InvalidInputError(f"{argument} must be at most {float(bound):g} in magnitude, got {_shown(x)}")
    return value


def vector(value, argument: str, bound: int | None = MAX_MAGNITUDE) -> tuple:
    """3 rationals (ints, Fractions, text such as ``"1/3"``), each at most ``bound`` in magnitude (``None``: any)."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 3:
        raise InvalidInputError(f"{argument} must be 3 numbers (x, y, z), got {value!r:.60}")
    out = tuple(_exact(x, argument) for x in value)
    if not all(x.is_Rational for x in out):
        raise InvalidInputError(f"{argument} must have rational coordinates, got {value!r:.60}")
    if bound is not None and any(abs(x) > bound for x in out):
        raise InvalidInputError(f"{argument} must have coordinates of at most {float(bound):g} in magnitude, "
                                f"got {_shown(','.join(str(x) for x in value))}")
    return out


def cross(a, b):
    """``a x b`` of two 3-vectors over any ring (sympy numbers, :class:`~symdecomp.algebra.number_field.FieldElement`,
    ...): the one exact cross product (numpy's on arrays of floats)."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), sp.Integer(0))


def frame(normal, tangent=None) -> tuple:
    """``(u, v, N)``, exact: ``u`` the tangent projected off ``N`` (default: ``N`` crossed with its smallest axis), ``v = N x u``."""
    N = vector(normal, "normal", None)
    if not any(N):
        raise InvalidInputError("normal must not be the zero vector")
    if tangent is None:
        axis = min(range(3), key=lambda k: (abs(N[k]), k))
        tangent = cross(N, tuple(sp.Integer(int(k == axis)) for k in range(3)))
    t = vector(tangent, "tangent", None)
    u = tuple(x - dot(t, N) / dot(N, N) * y for x, y in zip(t, N))
    if not any(u):
        raise InvalidInputError("tangent must not be parallel to the normal")
    u, N = _primitive(u, "tangent"), _primitive(N, "normal")
    return u, _primitive(cross(N, u), "tangent"), N


def _primitive(w, argument: str) -> tuple:
    """The integer vector with coprime entries along ``w`` (same direction): coordinates ``p + x u + ...`` with
    dyadic ``x`` then terminate whenever ``p`` does."""
    scale = sp.ilcm(*[sp.Rational(x).q for x in w])
    ints = [int(x * scale) for x in w]
    g = math.gcd(*ints)
    out = tuple(x // g for x in ints)
    if max(abs(x) for x in out) > MAX_DIRECTION:
        raise InvalidInputError(f"{argument}: its direction needs integers beyond {float(MAX_DIRECTION):g} "
                                "(give it with at most 15 significant digits)")
    return tuple(sp.Integer(x) for x in out)


def check_ring_scale(mesh, ids, vertex: int) -> None:
    """Refuse a 1-ring (``ids`` of ``mesh``'s points) whose coordinates exceed :data:`MAX_COORDINATE` or that is
    smaller than ``1/MAX_COORDINATE`` across: its tangents and normal would overflow or underflow in doubles."""
    points = [mesh.points[i] for i in ids]
    if any(abs(c) > MAX_COORDINATE for p in points for c in p):
        raise InvalidInputError(f"{mesh.name}: vertex {vertex}: its 1-ring has coordinates beyond "
                                f"{float(MAX_COORDINATE):g} in magnitude; scale the mesh down")
    centre = points[0]
    if max(abs(c - o) for p in points for c, o in zip(p, centre)) * MAX_COORDINATE < 1:
        raise InvalidInputError(f"{mesh.name}: vertex {vertex}: its 1-ring is smaller than "
                                f"{1 / MAX_COORDINATE:g} across; scale the mesh up")
