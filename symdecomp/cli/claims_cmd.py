"""``symdecomp claims``: check every registered claim of the paper and report its status."""

from __future__ import annotations

import argparse

from symdecomp.cli.common import (
    Once,
    add_budget_option,
    add_pool_options,
    add_scheme_option,
    flag,
    print_json,
    progress,
)
from symdecomp.cli.progress import add_quiet_option


def register(sub) -> None:
    p = sub.add_parser(
        "claims",
        help="check the paper's claims and list their statuses",
        description="Check every claim of the paper registered in symdecomp and print one row per claim: "
        "label, status (proved, verified, numeric, refuted, corrected, undecided, not applicable, error) and a line "
        "of evidence. Every claim is checked for the scheme given by --scheme (a name or a TOML file; default "
        "catmull-clark): the printed statement is one input, the scheme the other. Exit status 1 if any check "
        "failed to run (status 'error'); refuted or corrected claims are findings about the paper, not failures. "
        "Each row also gives the scope of its verdict (every n, range of n, single case; every k, range of k for "
        "the claims about sectors of k faces at sharp vertices), and the last line counts "
        "the verdicts established for every n (proved, or an erratum whose correction is proved for every n with an "
        "exact counterexample). A scheme of the zoo, or one on triangle meshes (loop), lists every claim as well: those "
        "that involve no scheme (Section 2, Section 6's CB-matrices) are checked, with the verdict every scheme gets; a claim "
        "that needs what the scheme lacks is 'not applicable', with the reason computed from the scheme (its topology, "
        "support or lattice), or with the command that answers the statement for it.",
    )
    flag(p, "--json", help="print the one JSON shape (docs: File formats, --json) with one row per claim: {label, section, title, "
         "status, scope, evidence, ...}")
    p.add_argument("--section", type=section, action=Once, help="only the claims of this section of the paper (e.g. 5.1), or of the toolkit's "
                   "own claims beyond the paper (B, B.1)")
    p.add_argument("--label", action="append", help="only this claim (repeatable), e.g. --label 'Eq. 34'")
    add_scheme_option(p, zoo=True)
    add_budget_option(p)
    add_pool_options(p, items="claims")
    flag(p, "--no-progress", help="do not draw a progress bar on stderr (the same as --quiet)")
    add_quiet_option(p)
    p.set_defaults(func=run)


def section(text: str) -> str:
    """argparse type: a section of the paper that has claims (``5`` or ``5.1``)."""
    from symdecomp.claims import all_claims

    sections = sorted({c.section for c in all_claims()})
    known = set(sections) | {s.split(".")[0] for s in sections}
    if text not in known:
        raise argparse.ArgumentTypeError(f"no claims in section {text!r}; known sections: {', '.join(sections)}")
    return text


def run(args) -> int:
    from symdecomp.claims import Status, all_claims, scope_summary
    from symdecomp.claims.batch import check_claims

    claims = all_claims()
    if args.section:
        claims = [c for c in claims if c.section == args.section or c.section.startswith(args.section + ".")]
    if args.label:
        wanted = set(args.label)
        unknown = wanted - {c.label for c in claims}
        if unknown:
            from symdecomp.errors import InvalidInputError

            raise InvalidInputError(f"no claim labelled {', '.join(sorted(unknown))}")
        claims = [c for c in claims if c.label in wanted]
    rows, results = [], []
    checked = check_claims([c.label for c in claims], args.scheme, budget=args.budget, jobs=args.jobs, executor=args.executor)
    for c, r in zip(claims, progress(checked, len(claims), "checking claims", enabled=not (args.no_progress or args.quiet or args.json))):
        results.append(r)
        row = {
            "label": c.label,
            "section": c.section,
            "title": c.title,
            "status": r.status.value,
            "scope": r.scope_text,
            "scheme": args.scheme.name,
            "evidence": str(r.evidence),
        }
        for key in ("counterexample", "correction", "digits", "valences"):
            value = getattr(r, key)
            if value is not None:
                row[key] = list(value) if isinstance(value, tuple) else value if isinstance(value, int) else str(value)
        rows.append(row)
    if args.json:
        print_json(args, rows)
    else:
        wl = max((len(r["label"]) for r in rows), default=5)
        ws = max((len(r["status"]) for r in rows), default=9)
        wc = max((len(r["scope"] or "-") for r in rows), default=5)
        for r in rows:
            print(f"{r['section']:<5} {r['label']:<{wl}}  {r['status']:<{ws}}  {r['scope'] or '-':<{wc}}  {r['evidence']}")
            pad = f"{'':<5} {'':<{wl}}  {'':<{ws}}  {'':<{wc}}"
            if "correction" in r:
                print(f"{pad}  corrected: {r['correction']}")
            if "counterexample" in r:
                print(f"{pad}  counterexample: {r['counterexample']}")
        counts = {}
        for r in rows:
            counts[r["status"]] = counts.get(r["status"], 0) + 1
        print(f"{len(rows)} claims: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())))
        print(scope_summary(results))
    return 1 if any(r["status"] == Status.ERROR.value for r in rows) else 0
