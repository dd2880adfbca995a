"""``symdecomp masks N``: the limit-position and tangent masks of the central vertex at valence N.

The masks are left eigenvectors of the subdivision matrix (see :mod:`symdecomp.analysis.masks`).
Scaling: the position mask sums to 1. The tangent masks are unnormalised: the first has
weight ``cos(2 pi i/N)`` on ``a_i`` and the second ``sin(2 pi i/N)``; their weights on ``b_i``
follow from the left-eigenvector equation (for Catmull-Clark
``(cos(2 pi i/N) + cos(2 pi (i+1)/N))/(16 lambda_1 - 4)``, resp. with ``sin``); ``O`` has weight 0.

JSON: ``{"n": N, "position": {"O": w, "a": [...], "b": [...]}, "tangents": [{"O": w, "a": [...],
"b": [...]}, {...}], "subdominant": "<decimal>"}``, every weight a decimal string.
"""

from __future__ import annotations

from symdecomp.analysis.masks import limit_masks, limit_masks_at
from symdecomp.analysis.ring_masks import ring_masks
from symdecomp.cli.common import Once, add_rings_option, add_scheme_option, closed_form_obstacle, digits, flag, general_path, print_json, valence


def register(sub) -> None:
    p = sub.add_parser(
        "masks",
        help="limit-position and tangent masks of the central vertex at valence N",
        description="Left eigenvectors of the valence-N subdivision matrix for the eigenvalue 1 (limit position, "
        "weights summing to 1) and for the subdominant eigenvalue lambda_1 (two tangent masks: weight cos(2 pi i/N), "
        "resp. sin(2 pi i/N), on a_i; b_i weights from the eigenvector equation; 0 on O).",
    )
    p.add_argument("n", type=valence("masks"), metavar="N", help="the valence (an integer, 3 <= N <= 1000)")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of the weights (default 20, at most 1000)")
    flag(p, "--json", help='print {"n", "position", "tangents", "subdominant"}')
    add_scheme_option(p)
    add_rings_option(p)
    p.set_defaults(func=run)


def _run_general(args) -> int:
    data = ring_masks(args.scheme, args.n, args.rings, digits=args.digits)
    if args.json:
        print_json(data)
        return 0
    print(f"{args.scheme.name}, valence n = {args.n}, {args.rings}-ring; subdominant eigenvalue lambda_1 = {data['subdominant']}")
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        print(f"  O: {mask['O']}")
        for key, weights in mask["classes"].items():
            print(f"  class ({key}), sectors 0..{args.n - 1}: {', '.join(weights)}")
    return 0


def run(args) -> int:
    if general_path(args) or closed_form_obstacle(args.scheme):  # no closed forms: the any-scheme route
        return _run_general(args)
    masks = limit_masks_at(args.scheme, args.n)
    data = masks.as_json(args.digits)
    if args.json:
        print_json(data)
        return 0
    closed = limit_masks(args.scheme)
    print(f"{args.scheme.name}, valence n = {args.n}; subdominant eigenvalue lambda_1 = {data['subdominant']}")
    print(f"closed forms: position O: {closed.position[0]}, a_i: {closed.position[1]}, b_i: {closed.position[2]}")
    for k in range(2):
        print(f"              tangent {k + 1}: a_i: {closed.tangent_a[k]}, b_i: {closed.tangent_b[k]}")
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        print(f"  O: {mask['O']}")
        for i, (a, b) in enumerate(zip(mask["a"], mask["b"])):
            print(f"  a_{i}: {a:<{args.digits + 8}} b_{i}: {b}")
    return 0
