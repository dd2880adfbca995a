"""Helpers shared by the subcommands: argument types, scheme lookup, progress, JSON output."""

from __future__ import annotations

import argparse
import json
import sys

from symdecomp.errors import InvalidValenceError, check_valence
from symdecomp.schemes.loop import loop, loop_warren
from symdecomp.schemes.rings import MAX_RINGS
from symdecomp.schemes.scheme import Scheme, catmull_clark

__all__ = [
    "valence", "valence_range", "positive_int", "SCHEMES", "scheme_by_name", "add_scheme_option", "add_rings_option",
    "general_path", "progress", "print_json",
]

#: Schemes selectable by name on the command line.
SCHEMES = {"catmull-clark": catmull_clark, "loop": loop, "loop-warren": loop_warren}


def scheme_by_name(name: str) -> Scheme:
    try:
        return SCHEMES[name]()
    except KeyError:
        raise argparse.ArgumentTypeError(f"unknown scheme {name!r}; known: {', '.join(SCHEMES)}") from None


def add_scheme_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--scheme",
        type=scheme_by_name,
        default="catmull-clark",
        help=f"subdivision scheme (default: catmull-clark; known: {', '.join(SCHEMES)})",
    )


def _rings(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--rings must be an integer from 1 to {MAX_RINGS}, got {text!r}") from None
    if not 1 <= value <= MAX_RINGS:
        raise argparse.ArgumentTypeError(f"--rings must be an integer from 1 to {MAX_RINGS}, got {value}")
    return value


def add_rings_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--rings", type=_rings, default=1, metavar="K",
        help=f"the K-ring neighbourhood of the centre (1..{MAX_RINGS}; default 1: the paper's 1-ring), "
        "its matrix built by exact refinement with the scheme's mesh rules",
    )


def general_path(args) -> bool:
    """Whether a command takes the any-scheme route (triangle meshes or ``--rings`` > 1)."""
    return args.scheme.mesh != "quad" or getattr(args, "rings", 1) != 1


def valence(text: str) -> int:
    """argparse type: an integer valence >= 3."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"valence must be an integer >= 3, got {text!r}") from None
    try:
        return check_valence(value)
    except InvalidValenceError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def valence_range(text: str) -> list[int]:
    """argparse type: ``N`` or an inclusive range ``A:B`` of valences."""
    if ":" in text:
        lo, _, hi = text.partition(":")
        a, b = valence(lo), valence(hi)
        if b < a:
            raise argparse.ArgumentTypeError(f"empty valence range {text!r}: {b} < {a}")
        return list(range(a, b + 1))
    return [valence(text)]


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {value}")
    return value


def progress(iterable, total: int, label: str, *, enabled: bool = True):
    """Yield from ``iterable`` while drawing a progress bar on stderr (when it is a terminal or forced)."""
    show = enabled and total > 1
    for done, item in enumerate(iterable, 1):
        yield item
        if show:
            width = 30
            filled = int(width * done / total)
            sys.stderr.write(f"\r{label} [{'#' * filled}{'.' * (width - filled)}] {done}/{total}")
            sys.stderr.flush()
    if show:
        sys.stderr.write("\n")


def print_json(obj) -> None:
    json.dump(obj, sys.stdout, indent=2, sort_keys=False)
    sys.stdout.write("\n")
