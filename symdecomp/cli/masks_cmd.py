"""``symdecomp masks N``: the limit-position and tangent masks of the central vertex at valence N.

The masks are left eigenvectors of the subdivision matrix (see :mod:`symdecomp.analysis.masks`).
Scaling: the position mask sums to 1. The tangent masks are unnormalised: the first has
weight ``cos(2 pi i/N)`` on ``a_i`` and the second ``sin(2 pi i/N)``; their weights on ``b_i``
follow from the left-eigenvector equation (for Catmull-Clark
``(cos(2 pi i/N) + cos(2 pi (i+1)/N))/(16 lambda_1 - 4)``, resp. with ``sin``); ``O`` has weight 0.

JSON: ``{"n": N, "position": {"O": w, "a": [...], "b": [...]}, "tangents": [{"O": w, "a": [...],
"b": [...]}, {...}], "subdominant": "<decimal>", "lambda_1_subdominant": true, "subdominance": "<why>"}``,
every weight a decimal string.

``lambda_1`` (the dominant eigenvalue of ``M_1``) is called the subdominant eigenvalue only when that is
certified at this valence on the 1-ring (:func:`~symdecomp.verify.c1_spectrum.spectral_conditions`: 1 simple,
``lambda_1`` real, of multiplicity 2, strictly larger in modulus than every other eigenvalue; exact where
balls tie). Otherwise the tangent masks are eigenvectors of ``lambda_1`` but not of the tangent plane: the
output says why and the exit status is 1.

``--plot FILE`` draws the printed masks on the neighbourhood's points (:mod:`symdecomp.output.plotting.mask_weights`),
each where it sits in the regular picture: on the fan of an interior vertex, on a sharp vertex's sectors, on a zoo
scheme's neighbourhood (a dual scheme's: the centre n-gon's corners and its rings). The target is checked before any
work; where the command finds no mask, ``--plot`` says so in one line (exit code 2) and writes nothing.
"""

from __future__ import annotations

import math
import sys

from symdecomp.cli.common import (
    Once,
    add_rings_option,
    add_scheme_option,
    closed_form_obstacle,
    digits,
    flag,
    general_path,
    print_json,
)
from symdecomp.cli.element import (
    add_sharp_options,
    describe,
    exact_only,
    faces_or_valence,
    named_element,
    refuse_sharp_options,
    ring_depth,
    route,
    sharp_vertex,
    steps_note,
)
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.errors import SymdecompError


def register(sub) -> None:
    p = sub.add_parser(
        "masks",
        help="limit-position and tangent masks of the central vertex at valence N",
        description="Left eigenvectors of the valence-N subdivision matrix for the eigenvalue 1 (limit position, "
        "weights summing to 1) and for the subdominant eigenvalue lambda_1 (two tangent masks: weight cos(2 pi i/N), "
        "resp. sin(2 pi i/N), on a_i; b_i weights from the eigenvector equation; 0 on O). With --boundary, --corner, "
        "--crease K2 or --dart: exact left eigenvectors of the vertex's 1-ring matrix: the limit position, the boundary "
        "(or crease) curve's tangent (the crease block's eigenvalue 1/2: it vanishes off the crease points) and the "
        "surface's cross tangent (the largest eigenvalue of a sector's block, its sine block j = 1, plus the solve on the "
        "crease points), one per side of a crease; a corner's two boundary curves; a dart's two subdominant "
        "eigenvectors; with --sharpness S, of the level-0 matrix. Exit status 1 when the tangents' eigenvalues are not "
        "certified the two subdominant ones.",
    )
    p.add_argument("n", type=faces_or_valence("masks"), metavar="N",
                   help="the valence (an integer, 3 <= N <= 1000), or the faces K of a sharp vertex's sector")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of the weights (default 20, at most 1000)")
    flag(p, "--json", help='print {"n", "position", "tangents", "subdominant"}')
    add_scheme_option(p, zoo=True)
    add_rings_option(p)
    add_sharp_options(p)
    add_plot_option(p, "each mask (position and the two tangents) on the neighbourhood's points, each point where it "
                    "sits in the regular picture, its weight by colour and size and written beside it: the fan of an "
                    "interior vertex (any --rings), a sharp vertex's sectors (--boundary, --corner, --crease, --dart), a "
                    "scheme of the zoo's neighbourhood (a dual scheme's: the centre n-gon's corners and its rings)")
    p.set_defaults(func=run)


def _panels(args, data, exact_position=None) -> list:
    """The masks as printed (``data``: ``O`` and ``a``/``b`` lists, or ``classes`` by ``"u,v"``), as figure panels;
    ``exact_position``: the position mask's exact weights ``(O, a_i, b_i)``, written beside the decimals."""
    from symdecomp.output.plotting.mask_weights import MaskPanel, MaskPoint

    def exact(k: int) -> str | None:
        return None if exact_position is None or len(str(exact_position[k])) > 12 else str(exact_position[k])

    names = {f"{u},{v}": name for name, (u, v) in args.scheme.lattice.one_ring_classes}  # a_i, and b_i on quads
    panels = []
    for k, (title, mask) in enumerate([("position", data["position"]), ("tangent 1", data["tangents"][0]),
                                       ("tangent 2", data["tangents"][1])]):
        points = [MaskPoint("O", (0, 0, 0), mask["O"], exact(0) if k == 0 else None)]
        if "classes" in mask:
            for key, weights in mask["classes"].items():
                u, v = (int(x) for x in key.split(","))
                name = names.get(key, f"({key})")
                points += [MaskPoint(f"{name}_{s}", (s, u, v), w) for s, w in enumerate(weights)]
        else:
            for j, name in enumerate(("a", "b")):
                points += [MaskPoint(f"{name}_{s}", (s, 1, j), w, exact(1 + j) if k == 0 else None)
                           for s, w in enumerate(mask[name])]
        panels.append(MaskPanel(title, tuple(points)))
    return panels


def _draw(args, plot, data, certified: bool, exact_position=None) -> None:
    """``masks --plot``: the printed masks on the fan (:mod:`symdecomp.output.plotting.mask_weights`)."""
    from symdecomp.output.plotting.mask_weights import mask_figure

    if plot is None:
        return
    rings = f", {args.rings}-ring" if args.rings != 1 else ""
    what = "subdominant" if certified else "NOT certified subdominant"
    title = f"{args.scheme.name}, valence n = {args.n}{rings}: limit masks (lambda_1 = {data['subdominant']}, {what})"
    write_plot(plot, lambda: mask_figure(_panels(args, data, exact_position), args.n, title))


def _subdominance(args) -> tuple[bool, str, bool]:
    return lambda_1_subdominance(args.scheme, args.n)


def lambda_1_subdominance(scheme, n: int) -> tuple[bool, str, bool]:
    """``(certified, why, one_simple)``: whether ``lambda_1`` is certified the subdominant eigenvalue of the 1-ring at
    valence ``n`` and why (not), and whether 1 is a simple eigenvalue there (else no mask is defined).
    The masks' tangent plane needs the first (``symdecomp inspect`` asks it too)."""
    from symdecomp.verify.c1_spectrum import spectral_conditions
    from symdecomp.verify.result import C1Verdict

    try:
        r = spectral_conditions(scheme, n, one_ring=True)
    except SymdecompError as exc:
        return False, f"not certified: {exc}", True
    if r.status is C1Verdict.C1 and r.subdominant is not None and r.subdominant.frequency == 1:
        return True, r.reason, True
    if r.status is C1Verdict.C1:
        return False, f"the subdominant eigenvalue is at frequency {r.subdominant.frequency}, not 1: {r.reason}", True
    return False, r.reason, r.one_simple


def _header(args, data, certified: bool, why: str) -> str:
    what = "subdominant eigenvalue lambda_1" if certified else "lambda_1 (NOT the subdominant eigenvalue: " + why + ")"
    rings = f", {args.rings}-ring" if general_path(args) or closed_form_obstacle(args.scheme) else ""
    return f"{args.scheme.name}, valence n = {args.n}{rings}; {what} = {data['subdominant']}"


def _finish(args, data, certified: bool, why: str) -> int:
    if not certified:
        print(f"symdecomp masks: at n = {args.n} lambda_1 is not the subdominant eigenvalue ({why}); the tangent masks "
              "are its eigenvectors, not the tangent plane's", file=sys.stderr)
    return 0 if certified else 1


def _run_general(args, certified: bool, why: str, plot=None) -> int:
    from symdecomp.analysis.masks import ring_masks

    data = ring_masks(args.scheme, args.n, args.rings, digits=args.digits)
    _draw(args, plot, data, certified)
    if args.json:
        print_json(args, {**data, "lambda_1_subdominant": certified, "subdominance": why})
        return _finish(args, data, certified, why)
    print(_header(args, data, certified, why))
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        print(f"  O: {mask['O']}")
        for key, weights in mask["classes"].items():
            print(f"  class ({key}), sectors 0..{args.n - 1}: {', '.join(weights)}")
    return _finish(args, data, certified, why)


def _block_names(scheme, vertex) -> dict:
    """``{eigenvalue key: "block, block"}`` from the spectrum's names (mirror blocks, or parts of the matrix)."""
    from symdecomp.analysis.spectrum import sharp_spectrum

    return {e.key: ", ".join(e.blocks) for e in sharp_spectrum(scheme, vertex, digits=8).entries}


def _print_mask(mask, names, digits: int, blocks: dict) -> None:
    exact = mask.exact()
    print(f"{mask.name} (eigenvalue {_value(mask, digits)}, {blocks.get(mask.eigenvalue.key, mask.eigenvalue.part)}):")
    for i, (name, text) in enumerate(zip(names, mask.texts(digits))):
        closed = "" if exact is None or exact[i].is_Integer or len(str(exact[i])) > 60 else f"  = {exact[i]}"
        print(f"  {name}: {text}{closed}")


def _value(mask, digits: int) -> str:
    from symdecomp.analysis.spectrum import acb_text

    return acb_text(mask.eigenvalue.ball, digits)


def _sector_panels(vertex, masks, digits: int) -> list:
    """A sharp vertex's printed masks as figure panels: each weight on its point ``(s, u, v)`` of the sectors, its exact
    value beside it where short."""
    from symdecomp.output.plotting.mask_weights import MaskPanel, MaskPoint

    labels = vertex.ring_labels(1)  # the matrix order of masks.names
    panels = []
    for mask in (masks.position, *masks.tangents):
        exact = mask.exact()
        short = [None if exact is None or len(str(e)) > 12 else str(e) for e in (exact or [None] * len(labels))]
        points = tuple(MaskPoint(name, label, text, e) for name, label, text, e in zip(masks.names, labels, mask.texts(digits), short))
        panels.append(MaskPanel(mask.name, points))
    return panels


def _draw_sector(args, plot, vertex, masks, value: str) -> None:
    """``masks K --boundary ... --plot``: the printed masks on the sharp vertex's sectors."""
    from symdecomp.output.plotting.mask_weights import mask_figure, sector_rays

    if plot is None:
        return
    span = float(vertex.angle) if vertex.angle is not None else math.pi / 2 if vertex.corner else None
    rays = sector_rays(vertex.sectors, vertex.closed, span)
    title = f"{args.scheme.name}, {describe(vertex)}: limit masks (subdominant eigenvalue {value})"
    write_plot(plot, lambda: mask_figure(_sector_panels(vertex, masks, args.digits), vertex.faces, title, rays))


def _run_sector(args, plot=None) -> int:
    """``symdecomp masks K --boundary`` (and ``--corner``, ``--crease K2``, ``--dart``): print the masks, exit 1 when the
    tangents are not the tangent plane's."""
    from symdecomp.analysis.masks import sharp_masks
    from symdecomp.analysis.spectrum import acb_text

    refuse_sharp_options(args, "--rings")
    vertex = sharp_vertex(args, args.n)
    masks = exact_only(args, vertex, lambda: sharp_masks(args.scheme, vertex))
    blocks = _block_names(args.scheme, vertex)
    value, where = acb_text(masks.subdominant.ball, args.digits), blocks.get(masks.subdominant.key, masks.subdominant.part)
    _draw_sector(args, plot, vertex, masks, value)
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "vertex": describe(vertex), "lattice": vertex.lattice.name,
                    "position": masks.position.as_json(masks.names, args.digits),
                    "tangents": [t.as_json(masks.names, args.digits) for t in masks.tangents],
                    "subdominant": {"value": value, "blocks": where}, "tangent_plane": masks.tangent_plane,
                    "reason": masks.reason})
    else:
        print(f"{args.scheme.name}, {describe(vertex)} ({vertex.lattice} mesh): subdominant eigenvalue {value} ({where}); "
              f"{masks.reason}")
        for mask in (masks.position, *masks.tangents):
            _print_mask(mask, masks.names, args.digits, blocks)
    if not masks.tangent_plane:
        print(f"symdecomp masks: {describe(vertex)}: the tangent masks are not the tangent plane's ({masks.reason})",
              file=sys.stderr)
    return 0 if masks.tangent_plane else 1


def _zoo_panels(scheme, data: dict) -> list:
    """A zoo scheme's printed masks as figure panels: the weight of class ``c`` in sector ``s`` (named ``c<c>_<s>``) on
    its point of the neighbourhood, placed as in the regular picture (around a centre face: the primal face it is)."""
    from symdecomp.output.plotting.mask_weights import MaskPanel, MaskPoint, neighbourhood_places
    from symdecomp.schemes.lattice import lattice
    from symdecomp.schemes.neighbourhood import neighbourhood
    from symdecomp.schemes.topology import topology_of

    n = data["n"]
    nb = neighbourhood(lattice(scheme.lattice), n, data["rings"], centred=topology_of(scheme).centre)
    places = neighbourhood_places(nb)
    centre = 0 if nb.centre is None else 1
    panels = []
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        points = [MaskPoint("O", (0, 0, 0), mask["O"], place=places[nb.order[0]])] if "O" in mask else []
        for c, weights in enumerate(mask["classes"].values()):
            points += [MaskPoint(f"c{c}_{s}", (s, 0, 0), w, place=places[nb.order[centre + c * n + s]])
                       for s, w in enumerate(weights)]
        panels.append(MaskPanel(title, tuple(points)))
    return panels


def _run_zoo(args, plot=None) -> int:
    """``masks N --scheme <zoo scheme>``: position and tangent masks by orbit class."""
    from symdecomp.analysis.zoo_masks import zoo_masks
    from symdecomp.output.plotting.mask_weights import mask_figure

    data = zoo_masks(args.scheme, args.n, ring_depth(args), digits=args.digits)
    title = (f"{data['scheme']}, n = {data['n']}, neighbourhood of depth {data['rings']}: limit masks (subdominant "
             f"eigenvalue {data['subdominant']})")
    write_plot(plot, lambda: mask_figure(_zoo_panels(args.scheme, data), data["n"], title))
    if args.json:
        print_json(args, data)
        return 0
    print(f"{data['scheme']}, n = {data['n']}, neighbourhood of depth {data['rings']}{steps_note(args.scheme)}: "
          f"subdominant eigenvalue {data['subdominant']}")
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        if "O" in mask:
            print(f"  centre: {mask['O']}")
        for key, weights in mask["classes"].items():
            print(f"  class {key}, sectors 0..{args.n - 1}: {', '.join(weights)}")
    return 0


def run(args) -> int:
    """``masks``: the route of the element the arguments name (:data:`ROUTES_BY_KIND`), ``--plot`` checked before any
    work and handed to it."""
    answer = route("masks", ROUTES_BY_KIND, named_element(args))
    return answer(args, check_plot(args))


def _run_vertex(args, plot=None) -> int:
    """``masks N``: an interior vertex, from the closed forms where they apply, else the any-scheme route."""
    from symdecomp.analysis.masks import limit_masks, limit_masks_at
    from symdecomp.analysis.tangent import complex_at

    certified, why, one_simple = _subdominance(args)
    if not one_simple and plot is not None:
        raise SymdecompError(f"--plot: at n = {args.n}, {args.scheme.name}: {why}; no limit position mask is defined, "
                             "nothing to draw")
    if not one_simple:
        print(f"symdecomp masks: at n = {args.n}, {args.scheme.name}: {why}; no limit position mask is defined, and no "
              "tangent masks", file=sys.stderr)
        return 1
    # no closed forms (or real closed forms for a complex lambda_1): the any-scheme route, from Arb balls
    if general_path(args) or closed_form_obstacle(args.scheme) or complex_at(args.scheme, args.n):
        return _run_general(args, certified, why, plot)
    at = limit_masks_at(args.scheme, args.n)
    data = at.as_json(args.digits)
    _draw(args, plot, data, certified, (at.position[0], at.position[1], at.position[1 + args.n]))  # O, a_0, b_0
    if args.json:
        print_json(args, {**data, "lambda_1_subdominant": certified, "subdominance": why})
        return _finish(args, data, certified, why)
    closed = limit_masks(args.scheme)
    print(_header(args, data, certified, why))
    print(f"closed forms: position O: {closed.position[0]}, a_i: {closed.position[1]}, b_i: {closed.position[2]}")
    for k in range(2):
        print(f"              tangent {k + 1}: a_i: {closed.tangent_a[k]}, b_i: {closed.tangent_b[k]}")
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        print(f"  O: {mask['O']}")
        for i, (a, b) in enumerate(zip(mask["a"], mask["b"])):
            print(f"  a_{i}: {a:<{args.digits + 8}} b_{i}: {b}")
    return _finish(args, data, certified, why)


#: The route of each kind of element (:mod:`symdecomp.cli.element`); the zoo's engine refuses a sharp option itself.
ROUTES_BY_KIND = {"vertex": _run_vertex, "sector": _run_sector, "zoo": _run_zoo, "zoo sector": _run_zoo}
