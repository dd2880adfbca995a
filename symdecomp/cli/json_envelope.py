"""One shape for every command's ``--json``: an object naming the command, its inputs and the version.

Every command prints its JSON through :func:`print_json`, which wraps the command's results in
:func:`envelope`::

    {"command": "c1", "inputs": {"valences": [3, 4], "scheme": "catmull-clark", ...},
     "version": "0.1.0", "rows": [...]}

A command whose result is a list (one object per valence, claim, case) puts it under ``"rows"``; a
command whose result is an object puts its named results beside the three keys (``"rows"`` and
``"summary"`` of ``check``, ``"eigenvalues"`` of ``spectrum``, ...). ``"inputs"`` holds every
argument of the command after parsing, defaults included, each as JSON: a scheme by its name, a
path as text, an infinite sharpness as ``"inf"``. The shape is described by a JSON Schema shipped
with the package (:func:`json_schema`; the format page ``docs/formats/json.md``), and
``tests/cli/test_json_envelope.py`` validates every command's output against it.
"""

from __future__ import annotations

import json
import math
import os
import sys
from importlib import resources

from symdecomp.errors import InternalError

__all__ = ["ENVELOPE_KEYS", "envelope", "json_inputs", "json_schema", "print_json"]

#: The keys every command's ``--json`` object starts with.
ENVELOPE_KEYS = ("command", "inputs", "version")

#: Parsed arguments that are the parser's bookkeeping, not the command's inputs (with every name starting with ``_``,
#: such as the marker a parser sets for the sharp options it has).
_NOT_INPUTS = {"func", "command", "json"}


def _as_json(value):
    """One parsed argument as JSON: numbers, text, booleans and lists as they are; a scheme by name; the rest as text."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else str(value)
    if isinstance(value, (list, tuple)):
        return [_as_json(v) for v in value]
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    name = getattr(value, "name", None)
    if isinstance(name, str) and hasattr(value, "lattice"):  # a Scheme: its name, as --scheme takes it
        return name
    return str(value)


def json_inputs(args) -> dict:
    """The command's inputs: every parsed argument (defaults included) as JSON, in the parser's order."""
    return {key: _as_json(value) for key, value in vars(args).items() if key not in _NOT_INPUTS and not key.startswith("_")}


def envelope(command: str, inputs: dict, results) -> dict:
    """``results`` (an object of named results, or a list of rows) in the one ``--json`` shape."""
    from symdecomp import __version__

    head = {"command": command, "inputs": inputs, "version": __version__}
    if isinstance(results, (list, tuple)):
        return {**head, "rows": list(results)}
    if not isinstance(results, dict):
        raise InternalError(f"{command} --json: results must be an object or a list, got {type(results).__name__}")
    clash = [key for key in ENVELOPE_KEYS if key in results]
    if clash:
        raise InternalError(f"{command} --json: the result key {clash[0]!r} is one of the envelope's")
    return {**head, **results}


#: A top-level list longer than this is printed one row per line: the indenting encoder is pure Python (seconds for the
#: 25,000 vertices of a scanned mesh), one compact row at a time is native.
ROWS_PER_LINE = 1000


def print_json(args, results) -> None:
    """Print ``results`` of the command run with ``args`` on stdout in the one ``--json`` shape (:func:`envelope`)."""
    data = envelope(args.command, json_inputs(args), results)
    long = {key: value for key, value in data.items() if isinstance(value, list) and len(value) > ROWS_PER_LINE}
    text = json.dumps({key: f"\0{key}" if key in long else value for key, value in data.items()}, indent=2)
    for key, rows in long.items():
        text = text.replace(json.dumps(f"\0{key}"), "[\n" + ",\n".join("    " + json.dumps(r) for r in rows) + "\n  ]", 1)
    sys.stdout.write(text + "\n")


def json_schema() -> dict:
    """The JSON Schema of every command's ``--json`` output (``symdecomp/output/json_schema.json``, shipped with the package)."""
    return json.loads(resources.files("symdecomp.output").joinpath("json_schema.json").read_text(encoding="utf-8"))
