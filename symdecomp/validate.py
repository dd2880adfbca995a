"""One validation layer for everything that enters the package from outside.

Valences, frequencies, digits, precisions, levels, parameter values and exact numbers are
checked here, once, at the public boundary, and refused with the package's own errors
(:mod:`symdecomp.errors`) naming the argument and the value. Integers must be integers:
``5.9``, ``"5"``, ``True`` and ``Symbol('n')`` are refused, never truncated or guessed
(numpy and sympy integers are accepted). Loaders of user data (the command line, scheme
files) call the same functions.

>>> check_valence(5)
5
>>> check_valence(5.9)
Traceback (most recent call last):
...
symdecomp.errors.InvalidValenceError: valence n must be an integer >= 3, got 5.9 (float)
>>> check_frequency(3, 4, period=4)
3
>>> check_int(True, "levels")
Traceback (most recent call last):
...
symdecomp.errors.InvalidInputError: levels must be an integer, got True (bool)
"""

from __future__ import annotations

import functools
import inspect
import numbers
import os
import sys
from collections.abc import Callable, Iterable, Mapping
from fractions import Fraction
from typing import Any, ParamSpec, Protocol, TypeVar

import sympy as sp

from symdecomp.errors import (
    FrequencyOutOfRangeError,
    InvalidExpressionError,
    InvalidInputError,
    InvalidSchemeError,
    InvalidTypeError,
    InvalidValenceError,
    ResourceLimitError,
)
from symdecomp.expressions import exact_value

__all__ = [
    "check_int",
    "check_type",
    "check_valence",
    "check_frequency",
    "check_digits",
    "check_precision",
    "check_levels",
    "check_bits",
    "check_depth",
    "check_rational",
    "cached",
    "parameter_values",
    "check_memory",
    "MAX_DIGITS",
    "MAX_DPS",
    "MAX_BITS",
    "MAX_DEPTH",
    "MEMORY_LIMIT",
    "MAX_DOUBLE_DIGITS",
    "FLOAT_DIGITS",
    "DEFAULT_BUDGET",
    "MAX_REPORT_VALENCE",
    "API_LIMITS",
    "INPUT_LIMITS",
    "check_limit",
    "MAX_MESH_VALENCE",
    "MESH_FORMATS",
    "MAX_COORDINATE",
    "finite_double",
    "MAX_NUMBER_CHARS",
    "MAX_MESH_FILE_BYTES",
    "check_mesh_valence",
    "mesh_memory",
    "MESH_ADVICE",
]

#: Most significant digits printed (a value is evaluated at a little more than this).
MAX_DIGITS = 1000
#: Most decimal digits of working precision (an eigenvalue solve at this precision and n = 64
#: takes minutes; beyond it, hours).
MAX_DPS = 1000
#: Largest memory (bytes) a single dense step may be estimated to need before it is refused:
#: half the machine's physical memory, and never more than 16 GiB.
MEMORY_LIMIT = None  # computed lazily by _memory_limit()
#: Most bits of working precision of a ball computation (about 20 000 decimal digits; one Arb
#: eigen-decomposition at this precision takes minutes).
MAX_BITS = 1 << 16
#: Deepest subdivision of a Bezier net in a sign test: each level splits a piece in four, so depth
#: 12 is 16 million pieces.
MAX_DEPTH = 12
#: The most digits of agreement asked of a double-precision check
#: (:func:`~symdecomp.verify.numeric.ring_numeric_check`, ``symdecomp check --digits``).
MAX_DOUBLE_DIGITS = 12
#: ``digits`` of a JSON document whose numbers are the correctly rounded float64 values (shortest form)
#: (:mod:`symdecomp.output.evaldata`, the least ``symdecomp evaldata --digits``).
FLOAT_DIGITS = 17
#: Seconds one claim's check may take (wall clock) before it is reported ``undecided``: ``check_claim``'s
#: ``budget`` and ``symdecomp claims --budget`` (:mod:`symdecomp.claims.guards`). Every check on standard
#: Catmull-Clark takes a few seconds.
DEFAULT_BUDGET = 60.0
#: The largest valence of a report (:mod:`symdecomp.output.report`, ``symdecomp report --n``): its tables grow
#: with every valence (2n + 1 eigenvalues, masks of 2n + 1 weights) and the eigen-polygon figure has n panels a row.
MAX_REPORT_VALENCE = 16
#: The most faces of a refined mesh ``symdecomp refine --plot`` draws (:mod:`symdecomp.output.plotting.refine_figure`):
#: a larger mesh is drawn from an even sample of its faces, as the figure's title says (a picture, not minutes of drawing).
MAX_REFINED_FACES = 8192

#: Upper bounds of the API's entry points and why: ``name: (bound, reason)``. Each is enforced by its entry point
#: (:func:`check_limit`), shared by the command that calls it, and listed with the command line's bounds in
#: :data:`symdecomp.cli.common.LIMITS` (the one table the docs render).
API_LIMITS = {
    "artifact_indicators(n)": (4096, "a valence costs time ~ n (the C1 test's spectrum at n/2 + 1 frequencies plus one "
                               "exact left eigenvector in Q(zeta_2n)): n = 1024 takes about 0.4 s, n = 4096 3 to 8 s"),
    "second_order_eigenstructure(n)": (4096, "the 2-ring matrix's spectrum at n/2 + 1 frequencies, certified in Arb: "
                                       "time ~ n, n = 4096 takes about 2 s"),
    "tune --region, interval_region, placed_points: phi(n)": (4, "the region's exact signs are decided in Q(cos(2 pi/n), lambda_1), of degree up to "
                                 "2 phi(n) (Euler's phi): at phi(n) <= 4 (n = 3, 4, 5, 6, 8, 10, 12) a region takes 2 to 45 s, "
                                 "at phi(7) = 6 two to over five minutes, and every step of phi doubles the degree"),
    "c1_test(n)": (10000, "Reif's test costs time ~ n (n/2 + 1 frequency blocks, memory O(n)): n = 10000 takes about 4 s"),
    "classify_shape(n)": (4096, "the central surface's Bezier nets at n/2 + 1 frequencies, certified: n = 4096 takes about 4 s"),
    "closed_form_spectrum(n)": (2000, "one evaluation of the closed forms per frequency: n = 2000 takes about 2 s"),
    "ring_spectrum(n)": (10000, "a K-ring's factored spectrum, one block per frequency, time ~ n (the structural certificate "
                         "of check --certify reads it up to its bound): n = 2000 takes about 15 s with exact values"),
    "ring_masks(n)": (1000, "2n + 1 weights a ring, each from a certified left eigenvector: n = 1000 takes about 3 s"),
    "certify_ring(n)": (10000, "the K-ring certificate, one factor per frequency (check --certify on the structural route "
                        "goes this far): n = 2000 takes about 10 s"),
    "patch_matrices(n)": (1000, "Stam's (2n + 8)-point matrices from one exact refinement of a mesh around the vertex, "
                          "dense in n: n = 1000 takes about 5 s and 200 MB"),
    "jordan_block_size(n)": (10000, "the Eq. 43 block holds cos(2 pi/n): exact ranks in Q(cos(2 pi/n)), whose degree "
                             "grows like n"),
    "jordan_vertex_weights(n)": (10000, "the Eq. 43 block holds cos(2 pi/n): an exact solve in Q(cos(2 pi/n)), whose "
                                 "degree grows like n"),
}


def check_limit(value, name: str, argument: str, *, minimum: int = 3, error: type = InvalidValenceError) -> int:
    """``value`` as an ``int`` within ``minimum`` and the bound :data:`API_LIMITS` gives ``name`` (with its reason).

    >>> check_limit(10**6, "artifact_indicators(n)", "valence n")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    symdecomp.errors.InvalidValenceError: valence n must be an integer with 3 <= n <= 4096, got 1000000 (a valence costs ...)
    """
    bound, reason = API_LIMITS[name]
    return check_int(value, argument, minimum=minimum, maximum=bound, error=error, reason=reason)


#: The mesh file formats read and written (by extension): :mod:`symdecomp.schemes.meshformats`; named here so that
#: the command line can offer them without importing the readers.
MESH_FORMATS = ("obj", "off", "ply")
#: The bounds of inputs that are no single entry point's ``n``, kept here so that the modules that enforce them read
#: them from one table (listed with the others in :data:`symdecomp.cli.common.LIMITS`): ``name: (bound, reason)``.
INPUT_LIMITS: dict[str, tuple[Any, str]] = {  # bounds are ints, except the largest double
    "mesh (inspect, design --mesh, refine, API): valence of an analysed vertex": (64, "the valence bound of design --n; "
        "a fan of thousands of faces is read, and refused where it is analysed"),
    "mesh: magnitude of a coordinate": (sys.float_info.max, "every coordinate is a finite double (1e309 is refused); the "
        "analyses scale what would overflow"),
    "mesh: characters of one number": (1100, "the exact decimal of every double fits; a 5000-digit number does not"),
    "mesh: bytes of a file": (512 * 2**20, "from a path or standard input, whatever size the file system reports"),
    "mesh, OBJ: bytes of a line": (8 * 2**20, "a face of a million corners fits; a file of one endless line does not"),
    "mesh, PLY: bytes of the header": (2**20, "'end_header' is looked for this far; a header is a few hundred bytes"),
    "refine --steps (refine_mesh)": (8, "each step multiplies the faces by 4 (8 steps: 65536 faces for one)"),
    "scheme file: bytes": (100_000, "a scheme file is a few lines of TOML"),
    "design_ring(n)": (1000, "40-digit eigenvectors per frequency and exact checks in Q(zeta_4n); design --n stops at 64"),
    "levels": (40, "double precision: after about 40 levels the ring is below rounding for every valence"),
    "design --position, --elliptic, --hyperbolic: magnitude": (10**6, "the designed ring's exact coordinates stay "
        "small enough to print and write as doubles"),
    "design --angle: magnitude (radians)": (10**6, "read as a double, whose spacing there is still far below a degree"),
    "design --normal, --tangent: integer entries of the direction": (10**15, "15 significant digits, what a double carries"),
    "design --mesh: magnitude of a ring's coordinates (and 1/extent)": (10**12, "beyond, the tangents' product "
        "overflows or underflows in doubles"),
    "--boundary, --corner, --crease, --dart: faces": (64, "the faces K (K + K2 on a crease) around a boundary, crease, "
        "corner or dart vertex where its 1-ring matrices are dense and exact (darts, semi-sharp creases, masks, "
        "check --certify --route charpoly, check's numeric eigenvalues, C1's maps)"),
    "--boundary, --corner, --crease: faces by the blocks": (10_000, "the faces K (K + K2 on a crease) where spectrum "
        "and check read the vertex by the mirror decomposition's blocks: check --certify's structural route (the "
        "refined matrix's sparse rows against the mirror model, O(K): K = 10000 in about 10 s) and its numeric "
        "polylines (O(K^2) doubles: 16 to 35 s at 10000)"),
    "masks --boundary, ... (sharp_masks): unknowns of a mask's system": (1200, "an exact mask is the null space of a "
        "rational system of m points x the eigenvalue's degree unknowns, eliminated densely in time ~ (m d)^3 with "
        "growing rationals (masks 64 --dart asked for about 8000 and ended in an allocation failure)"),
}
MAX_MESH_VALENCE = INPUT_LIMITS["mesh (inspect, design --mesh, refine, API): valence of an analysed vertex"][0]
MAX_COORDINATE = INPUT_LIMITS["mesh: magnitude of a coordinate"][0]
MAX_NUMBER_CHARS = INPUT_LIMITS["mesh: characters of one number"][0]
MAX_MESH_FILE_BYTES = INPUT_LIMITS["mesh: bytes of a file"][0]
#: What a refusal of a mesh for its memory advises.
MESH_ADVICE = "split the mesh, or read a smaller one"
#: Measured peak memory of reading and checking a mesh: bytes per byte of a text file (a 1M-face quad OBJ of 69 MB:
#: 750 MB in all), and per corner, face and vertex of the mesh checked (1M quads: 510 MB; 1.56M triangles: 700 MB).
_MESH_BYTES_PER_FILE_BYTE, _MESH_BYTES_PER_CORNER, _MESH_BYTES_PER_FACE, _MESH_BYTES_PER_VERTEX = 11, 44, 300, 48


def _kind(value) -> str:
    return type(value).__name__


def _is_integer(value) -> bool:
    if isinstance(value, bool):
        return False
    if isinstance(value, sp.Basic):
        return bool(value.is_Integer)
    return isinstance(value, numbers.Integral)


def check_int(value, argument: str, *, minimum: int | None = None, maximum: int | None = None,
              error: type = InvalidInputError, reason: str = "") -> int:
    """``value`` as an ``int`` if it is an integer in ``[minimum, maximum]``; else ``error``.

    ``reason`` (shown when ``value`` is above ``maximum``) says why the bound is there.
    """
    if type(value) is int and (minimum is None or value >= minimum) and (maximum is None or value <= maximum):
        return value  # the common case, on hot paths (cached functions check before their lookup)
    bounds = ""
    if minimum is not None and maximum is not None:
        bounds = f" with {minimum} <= {argument.split()[-1]} <= {maximum}"
    elif minimum is not None:
        bounds = f" >= {minimum}"
    elif maximum is not None:
        bounds = f" <= {maximum}"
    if not _is_integer(value):
        shown = repr(value) if not isinstance(value, sp.Basic) else str(value)
        raise error(f"{argument} must be an integer{bounds}, got {shown} ({_kind(value)})")
    value = int(value)
    if (minimum is not None and value < minimum) or (maximum is not None and value > maximum):
        why = f" ({reason})" if reason and maximum is not None and value > maximum else ""
        raise error(f"{argument} must be an integer{bounds}, got {value}{why}")
    return value


def check_type(value, kind: type | tuple[type, ...], argument: str, *, hint: str = ""):
    """``value`` if it is an instance of ``kind``, else :class:`~symdecomp.errors.InvalidTypeError` naming ``argument``.

    ``hint`` says where such a value comes from (e.g. ``"catmull_clark(), loop()"``).
    """
    if not isinstance(value, kind):
        names = " or ".join(k.__name__ for k in (kind if isinstance(kind, tuple) else (kind,)))
        raise InvalidTypeError(f"{argument} must be a {names}{f' ({hint})' if hint else ''}, got {value!r:.60} "
                               f"({type(value).__name__})")
    return value


def check_valence(n, *, minimum: int = 3, maximum: int | None = None, argument: str = "valence n") -> int:
    """Return ``n`` as an ``int`` if it is an integer valence ``>= minimum`` (and ``<= maximum``).

    >>> check_valence(2)
    Traceback (most recent call last):
    ...
    symdecomp.errors.InvalidValenceError: valence n must be an integer >= 3, got 2
    """
    if isinstance(n, sp.Symbol):
        raise InvalidValenceError(
            f"{argument} must be a concrete integer >= {minimum}, got the symbol {n}; the closed forms in "
            "symbolic n are the functions without a valence argument"
        )
    return check_int(n, argument, minimum=minimum, maximum=maximum, error=InvalidValenceError)


def check_frequency(j, n: int, *, period: int | None = None, start: int = 0, argument: str = "frequency j") -> int:
    """Return ``j`` as an ``int`` if ``start <= j < period`` (``period`` defaults to ``2n``).

    The paper indexes the components of the 1-ring 2n-gon by ``j = 0..2n-1`` (Eq. 11), so
    that is the default range.

    >>> check_frequency(8, 4)
    Traceback (most recent call last):
    ...
    symdecomp.errors.FrequencyOutOfRangeError: frequency j must be an integer with 0 <= j < 8 (valence n = 4), got 8
    """
    n = check_valence(n)
    period = 2 * n if period is None else period
    if not _is_integer(j):
        shown = repr(j) if not isinstance(j, sp.Basic) else str(j)
        raise FrequencyOutOfRangeError(
            f"{argument} must be an integer with {start} <= j < {period}, got {shown} ({_kind(j)})"
        )
    j = int(j)
    if not start <= j < period:
        raise FrequencyOutOfRangeError(
            f"{argument} must be an integer with {start} <= j < {period} (valence n = {n}), got {j}"
        )
    return j


def check_digits(digits, argument: str = "digits", *, maximum: int = MAX_DIGITS) -> int:
    """Significant digits of printed values: an integer in ``[1, MAX_DIGITS]``."""
    return check_int(digits, argument, minimum=1, maximum=maximum,
                     reason="more digits than anyone reads; each one costs evaluation time")


def check_precision(dps, argument: str = "dps", *, minimum: int = 5, maximum: int = MAX_DPS) -> int:
    """Decimal digits of working precision: an integer in ``[minimum, MAX_DPS]``."""
    return check_int(dps, argument, minimum=minimum, maximum=maximum,
                     reason="an eigenvalue solve at this precision takes hours")


def check_levels(levels, argument: str = "levels", *, minimum: int = 0, maximum: int | None = None,
                 reason: str = "") -> int:
    """A number of refinement levels or steps: an integer in ``[minimum, maximum]``."""
    return check_int(levels, argument, minimum=minimum, maximum=maximum, reason=reason)


def check_bits(prec, argument: str = "prec", *, minimum: int = 16, maximum: int = MAX_BITS) -> int:
    """Bits of working precision of a ball computation: an integer in ``[minimum, MAX_BITS]``."""
    return check_int(prec, argument, minimum=minimum, maximum=maximum,
                     reason="an Arb computation at this precision takes minutes per step")


def check_depth(depth, argument: str = "max_depth", *, maximum: int = MAX_DEPTH) -> int:
    """Depth of a subdivision of Bezier nets: an integer in ``[0, MAX_DEPTH]``."""
    return check_int(depth, argument, minimum=0, maximum=maximum,
                     reason="each level splits a piece in four: depth 12 is 16 million pieces")


def check_rational(value, argument: str) -> Fraction:
    """``value`` as a ``Fraction`` if it is an exact rational number (int, Fraction, sympy Rational, text like ``'1/3'``).

    Read through :func:`~symdecomp.expressions.exact_value` (text is parsed, never evaluated); floats,
    booleans, symbols and irrational numbers are refused with an error naming ``argument``.

    >>> check_rational("-3/4", "angle")
    Fraction(-3, 4)
    """
    if hasattr(value, "dtype") and getattr(value.dtype, "kind", "") in "iu":  # a numpy integer is an int
        value = int(value)
    expr = exact_value(value, {}, argument=argument)
    if not isinstance(expr, sp.Rational):
        raise InvalidInputError(f"{argument} must be an exact rational number, got {expr}")
    return Fraction(int(expr.p), int(expr.q))


_P = ParamSpec("_P")
_R = TypeVar("_R", covariant=True)


class CachedFunction(Protocol[_P, _R]):
    """A function wrapped by :func:`cached`: called as the function, with ``functools.lru_cache``'s two methods."""

    def __call__(self, *args: _P.args, **kwargs: _P.kwargs) -> _R: ...

    def cache_clear(self) -> None: ...

    def cache_info(self) -> Any: ...


def cached(maxsize: int | None = None, **checks: Callable[..., Any]) -> Callable[[Callable[_P, _R]], CachedFunction[_P, _R]]:
    """A ``functools.lru_cache`` keyed on the checked arguments: the checks run before the lookup.

    A bare cache answers ``f(scheme, 5.0)`` from the entry of ``f(scheme, 5)`` (``5 == 5.0`` and
    ``hash(5) == hash(5.0)``) without running the function's own checks. Here ``checks[name]``
    runs first on the argument ``name`` (defaults filled in), raising the package's error or
    returning the normalized value (a numpy integer as ``int``), and the cache sees only those.

    >>> @cached(n=check_valence)
    ... def size(n):
    ...     return 2 * n + 1
    >>> size(5), size.cache_info().currsize
    (11, 1)
    >>> size(5.0)
    Traceback (most recent call last):
    ...
    symdecomp.errors.InvalidValenceError: valence n must be an integer >= 3, got 5.0 (float)
    """

    def decorate(function: Callable[_P, _R]) -> CachedFunction[_P, _R]:
        names = list(inspect.signature(function).parameters)
        unknown = set(checks) - set(names)
        if unknown:  # pragma: no cover - a typo in a decorator
            raise TypeError(f"{function.__qualname__} has no arguments {sorted(unknown)}")
        store = functools.lru_cache(maxsize)(function)
        where = tuple((names.index(name), name, check) for name, check in checks.items())

        @functools.wraps(function)
        def checked(*args: Any, **kwargs: Any) -> Any:
            # by position or by keyword, without binding the signature (a hot path: a cache hit costs microseconds);
            # an argument left at its default is the function's own choice and needs no check
            values = list(args)
            for index, name, check in where:
                if index < len(values):
                    values[index] = check(values[index])
                elif name in kwargs:
                    kwargs[name] = check(kwargs[name])
            return store(*values, **kwargs)

        checked.cache_clear = store.cache_clear  # type: ignore[attr-defined]
        checked.cache_info = store.cache_info  # type: ignore[attr-defined]
        return checked  # type: ignore[return-value]

    return decorate


def parameter_values(declared: Iterable[sp.Symbol], given: Mapping | None, *, owner: str = "scheme",
                     symbols: Mapping[str, sp.Symbol] | None = None, require_all: bool = True) -> dict:
    """Values of free parameters as a sympy substitution ``{symbol: exact value}``.

    ``declared`` are the parameters the owner (a scheme) has. Keys of ``given`` may be the
    symbols or their names; values are exact numbers, sympy expressions or text (parsed by
    :func:`symdecomp.expressions.parse_expression` in ``symbols``, e.g. ``{"n": n}``), never
    floats. With ``require_all`` every declared parameter needs a value.
    """
    declared = tuple(declared)
    if given is not None and not isinstance(given, Mapping):
        raise InvalidSchemeError(f"parameters must be a mapping {{name: value}}, got {_kind(given)}")
    subs = {}
    for key, value in dict(given or {}).items():
        name = key if isinstance(key, str) else str(key) if isinstance(key, sp.Symbol) else None
        if name is None:
            raise InvalidSchemeError(f"parameter names must be strings or symbols, got {key!r} ({_kind(key)})")
        match = [p for p in declared if str(p) == name]
        if not match:
            raise InvalidSchemeError(
                f"{owner} has no parameter {name}; its parameters are {[str(p) for p in declared] or 'none'}"
            )
        try:
            subs[match[0]] = exact_value(value, symbols, argument=f"parameter {name}")
        except InvalidExpressionError as exc:
            raise InvalidSchemeError(str(exc)) from None
    missing = [str(p) for p in declared if p not in subs]
    if require_all and missing:
        raise InvalidSchemeError(f"{owner} has free parameters {missing}; give their values")
    return subs


def _memory_limit() -> int:
    """Half the machine's memory, at most 16 GiB, and no more than this process may map (``ulimit -v``)."""
    try:
        physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):  # pragma: no cover - not POSIX
        physical = 8 << 30
    limit = min(physical // 2, 16 << 30)
    try:
        import resource

        mapped = resource.getrlimit(resource.RLIMIT_AS)[0]
    except (ImportError, OSError, ValueError):  # pragma: no cover - not POSIX
        return limit
    return limit if mapped == resource.RLIM_INFINITY else min(limit, mapped)


def check_memory(estimate: int, what: str, advice: str = "choose a smaller valence") -> None:
    """Refuse a step whose estimated memory ``estimate`` (bytes) is beyond :func:`_memory_limit`; ``advice`` ends the line."""
    limit = _memory_limit() if MEMORY_LIMIT is None else MEMORY_LIMIT
    if estimate > limit:
        raise ResourceLimitError(
            f"{what} would need about {_human(estimate)} of memory, more than the limit of {_human(limit)}; {advice}"
        )


def finite_double(value: Fraction) -> float | None:
    """The double nearest to ``value`` (correctly rounded), or ``None`` when it is beyond the range of doubles."""
    if abs(value.numerator).bit_length() - value.denominator.bit_length() > 1030:
        return None
    try:
        return float(value)
    except OverflowError:
        return None


def check_mesh_valence(n: int, vertex: int, name: str = "mesh") -> int:
    """``n`` if the vertex's valence is at most :data:`MAX_MESH_VALENCE`; else one line naming the mesh and the vertex."""
    from symdecomp.errors import InvalidMeshError

    if n > MAX_MESH_VALENCE:
        raise InvalidMeshError(f"{name}: vertex {vertex} has valence {n}; a mesh's vertices are analysed up to valence "
                               f"{MAX_MESH_VALENCE}")
    return n


def mesh_memory(file_bytes: int = 0, corners: int = 0, faces: int = 0, vertices: int = 0) -> int:
    """The estimated peak memory (bytes) of reading a text mesh file of ``file_bytes`` bytes, plus that of checking a
    mesh of ``corners`` face corners in all, ``faces`` faces and ``vertices`` vertices, as measured
    (``benchmarks/bench_meshread.py``).

    >>> round(mesh_memory(file_bytes=69_000_000) / 2**20), round(mesh_memory(corners=4 * 10**6, faces=10**6, vertices=10**6) / 2**20)
    (724, 500)
    """
    return (_MESH_BYTES_PER_FILE_BYTE * int(file_bytes) + _MESH_BYTES_PER_CORNER * int(corners) + _MESH_BYTES_PER_FACE * int(faces)
            + _MESH_BYTES_PER_VERTEX * int(vertices))


def _human(size: float) -> str:
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if size < 1024:
            return f"{size:.0f} {unit}"
        size /= 1024
    return f"{size:.0f} EiB"
