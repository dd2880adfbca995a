"""``symdecomp derive``: regenerate the LaTeX derivations of the paper's claims."""

from __future__ import annotations

import re
import sys
from pathlib import Path

from symdecomp.cli.common import Once, add_budget_option, add_scheme_option, flag, given, print_json, progress, refuse_non_quad
from symdecomp.cli.files import check_output_directory, replace_owned_files
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError
from symdecomp.validate import DEFAULT_BUDGET

__all__ = ["register", "run", "write_derivations"]

#: Files this command owns in the output directory (stale ones are removed on regeneration).
OWNED = re.compile(r"^(main|section-[0-9-]+|beyond-[0-9-]+|zoo|c1-every-n)\.tex$")


def register(sub) -> None:
    p = sub.add_parser(
        "derive",
        help="write the derivations of the paper's claims as LaTeX (main.tex + one file per section)",
        description="Check every registered claim and write its statement, status, evidence and "
        "derivation (formulas printed by sympy) as LaTeX: one section-<N>.tex file per section of the "
        "paper and a main.tex that inputs them after a summary table. The output is deterministic; "
        "compile it with `latexmk -pdf main.tex` (or pdflatex, twice). Files of earlier runs that no "
        "longer correspond to a section are removed; other files in the directory are left alone. "
        "Exit status 1 if a check failed to run (status 'error'; the files are written all the same). main.tex also inputs "
        "c1-every-n.tex: for Catmull-Clark and Loop, C1 and the curvature regime for every valence as propositions, proved "
        "with the steps of `symdecomp c1 --every-n` and `symdecomp artifacts --every-n`, then Doo-Sabin's C1 for every "
        "valence (the dual test certified valence by valence over the report's range). It also writes "
        "zoo.tex, a document of its own: the paper's decomposition applied to each shipped family of the zoo (the rules' "
        "symbols, the frequency blocks and their factored characteristic polynomials, the spectrum at a few valences).",
    )
    p.add_argument("--out", action=Once, default="derivations",
                   help="output directory (default: derivations/), checked before any claim is computed; written as a "
                   "whole, so an interrupted run leaves the old files or the new ones, never a mix")
    flag(p, "--json", help="print the one JSON shape (docs: File formats, --json) with the files written under \"files\"")
    p.add_argument(
        "--label",
        action="append",
        help="print the LaTeX of this claim (repeatable) to stdout instead of writing files, "
        "e.g. --label 'Eq. 43' (to paste into a paper; needs the preamble of main.tex)",
    )
    add_scheme_option(p)
    add_budget_option(p)
    flag(p, "--no-progress", help="do not draw a progress bar on stderr (the same as --quiet)")
    add_quiet_option(p)
    p.set_defaults(func=run)


def all_claims():
    """The registered claims (:func:`symdecomp.claims.all_claims`), imported when the command runs."""
    from symdecomp.claims import all_claims

    return all_claims()


def zoo_files(show_progress: bool = False) -> dict[str, str]:
    """``zoo.tex``: the zoo's families derived by the engine (:func:`symdecomp.output.zoo_derivations.zoo_derivation_files`)."""
    from symdecomp.output.zoo_derivations import zoo_derivation_files
    from symdecomp.schemes.stencil_files import ZOO_FILES

    return zoo_derivation_files(progress(list(ZOO_FILES), len(ZOO_FILES), "deriving the zoo", enabled=show_progress))


def write_derivations(out: Path, *, show_progress: bool = False, scheme=None, budget=DEFAULT_BUDGET) -> list[Path]:
    """Check every claim (for ``scheme``, default Catmull-Clark; ``budget`` seconds each) and write the derivation files to ``out``,
    with C1 and the curvature regime for every valence of the built-in schemes in ``c1-every-n.tex``
    (:mod:`symdecomp.output.every_n_derivations`) and the zoo's families in ``zoo.tex`` (:mod:`symdecomp.output.zoo_derivations`)."""
    from symdecomp.claims import check_claim
    from symdecomp.output.every_n_derivations import every_n_files
    from symdecomp.output.latex import derivation_files

    claims = all_claims()
    pairs = [(c, check_claim(c.label, scheme, budget=budget)) for c in progress(claims, len(claims), "checking claims", enabled=show_progress)]
    every_n = every_n_files()  # the built-in schemes' proofs for every valence, input by main.tex after the claims
    return _write(out, {**derivation_files(pairs, tuple(every_n)), **every_n, **zoo_files(show_progress)})


def _write(out: Path, files: dict[str, str]) -> list[Path]:
    """Replace the owned files of ``out`` by ``files`` in one step (stale owned files go, others stay)."""
    return replace_owned_files(out, files, OWNED)


def run(args) -> int:
    from symdecomp.claims import Status, check_claim
    from symdecomp.output.latex import claim_latex

    refuse_non_quad(args.scheme, "derive")
    for option in ("--out", "--json", "--no-progress"):
        if args.label and given(args, option[2:].replace("-", "_")):
            raise InvalidInputError(f"--label and {option} cannot be used together: --label prints LaTeX to stdout and writes no files")
    if args.label:
        known = {c.label: c for c in all_claims()}
        unknown = [label for label in args.label if label not in known]
        if unknown:
            raise InvalidInputError(f"no claim labelled {', '.join(unknown)}; known: {', '.join(known)}")
        print("\n".join(claim_latex(known[label], check_claim(label, args.scheme, budget=args.budget)) for label in args.label), end="")
        return 1 if any(check_claim(label, args.scheme, budget=args.budget).status is Status.ERROR for label in args.label) else 0
    out = check_output_directory(args.out)  # before the claims are computed: a bad path is bad input, now
    written = write_derivations(out, show_progress=not (args.no_progress or args.quiet or args.json), scheme=args.scheme, budget=args.budget)
    if args.json:
        print_json(args, {"files": [str(p) for p in written]})
    else:
        for path in written:
            print(path)
        print(f"compile with: cd {out} && latexmk -pdf main.tex", file=sys.stderr)
    failed = [c.label for c in all_claims() if check_claim(c.label, args.scheme, budget=args.budget).status is Status.ERROR]
    if failed:
        print(f"symdecomp: the checks of {', '.join(failed)} failed to run (status error)", file=sys.stderr)
    return 1 if failed else 0
