"""The ``symdecomp`` command line. One module per subcommand, each with ``register(sub)``.

Exit codes (also in ``symdecomp --help`` and the user guide, docs/guide/command-line.md):

===  =====================================================================================
0    success
1    a check disagrees or could not reach a verdict (or an internal error, or an output that could not
     be written after its path was checked: a full disk, an I/O error; reported in one line)
2    bad input: the message names the argument and the problem
3    an optional component is missing (the OpenSubdiv bridge); the message says how to get it
130  interrupted (Ctrl-C or SIGTERM), within seconds even inside a native computation; worker
     processes are stopped with the command
===  =====================================================================================

No traceback is ever printed: every error is one line on stderr.

Adding a command: a module ``NAME_cmd.py`` here, named in :data:`COMMANDS` (in ``--help`` order)
and in the module map, with ``register(sub)`` (its parser, ``set_defaults(func=run)``) and
``run(args)`` (the exit code). Start-up stays cheap, so that ``symdecomp --help``, ``--version``
and ``symdecomp CMD --help`` cost little beyond importing sympy, mpmath and FLINT
(``benchmarks/bench_startup.py``): every parser is built for every run, so at module level and in
``register`` a command module imports only the standard library, :mod:`symdecomp.cli.common`
(argument types, scheme and pool options), :mod:`symdecomp.cli.files`, the errors, the limits of
:mod:`symdecomp.validate`, and schemes and symbols; what it computes with (the analysis, verify,
claims and output layers) it imports inside ``run`` and its helpers. A number its help text
prints (a default, a limit) lives in :mod:`symdecomp.validate` or :data:`~symdecomp.cli.common.LIMITS`.
``tests/cli/test_lazy_commands.py`` checks every ``*_cmd.py`` it finds, and that :data:`COMMANDS`
names them all.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from __future__ import annotations

import errno
import importlib
import os
import signal
import sys

from symdecomp.cli.common import LIMITS, Parser, check_scheme_valences, error_line
from symdecomp.cli.files import release_held
from symdecomp.errors import InternalError, OutputWriteError, ResourceLimitError, SymdecompError, UnavailableError

__all__ = ["main", "entry", "build_parser", "EXIT_CODES"]

#: Subcommand modules of this package, in the order ``--help`` lists them.
COMMANDS = ("claims_cmd", "derive_cmd", "spectrum_cmd", "charpoly_cmd", "oracle_cmd", "tune_cmd", "masks_cmd", "check_cmd", "c1_cmd",
            "artifacts_cmd", "evaldata_cmd", "inspect_cmd", "refine_cmd", "design_cmd", "report_cmd")

#: The exit codes of every command.
EXIT_CODES = {
    0: "success",
    1: "a check disagrees or could not reach a verdict (or an output could not be written: disk full, I/O error)",
    2: "bad input (the message names the argument)",
    3: "an optional component is missing (the message says how to get it)",
    130: "interrupted (Ctrl-C or SIGTERM)",
}


# Control flow, not an error of the package: a BaseException like KeyboardInterrupt so that no
# `except Exception` swallows it; main() turns it into exit code 130.
class Interrupted(BaseException):
    """Raised in the main process by SIGTERM, so that cleanup runs as for Ctrl-C."""


def _epilog() -> str:
    codes = "; ".join(f"{code} {text}" for code, text in EXIT_CODES.items())
    limits = "; ".join(f"{name} <= {bound} ({why})" for name, (bound, why) in LIMITS.items())
    return f"exit codes: {codes}. limits: {limits}."


def build_parser() -> Parser:
    from symdecomp import __version__

    parser = Parser(
        prog="symdecomp",
        description="Exact, symbolic eigenanalysis of subdivision surfaces through polygonal decompositions "
        "(Ivrissimtzis, Zayer, Seidel: Polygonal decompositions of quadrilateral subdivision meshes).",
        epilog=_epilog(),
    )
    parser.add_argument("--version", action="version", version=f"symdecomp {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    sub.required = True
    for name in COMMANDS:
        importlib.import_module(f"{__name__}.{name}").register(sub)
    return parser


def _fail(message: object, code: int) -> int:
    """Print ``message`` as the one error line of every command (:func:`~symdecomp.cli.common.error_line`); return ``code``."""
    print(error_line(message), file=sys.stderr)
    return code


def _on_sigterm(signum, frame):
    raise Interrupted


#: Seconds after which an interruption that a finalizer swallowed is raised again.
REDELIVERY_SECONDS = 0.01


def _redeliver(unraisable) -> None:
    """``sys.unraisablehook`` while a command runs: an interruption raised inside a finalizer (a ``__del__``, a
    weakref callback, a generator's close) cannot propagate: Python prints "Exception ignored ... Traceback" and the
    command goes on until it is killed. Instead it is raised again, a moment later, from another thread
    (``_thread.interrupt_main``: the main thread's handler, outside the finalizer by then). Other exceptions are
    printed as before."""
    if isinstance(unraisable.exc_value, (Interrupted, KeyboardInterrupt)):
        import _thread
        import threading

        signum = signal.SIGTERM if isinstance(unraisable.exc_value, Interrupted) else signal.SIGINT
        timer = threading.Timer(REDELIVERY_SECONDS, _thread.interrupt_main, (signum,))
        timer.daemon = True
        timer.start()
        return
    sys.__unraisablehook__(unraisable)


def _silence_stdout() -> None:
    """Point stdout at /dev/null so that the interpreter's final flush cannot fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass


def entry() -> None:
    """The ``symdecomp`` program: :func:`main` in a child process that SIGTERM or Ctrl-C can always
    stop, within :data:`~symdecomp.parallel.GRACE_SECONDS`, even inside a native computation
    (:func:`~symdecomp.parallel.run_killable`)."""
    from symdecomp.parallel import run_killable

    sys.exit(run_killable(main))


def main(argv=None) -> int:
    """Run the command line; return the exit code (never raises, never prints a traceback)."""
    try:
        parser = build_parser()
        try:
            args = parser.parse_args(argv)
        except SystemExit as exc:  # --help, --version, or a usage error (already printed, one line)
            return exc.code if isinstance(exc.code, int) else 2
        previous, hook = _install(signal.SIGTERM, _on_sigterm), sys.unraisablehook
        sys.unraisablehook = _redeliver
        try:
            check_scheme_valences(args)
            code = int(args.func(args) or 0)
            sys.stdout.flush()
            return code
        finally:
            _install(signal.SIGTERM, previous)
            sys.unraisablehook = hook
            release_held()  # FIFOs checked and not written: their readers see the end
    except UnavailableError as exc:
        return _fail(exc, 3)
    except InternalError as exc:
        return _fail(f"internal error (please report): {exc}", 1)
    except OutputWriteError as exc:  # the path was fine (checked first); the write failed: not bad input
        return _fail(exc, 1)
    except ResourceLimitError as exc:
        return _fail(exc, 2)
    except SymdecompError as exc:
        return _fail(exc, 2)
    except (KeyboardInterrupt, Interrupted):
        print("symdecomp: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into e.g. `head`: stop quietly
        _silence_stdout()
        return 0
    except MemoryError:
        return _fail("out of memory; try a smaller valence or range", 1)
    except OSError as exc:
        if exc.errno in (errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EBADF):
            _silence_stdout()
            return _fail(f"cannot write the output: {exc.strerror or exc}", 1)
        return _fail(f"{exc.strerror or exc}" + (f": {exc.filename}" if exc.filename else ""), 1)
    except RecursionError:
        return _fail("an expression is nested too deeply", 2)
    except Exception as exc:  # noqa: BLE001 - the last line of defence against a traceback
        return _fail(f"internal error (please report): {type(exc).__name__}: {exc}", 1)


def _install(signum, handler):
    """Set a signal handler; return the previous one (None where it cannot be set: not the main thread)."""
    if handler is None:
        return None
    try:
        return signal.signal(signum, handler)
    except ValueError:
        return None
