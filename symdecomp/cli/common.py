"""Helpers shared by the subcommands: the parser, strict argument types, limits, progress, output.

Every argument type is strict: integers are ASCII digits with an optional sign (``5_0``,
Unicode digits, ``5.0`` and ``0x5`` are refused), each bounded by a documented limit
(:data:`LIMITS`, with the reason). Every option may be given once (:class:`Once`); a
repeated option is an error, not "the last one wins". The checks call
:mod:`symdecomp.validate`, the same functions the API uses.
"""

from __future__ import annotations

import argparse
import os
import re
import sys

from symdecomp.cli.files import FIFO_WAIT
from symdecomp.cli.json_envelope import print_json
from symdecomp.cli.progress import progress
from symdecomp.errors import InvalidInputError, SymdecompError
from symdecomp.parallel import parse_executor
from symdecomp.parallel.cluster import EXCHANGE_SECONDS, GREETING_LIMIT
from symdecomp.schemes.files import SCHEMES, load_scheme
from symdecomp.schemes.rings import MAX_RINGS
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import (
    API_LIMITS,
    DEFAULT_BUDGET,
    INPUT_LIMITS,
    MAX_DEPTH,
    MAX_DIGITS,
    MAX_DOUBLE_DIGITS,
    MAX_DPS,
    MAX_REPORT_VALENCE,
)

__all__ = [
    "Parser",
    "Once",
    "LIMITS",
    "integer",
    "valence",
    "valence_range",
    "positive_int",
    "digits",
    "SCHEMES",
    "scheme_by_name",
    "add_scheme_option",
    "add_rings_option",
    "add_pool_options",
    "general_path",
    "closed_form_obstacle",
    "check_scheme_valences",
    "refuse_non_quad",
    "given",
    "sharp_given",
    "SHARP_OPTIONS",
    "refuse_together",
    "progress",
    "print_json",
    "estimate_seconds",
    "ARTIFACTS_COST",
    "ARTIFACTS_SECONDS",
]

#: ``artifacts --n A:B``: seconds of CPU one valence N costs, about ``ARTIFACTS_COST * N`` (measured, N = 64 to 4096),
#: and the most a range may be estimated to cost.
ARTIFACTS_COST, ARTIFACTS_SECONDS = 4e-4, 600

#: Upper bounds of the command line and why they are there: ``name: (bound, reason)``. The API's bounds
#: (:data:`symdecomp.validate.API_LIMITS`) and the inputs' (mesh files, design amounts, sharp vertices:
#: :data:`symdecomp.validate.INPUT_LIMITS`, read by the modules that enforce them) close the table: the docs render
#: it, and each bound is enforced where it is named (``tests/cli/test_limits_table.py`` goes one step past each).
LIMITS = {
    "digits": (MAX_DIGITS, "more digits than anyone reads; each one costs evaluation time"),
    "dps": (MAX_DPS, "an eigenvalue solve at this precision takes hours"),
    "check --dps (triangle schemes, --rings > 1)": (MAX_DOUBLE_DIGITS, "the numeric check of the K-ring frequency "
                                                    "matrices runs in double precision; --certify proves them"),
    "spectrum": (API_LIMITS["closed_form_spectrum(n)"][0], "the time grows with N (one evaluation per frequency): N = 1000 takes about a second"),
    "masks": (1000, "2N + 1 weights per mask, each a certified ball: N = 1000 takes about a second"),
    "charpoly": (300, "the exact characteristic polynomial of the (2N+1)x(2N+1) matrix grows like N^3"),
    "tune": (1000, "the exact solve grows with N: N = 300 takes about 10 s"),
    "tune --table": (200, "one exact evaluation per valence: N = 60 takes about 10 s"),
    "check": (128, "numeric mode solves a (2N+1)x(2N+1) eigenproblem at rising precision, time ~ N^3"),
    "check --certify": (512, "the dense route (--route charpoly): the memory of the exact characteristic polynomial grows "
                        "like N^3; N = 256 takes minutes"),
    "check --certify --route structural": (10000, "the structural route's memory grows like N (about 10 kB per valence "
                                           "and ring squared); N = 1000 takes about a second on the 1-ring"),
    "design": (64, "exact checks in Q(zeta_4N) and 40-digit eigenvectors per frequency: N = 64 takes seconds"),
    "oracle": (64, "OpenSubdiv refines the whole 1-ring mesh; the comparison is in double precision"),
    "jobs": (256, "more worker processes than this only cost memory"),
    "c1": (API_LIMITS["c1_test(n)"][0], "a valence costs time ~ N (N/2 + 1 frequency blocks of size 2 or 1, memory O(N)): N = 10000 takes about "
           "0.15 s, the range 3:10000 about 10 minutes of CPU (--executor dask spreads it over a cluster)"),
    "artifacts": API_LIMITS["artifact_indicators(n)"],
    "artifacts --n A:B": (ARTIFACTS_SECONDS, "estimated seconds of CPU for the range, from the cost of one valence (about "
                          f"{ARTIFACTS_COST:.0e} N s, so 3:1000 is about 3 minutes and 3:1700 the most); a range beyond it is refused before it "
                          "starts: split it, or run it on a cluster in parts"),
    "c1 --k": (10000, "the spectral and tangent conditions are read from the sector's blocks (O(log K) per sector: "
               "K = 10000 in under a second); with BLZ's rules (the blocks' exact double 1/2) the characteristic map is "
               "certified from the closed-form modes on a few faces per sector from 8 faces on (K = 1000 in about 0.05 s); "
               "otherwise on the eigenvectors the blocks name, "
               "in Arb from the sector's exact sparse matrix (cubic in K: K = 32 takes about 3 s, K = 64 about 15 s), for "
               "vertices of at most 64 faces only, so a sector with more faces that the blocks do not show to fail is "
               "undecided"),
    "c1 --depth": (MAX_DEPTH, "each level splits a piece in four: depth 12 is 16 million pieces"),
    "rings": (MAX_RINGS, "deeper neighbourhoods are not derived (their matrices grow like K^2 n)"),
    "budget": (86400, "seconds for one claim's check: a day is more than any check needs"),
    "report": (MAX_REPORT_VALENCE, "a report's tables grow with every valence (2N + 1 eigenvalues and mask weights) and its "
               "eigen-polygon figure has N panels a row; 3:8 takes about half a minute"),
    "evaldata --k": (64, "a sharp vertex has at most 64 faces; k = 64 writes about 10 MB of exact rationals"),
    "evaldata": (1000, "the file grows like N^3 (N = 128: 32 MB) and each valence costs ~N^2 Arb operations at 256 bits "
                 "(a run's memory is estimated and checked before it starts)"),
    "--executor dask=ADDRESS: seconds of each exchange": (EXCHANGE_SECONDS, "to connect, to greet, to find a worker, "
                                                          "between signs of life: a peer that stays silent is not waited for"),
    "--executor dask=ADDRESS: bytes of the greeting": (GREETING_LIMIT, "a scheduler's greeting takes about 60 bytes; a "
                                                       "larger length read from a peer is no Dask scheduler's"),
    "--out FIFO: seconds to wait for its reader": (FIFO_WAIT, "an output FIFO is opened when it is checked, before the "
                                                   "work: without a reader by then, the run would block after it"),
    **API_LIMITS,
    **INPUT_LIMITS,
}

#: Where a help text sends a reader for the scheme file format (one page of the docs, from the one docstring).
SCHEME_FORMAT = "(the format: docs/formats/scheme-files.rst, the docs' page 'Scheme files'; the docstring of symdecomp.schemes.files)"

_INTEGER = re.compile(r"[+-]?[0-9]{1,12}", re.ASCII)
_DIGITS = re.compile(r"[+-]?[0-9]+", re.ASCII)


#: How every error line of the command line starts, whichever command and whatever went wrong: a usage error
#: found by the parser and an error raised while a command runs look alike (the parser's line names the
#: command in its ``(see 'symdecomp CMD --help')``).
ERROR_PREFIX = "symdecomp: error: "


def error_line(message: object) -> str:
    """The one line (no newline) that reports ``message`` as an error: :data:`ERROR_PREFIX`, then the message
    with every run of whitespace (newlines too) made one space.

    >>> error_line("--n 2:\\n  below the smallest valence 3")
    'symdecomp: error: --n 2: below the smallest valence 3'
    """
    return ERROR_PREFIX + " ".join(str(message).split())


class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line (:func:`error_line`, naming the command's ``--help``) and exit code 2."""

    def error(self, message: str):  # noqa: D401 - argparse's hook
        self.exit(2, error_line(f"{message} (see '{self.prog} --help')") + "\n")


class Once(argparse.Action):
    """Store an option's value, refusing a second occurrence (``--n 3 --n 4`` is an error)."""

    def __init__(self, option_strings, dest, nargs=None, const=None, **kwargs):
        self._flag = nargs == 0
        if self._flag:
            kwargs.setdefault("default", False)
        super().__init__(option_strings, dest, nargs=nargs, const=True if self._flag else const, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        seen = namespace.__dict__.setdefault("_given", set())
        if self.dest in seen:
            raise argparse.ArgumentError(self, "given more than once")
        seen.add(self.dest)
        setattr(namespace, self.dest, self.const if self._flag else values)


def flag(parser, *names, **kwargs):
    """A boolean ``--flag`` that may be given once."""
    return parser.add_argument(*names, action=Once, nargs=0, **kwargs)


def given(args, dest: str) -> bool:
    """Whether the user gave the option stored in ``dest`` (as opposed to its default)."""
    return dest in getattr(args, "_given", set())


#: The options that name a boundary, crease, corner or dart vertex (:mod:`symdecomp.cli.element`), by destination.
SHARP_OPTIONS = {"boundary": "--boundary", "corner": "--corner", "crease": "--crease", "dart": "--dart"}


def sharp_given(args) -> bool:
    """Whether the command line names a boundary, crease, corner or dart vertex (then ``N`` is a face count)."""
    return any(given(args, dest) for dest in SHARP_OPTIONS)


def refuse_together(args, first: str, second: str, why: str) -> None:
    """Refuse two options given together (contradictory, or one would be ignored)."""
    if given(args, first.lstrip("-").replace("-", "_")) and given(args, second.lstrip("-").replace("-", "_")):
        raise InvalidInputError(f"{first} and {second} cannot be used together: {why}")


def integer(text: str, name: str, *, minimum: int | None = None, limit: str | None = None, noun: str = "an integer") -> int:
    """Parse strict ASCII integer text for the option ``name``, within ``minimum`` and ``LIMITS[limit]``.

    The messages leave the option's name to argparse (which prefixes ``argument NAME:``).
    """
    maximum, reason = LIMITS[limit] if limit else (None, "")
    bounds = " and ".join(part for part in (f">= {minimum}" if minimum is not None else "",
                                             f"<= {maximum}" if maximum is not None else "") if part)
    expected = f"{noun}{' ' + bounds if bounds else ''}"
    shown = text if len(text) <= 40 else text[:37] + "..."
    if not _DIGITS.fullmatch(text):
        raise argparse.ArgumentTypeError(f"expected {expected} written with the digits 0-9, got {shown!r}")
    if not _INTEGER.fullmatch(text):
        raise argparse.ArgumentTypeError(f"expected {expected}, got {shown!r}, which has too many digits"
                                         + (f" ({reason})" if reason else ""))
    value = int(text)
    if minimum is not None and value < minimum:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {value}")
    if maximum is not None and value > maximum:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {value} ({reason})")
    return value


def valence(limit: str):
    """argparse type: an integer valence ``3 <= N <= LIMITS[limit]``."""

    def parse(text: str) -> int:
        return integer(text, "N", minimum=3, limit=limit, noun="a valence: an integer")

    parse.__name__ = "valence"
    return parse


def face_range(option: str, limit: str):
    """argparse type: ``K`` or an inclusive range ``A:B`` of a sector's faces, ``1 <= A <= B <= LIMITS[limit]``."""

    def parse(text: str) -> list[int]:
        parts = text.split(":")
        if len(parts) > 2:
            raise argparse.ArgumentTypeError(f"expected K or A:B, got {text[:40]!r}")
        a, b = (integer(x, option, minimum=1, limit=limit) for x in (parts[0], parts[-1]))
        if b < a:
            raise argparse.ArgumentTypeError(f"empty range {text!r}: {b} < {a}")
        return list(range(a, b + 1))

    return parse


def valence_range(limit: str):
    """argparse type: ``N`` or an inclusive range ``A:B`` of valences, ``3 <= A <= B <= LIMITS[limit]``."""
    one = valence(limit)

    def parse(text: str) -> list[int]:
        if text.count(":") > 1:
            raise argparse.ArgumentTypeError(f"expected N or A:B, got {text!r}")
        if ":" in text:
            lo, _, hi = text.partition(":")
            a, b = one(lo), one(hi)
            if b < a:
                raise argparse.ArgumentTypeError(f"empty valence range {text!r}: {b} < {a}")
            return list(range(a, b + 1))
        return [one(text)]

    parse.__name__ = "valence range"
    return parse


def positive_int(name: str, limit: str | None = None):
    """argparse type: an integer ``>= 1`` (and ``<= LIMITS[limit]``)."""

    def parse(text: str) -> int:
        return integer(text, name, minimum=1, limit=limit)

    parse.__name__ = "positive integer"
    return parse


def digits(name: str = "--digits", *, minimum: int = 1, limit: str = "digits"):
    """argparse type: digits of a printed value or of working precision, bounded."""

    def parse(text: str) -> int:
        return integer(text, name, minimum=minimum, limit=limit)

    parse.__name__ = "digits"
    return parse


def add_budget_option(parser: argparse.ArgumentParser) -> None:
    """``--budget SECONDS``: the wall-clock time one claim's check may take before it is reported undecided."""
    parser.add_argument("--budget", type=positive_int("--budget", "budget"), action=Once, default=int(DEFAULT_BUDGET),
                        metavar="SECONDS", help=f"seconds one claim's check may take; a check still running then is reported "
                        f"undecided, saying so (default {int(DEFAULT_BUDGET)})")


#: The commands that analyse a scheme of the zoo (a StencilScheme), through its engine.
ZOO_COMMANDS = ("spectrum", "masks", "check --certify", "c1", "artifacts", "report", "evaldata")


def any_scheme_by_name(name: str):
    """argparse type: a scheme by name (today's ``SCHEMES`` or the zoo's families) or a TOML scheme file of either
    format; a bad file is one line naming the key."""
    try:
        return load_scheme(name)
    except SymdecompError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def scheme_by_name(name: str) -> Scheme:
    """argparse type of the commands that take only 1-ring primal schemes: a zoo scheme is refused in one line."""
    scheme = any_scheme_by_name(name)
    if not isinstance(scheme, Scheme):  # a zoo scheme (StencilScheme)
        raise argparse.ArgumentTypeError(f"{name}: a scheme of the zoo ({scheme.topology} topology, {scheme.lattice} lattice); "
                                         f"this command takes 1-ring primal schemes; the zoo's are analysed by "
                                         f"{', '.join(ZOO_COMMANDS)}")
    return scheme


def add_scheme_option(parser: argparse.ArgumentParser, *, zoo: bool = False) -> None:
    """``--scheme NAME|FILE``; with ``zoo``, the command also takes the zoo's schemes (its engine answers)."""
    names = ", ".join(SCHEMES) + (", " + ", ".join(_zoo_names()) if zoo else "")
    parser.add_argument(
        "--scheme",
        type=any_scheme_by_name if zoo else scheme_by_name,
        action=Once,
        default="catmull-clark",  # text: argparse builds the scheme (type) only when a command runs, not for --help
        metavar="NAME|FILE",
        help=f"subdivision scheme: a known name ({names}; default catmull-clark) or a TOML scheme file "
        f"{SCHEME_FORMAT}",
    )


def _zoo_names() -> tuple[str, ...]:
    """The zoo's shipped families, read from the package's folder of them (``--help`` imports no sympy)."""
    from importlib import resources

    folder = resources.files("symdecomp.schemes").joinpath("zoo")
    return tuple(sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml")))


def _rings(text: str) -> int:
    return integer(text, "--rings", minimum=1, limit="rings")


def add_rings_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--rings", type=_rings, action=Once, default=1, metavar="K",
        help=f"the K-ring neighbourhood of the centre (1..{MAX_RINGS}; default 1: the paper's 1-ring), "
        "its matrix built by exact refinement with the scheme's mesh rules",
    )


def _executor(text: str):
    try:
        return parse_executor(text, option=None)
    except InvalidInputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def add_pool_options(parser: argparse.ArgumentParser, *, default_jobs: int | None = None, items: str = "valences") -> None:
    """``--jobs N`` and ``--executor local|dask|dask=ADDRESS``: where the ``items`` (valences, claims) are computed
    (:mod:`symdecomp.parallel`)."""
    jobs = default_jobs or os.cpu_count() or 1
    parser.add_argument("--jobs", type=positive_int("--jobs", "jobs"), action=Once, default=jobs,
                        help=f"worker processes at most (default {'the number of CPUs' if default_jobs is None else jobs}; "
                        f"the local pool and a Dask LocalCluster never have more than the {items} or the CPUs)")
    parser.add_argument("--executor", type=_executor, action=Once, default=parse_executor("local"),
                        metavar="local|dask|dask=ADDRESS",
                        help="local: a pool of forked processes (default); dask: a Dask LocalCluster of --jobs workers "
                        "started for the run; dask=ADDRESS: the Dask scheduler at ADDRESS, e.g. tcp://127.0.0.1:8786, "
                        "whose workers have symdecomp installed (needs pip install 'symdecomp[dask]')")


def closed_form_obstacle(scheme: Scheme) -> str | None:
    """:func:`symdecomp.claims.applicability.closed_form_obstacle`, imported when a command runs (not for ``--help``)."""
    from symdecomp.claims.applicability import closed_form_obstacle

    return closed_form_obstacle(scheme)


def is_stencil_scheme(scheme) -> bool:
    """Whether ``scheme`` is a scheme of the zoo (a StencilScheme): its engine answers (the commands' routes, :mod:`symdecomp.cli.element`)."""
    from symdecomp.schemes.stencils import StencilScheme

    return isinstance(scheme, StencilScheme)


def general_path(args) -> bool:
    """Whether a command takes the any-scheme route (triangle meshes or ``--rings`` > 1)."""
    return not args.scheme.lattice.paper_claims or getattr(args, "rings", 1) != 1


def refuse_non_quad(scheme: Scheme, command: str) -> None:
    """One line for a command about the paper's claims given a scheme on triangle meshes."""
    if not scheme.lattice.paper_claims:
        raise InvalidInputError(
            f"--scheme {scheme.name}: {command} works on the paper's claims, statements about quad meshes; "
            f"a {scheme.lattice}-mesh "
            "scheme is analysed by spectrum, check, charpoly, masks, oracle, c1 and evaldata"
        )


def check_scheme_valences(args) -> None:
    """Refuse, before a command starts, a valence of the command at which its scheme cannot be evaluated.

    The one check every command reaches (``main`` calls it): at each valence the command uses (``N``, ``--n A:B``)
    the stencils must fit and every weight must be defined and real
    (:meth:`~symdecomp.schemes.scheme.Scheme.fitting_valence`); the error names the valence and the weight.
    """
    from symdecomp.cli.element import check_sharp_options  # the sharp options' own checks (imported late: it imports this)

    scheme = getattr(args, "scheme", None)
    valences = getattr(args, "valences", None) or getattr(args, "n", None)
    check_sharp_options(args)
    if not isinstance(scheme, Scheme) or valences is None or sharp_given(args):
        return  # a sharp vertex's N is a face count: its matrix's rules are checked where it is built
    if isinstance(valences, int) and valences < 3:  # N admits face counts from 1 for sharp vertices
        bound = LIMITS.get(getattr(args, "command", ""), (None,))[0]
        raise InvalidInputError(f"argument N: expected a valence: an integer >= 3{f' and <= {bound}' if bound else ''}, got "
                                f"{valences} (face counts 1 and 2 are for --boundary, --corner, --crease or --dart)")
    for n in valences if isinstance(valences, list) else [valences]:
        scheme.fitting_valence(n, real=True)


def estimate_seconds(seconds: float, limit: str, what: str, *, show: float = 10.0) -> None:
    """Refuse work estimated to take more than ``LIMITS[limit]`` seconds of CPU, before it starts; say the estimate on
    stderr when it is more than ``show`` seconds (long runs announce themselves)."""
    bound, why = LIMITS[limit]
    if seconds > bound:
        raise InvalidInputError(f"{what}: estimated {_duration(seconds)} of CPU, more than the limit of {_duration(bound)} "
                                f"({why})")
    if seconds > show:
        print(f"{what}: estimated {_duration(seconds)} of CPU", file=sys.stderr, flush=True)


def _duration(seconds: float) -> str:
    return f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.0f} minutes" if seconds < 7200 else \
        f"{seconds / 3600:.0f} hours"
