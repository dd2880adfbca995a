"""The ``symdecomp`` command line. One module per subcommand, each with ``register(sub)``."""

from __future__ import annotations

import argparse
import importlib
import sys

from symdecomp.errors import SymdecompError

__all__ = ["main", "build_parser"]

#: Subcommand modules of this package, in the order ``--help`` lists them.
COMMANDS = ("claims_cmd", "derive_cmd", "spectrum_cmd", "charpoly_cmd", "oracle_cmd", "tune_cmd", "masks_cmd", "check_cmd", "evaldata_cmd")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="symdecomp",
        description="Exact, symbolic eigenanalysis of subdivision surfaces through polygonal decompositions "
        "(Ivrissimtzis, Zayer, Seidel: Polygonal decompositions of quadrilateral subdivision meshes).",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in COMMANDS:
        importlib.import_module(f"{__name__}.{name}").register(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except SymdecompError as exc:
        print(f"symdecomp: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # pragma: no cover
        return 130
    except BrokenPipeError:  # output piped into e.g. `head`: stop quietly
        import os

        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0
