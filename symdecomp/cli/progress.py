"""The one progress display of the command line's long runs: a bar with rate and time left on a terminal
(tqdm), a plain line every :data:`PLAIN_INTERVAL` seconds otherwise (a log file, a pipe, a CI job).

A call site wraps the loop over its work and nothing else::

    for n in progress(valences, len(valences), "c1", enabled=not args.quiet):
        ...

The display goes to stderr, so that ``--json`` and the text results on stdout stay clean. A run shorter
than :data:`PLAIN_INTERVAL` prints no plain line at all; a longer one prints what is done, the rate and
the time left, and a last line when it ends. :func:`add_quiet_option` gives a command ``--quiet``.
"""

from __future__ import annotations

import re
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from typing import TypeVar

__all__ = ["PLAIN_INTERVAL", "PLAIN_LINE", "add_quiet_option", "progress", "plain_line"]

T = TypeVar("T")

#: Seconds between two plain progress lines when stderr is not a terminal.
PLAIN_INTERVAL = 10.0

#: What a plain progress line looks like (:func:`plain_line`): a program reading stderr can tell it from an error.
PLAIN_LINE = re.compile(r"[^:\n]+: [0-9]+/[0-9]+ \([0-9]+ %\), [0-9.]+ \S+/s, [0-9:]+ elapsed(, about [0-9:]+ left)?")


def add_quiet_option(parser) -> None:
    """``--quiet``: no progress display on stderr (errors are still printed)."""
    from symdecomp.cli.common import flag

    flag(parser, "--quiet", help="draw no progress on stderr (on a terminal a bar with rate and time left, otherwise a "
         f"line every {PLAIN_INTERVAL:g} s of a long run)")


def progress(iterable: Iterable[T], total: int, label: str, *, enabled: bool = True, unit: str = "it", stream=None,
             clock: Callable[[], float] = time.monotonic) -> Iterator[T]:
    """Yield from ``iterable`` (``total`` items), showing the progress on ``stream`` (default stderr) unless not ``enabled``.

    On a terminal: a tqdm bar with the count, the rate and the time left. Otherwise: :func:`plain_line` each
    :data:`PLAIN_INTERVAL` seconds (by ``clock``), and a last line if any was printed.
    """
    stream = sys.stderr if stream is None else stream
    if not enabled or total < 1:
        yield from iterable
    elif _is_terminal(stream):
        from tqdm import tqdm

        with tqdm(iterable, total=total, desc=label, unit=unit, file=stream, dynamic_ncols=True, mininterval=0.5) as bar:
            yield from bar
    else:
        yield from _plain(iterable, total, label, unit, stream, clock)


def _plain(iterable, total, label, unit, stream, clock):
    start = last = clock()
    done = 0
    for item in iterable:
        yield item
        done += 1
        now = clock()
        if now - last >= PLAIN_INTERVAL and done < total:
            stream.write(plain_line(label, done, total, now - start, unit) + "\n")
            stream.flush()
            last = now
    if last != start:
        stream.write(plain_line(label, done, total, clock() - start, unit) + "\n")
        stream.flush()


def plain_line(label: str, done: int, total: int, elapsed: float, unit: str = "it") -> str:
    """One line of progress: ``c1: 12/40 (30 %), 0.50 it/s, 00:24 elapsed, about 00:56 left``."""
    from tqdm import tqdm

    rate = done / elapsed if elapsed > 0 else 0.0
    left = f", about {tqdm.format_interval((total - done) / rate)} left" if rate > 0 and done < total else ""
    return (f"{label}: {done}/{total} ({100 * done // total} %), {rate:.2f} {unit}/s, "
            f"{tqdm.format_interval(elapsed)} elapsed{left}")


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False
