"""Sphinx extension: the guide pages' pictures, drawn by the commands themselves when the site is built.

:data:`FIGURES` lists ``(command line, image)`` pairs. When the build starts, each command runs as a user
would run it (``python -m symdecomp ...`` from the repository's root, matplotlib's Agg backend) and its
image is written into ``docs/_generated/figures/`` (generated, ignored by git); the directive
``symdecomp-figure NAME`` shows it on its guide page. The pictures are those of the current code, and a
command that fails fails the build.

A command that cannot draw yet (its parser has no ``--plot``) is skipped with one build-time line saying
so, and its page says where the picture will appear: the figure turns on by itself once the option exists.

Deterministic: fixed inputs, PNG with matplotlib's fixed metadata; a picture is drawn again only when its
command line, an input file or the package's source changed (a digest beside it, ``NAME.png.key``).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: Where the pictures are written, relative to the documentation's source folder.
FIGURE_DIR = "_generated/figures"


@dataclass(frozen=True)
class Figure:
    """One guide picture: a command line and the image it draws."""

    #: The picture's name: ``NAME.png`` in :data:`FIGURE_DIR`, the argument of ``symdecomp-figure``.
    name: str
    #: The arguments after ``symdecomp``; ``{out}`` is the image file, ``{dir}`` a folder (it exists) for commands that write several.
    argv: tuple[str, ...]
    #: With ``{dir}``: the file of that folder to show.
    pick: str = ""
    #: What the picture shows (the caption).
    caption: str = ""

    @property
    def command(self) -> str:
        return self.argv[0]

    def inputs(self) -> list[Path]:
        """The repository's files the command reads (their bytes enter the digest)."""
        return [ROOT / a for a in self.argv if "/" in a and (ROOT / a).is_file()]


#: The pictures of the guide, by page (each drawn by its command's ``--plot``, or ``--figures``).
FIGURES = (
    Figure("inspect-vertex", ("inspect", "notebooks/data/valences-3-5-6.obj", "--figures", "{dir}"), pick="vertex-11.png",
           caption="symdecomp inspect notebooks/data/valences-3-5-6.obj --figures DIR: vertex 11 (valence 5), its 1-ring, "
           "limit point, normal and tangents"),
    Figure("real-mesh", ("inspect", "notebooks/data/catmark_pawn.obj", "--color-by", "kind", "--plot", "{out}"),
           caption="symdecomp inspect notebooks/data/catmark_pawn.obj --color-by kind --plot FILE: OpenSubdiv's pawn, "
           "each vertex coloured by its kind of neighbourhood"),
    Figure("tune-region", ("tune", "5", "--region", "--scheme", "tests/corpus/free-vertex.toml", "--plot", "{out}"),
           caption="symdecomp tune 5 --region --scheme tests/corpus/free-vertex.toml --plot FILE: the vertex weights by "
           "curvature regime, the published weights placed in it"),
    Figure("c1", ("c1", "--n", "5", "--plot", "{out}"),
           caption="symdecomp c1 --n 5 --plot FILE: the characteristic map and its Jacobian"),
    Figure("spectrum", ("spectrum", "5", "--plot", "{out}"),
           caption="symdecomp spectrum 5 --plot FILE: the eigenvalues by frequency"),
    Figure("artifacts", ("artifacts", "--n", "3:8", "--plot", "{out}"),
           caption="symdecomp artifacts --n 3:8 --plot FILE: the curvature regime over the valence"),
    Figure("check", ("check", "--n", "3:16", "--plot", "{out}"),
           caption="symdecomp check --n 3:16 --plot FILE: the closed forms against the full matrix"),
    Figure("refine", ("refine", "notebooks/data/valences-3-5-6.obj", "--steps", "2", "--out", "{dir}/refined.obj", "--plot", "{out}"),
           caption="symdecomp refine notebooks/data/valences-3-5-6.obj --steps 2 --out refined.obj --plot FILE: the refined "
           "mesh over its control mesh"),
    Figure("design", ("design", "--n", "5", "--normal", "1,1,2", "--elliptic", "1/2", "--out", "{dir}/ring.obj", "--plot", "{out}"),
           caption="symdecomp design --n 5 --normal 1,1,2 --elliptic 1/2 --out ring.obj --plot FILE: the 2-ring it writes, "
           "its limit point, normal and tangent directions"),
    Figure("masks", ("masks", "5", "--plot", "{out}"),
           caption="symdecomp masks 5 --plot FILE: the limit position and tangent masks on the 1-ring"),
    Figure("charpoly", ("charpoly", "5", "--plot", "{out}"),
           caption="symdecomp charpoly 5 --plot FILE: the roots of the characteristic polynomial"),
)


def missing_options(figure: Figure) -> list[str]:
    """The options of the figure's command line that its command does not have yet (``--plot`` arrives command by command)."""
    import argparse

    from symdecomp.cli import build_parser

    (action,) = [a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)]
    options = {o for a in action.choices[figure.command]._actions for o in a.option_strings}
    return [a for a in figure.argv if a.startswith("--") and a not in options]


def _digest(figure: Figure) -> str:
    h = hashlib.sha256(repr(figure.argv).encode())
    for path in sorted((ROOT / "symdecomp").rglob("*")) + figure.inputs():
        if path.is_file() and "_build" not in path.parts and "__pycache__" not in path.parts:
            h.update(path.relative_to(ROOT).as_posix().encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


def draw(figure: Figure, target: Path) -> Path:
    """Run the figure's command and put its image at ``target/NAME.png``; return that path.

    Raises ``RuntimeError`` with the command's error line when it fails."""
    out = target / f"{figure.name}.png"
    with tempfile.TemporaryDirectory() as work:
        drawn = Path(work) / "figure.png"
        folder = Path(work) / "figures"
        folder.mkdir()  # for the files a command writes beside its figure (refine's and design's --out mesh)
        argv = [a.format(out=drawn, dir=folder) for a in figure.argv]
        env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
        run = subprocess.run([sys.executable, "-m", "symdecomp", *argv], cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
        if run.returncode not in (0, 1):  # 1: a verdict (a check that disagrees) still draws
            raise RuntimeError(f"symdecomp {' '.join(figure.argv)}: exit {run.returncode}: {run.stderr.strip()[-500:]}")
        source = folder / figure.pick if figure.pick else drawn
        if not source.is_file():
            raise RuntimeError(f"symdecomp {' '.join(figure.argv)}: wrote no {source.name}")
        target.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, out)
    return out


def draw_all(srcdir: Path, figures=FIGURES, say=print) -> dict[str, Path | None]:
    """Draw every figure that its command can draw into ``srcdir/_generated/figures`` (again only when its digest
    changed); ``None`` for a figure skipped because its command cannot draw yet (said through ``say``)."""
    target = srcdir / FIGURE_DIR
    done: dict[str, Path | None] = {}
    for figure in figures:
        missing = missing_options(figure)
        if missing:
            say(f"symdecomp docs: figure {figure.name!r} skipped: 'symdecomp {figure.command}' has no {', '.join(missing)} yet; "
                "its guide page shows a note instead")
            done[figure.name] = None
            continue
        out, key = target / f"{figure.name}.png", target / f"{figure.name}.png.key"
        digest = _digest(figure)
        if not (out.is_file() and key.is_file() and key.read_text() == digest):
            say(f"symdecomp docs: drawing figure {figure.name!r}: symdecomp {' '.join(figure.argv)}")
            draw(figure, target)
            key.write_text(digest)
        done[figure.name] = out
    return done


def figure_text(name: str, drawn: dict) -> str:
    """The reStructuredText of ``symdecomp-figure NAME``: the picture with its caption, or a note while it waits."""
    figures = {f.name: f for f in FIGURES}
    if name not in figures:
        raise ValueError(f"unknown figure {name!r} (known: {', '.join(figures)})")
    figure = figures[name]
    if drawn.get(name) is None:
        return (f".. note::\n\n   The picture of ``symdecomp {figure.command} --plot`` goes here, drawn when the site is "
                "built, once the command can draw it.\n")
    command, what = figure.caption.split(": ", 1)
    return f".. figure:: /{FIGURE_DIR}/{name}.png\n   :width: 90%\n\n   ``{command}``: {what}\n"


def setup(app):
    from docutils.parsers.rst import Directive, directives
    from docutils.parsers.rst import Parser as RSTParser
    from docutils.utils import new_document
    from sphinx.util import logging

    logger = logging.getLogger(__name__)
    drawn: dict = {}

    def builder_inited(app):
        drawn.update(draw_all(Path(app.srcdir), say=logger.info))

    class FigureDirective(Directive):
        required_arguments = 1
        has_content = False

        def run(self):
            document = new_document(self.state.document.current_source, self.state.document.settings)
            RSTParser().parse(figure_text(self.arguments[0], drawn), document)
            return document.children

    directives.register_directive("symdecomp-figure", FigureDirective)
    app.connect("builder-inited", builder_inited)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
