"""``symdecomp design``: a control net whose limit surface has prescribed properties at an extraordinary vertex.

Two modes (the mathematics is :mod:`symdecomp.analysis.design`):

* **a new 1-ring** (``--n N --normal x,y,z``): the 2-ring net of a vertex of valence ``N`` whose limit at the
  centre is at ``--position`` (default the origin), with normal ``--normal``, first tangent along ``--tangent``
  (projected off the normal; default a tangent chosen from the normal), and heights along the normal made of
  ``--elliptic A`` times the elliptic eigenvector (frequency 0) and ``--hyperbolic B`` at ``--angle T`` (radians,
  frequency 2; valence 5 or more). Vectors are three exact rationals ``x,y,z`` (``1/3``, ``0.25``, ``-2``); the
  amounts are exact numbers or expressions (``pi/6``). Parsed, never evaluated. Example::

      symdecomp design --n 5 --normal 0,0,1 --position 1,2,3 --elliptic 1/2 --out ring.obj

  prints the achieved limit position (as decimals; ``--exact``: exact rationals), normal, tangents and amounts,
  each saying whether it is exact.
* **a redesign** (``--mesh FILE --vertex I``): the smallest change of the vertex's 1-ring (least squares, along
  the normal) that makes the limit normal parallel to ``--normal`` and/or (``--flatten-hyperbolic``) removes the
  hyperbolic heights; the whole mesh is written with the changed 1-ring.

``--out FILE`` (``.obj``, ``.off``, ``.ply``, or ``--format``) is checked before any work and written whole. By
default each coordinate is rounded to the double nearest it and written as the shortest decimal that reads back as
that double (Python's ``repr``; PLY stores the double), and the achieved values are those of the net of these
doubles (measured again where the rounding changed a coordinate), so that the output describes the file. With ``--exact``
the file holds the computed net exactly where its coordinates are terminating decimals (every coordinate is
``p + x u + y v + h N`` with doubles ``x, y, h`` and integer ``u, v, N``, so exact in OBJ and OFF when
``--position`` is decimal, written in full: a double is up to about 55 significant digits; PLY stores doubles, so
there the exact checks hold to double precision), and the limit position is printed as exact rationals. What is
exact on the exact net: the position (Catmull-Clark: always; Loop: at valences 3, 4, 6 or with no heights), the
normal (without ``--hyperbolic``, and with it at even valences), the tangent direction; the amounts are measured to
double precision.

``--plot FILE`` also draws the net it writes: the faces around the vertex (the 2-ring), the centre ``O``, its 1-ring,
and the limit point, normal and tangent directions it prints (:mod:`symdecomp.output.plotting.design_figure`). The
target is checked before any work; naming the ``--out`` file is refused.

JSON (``--json``): ``{"scheme", "n", "vertex", "ring", "out", "format", "position_exact": ["x", "y", "z"],
"position", "tangents", "normal", "normal_exact", "tangent_exact", "elliptic", "hyperbolic", "angle", "change"}``
(``normal_exact``/``tangent_exact`` null where there was no target; ``change`` the Euclidean norm of the
1-ring's change, 0 for a new design).
"""

from __future__ import annotations

import argparse
from fractions import Fraction

from symdecomp.cli.common import Once, flag, integer, print_json, scheme_by_name, valence
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.validate import MESH_FORMATS as FORMATS

__all__ = ["register", "run"]


def _vector(name: str):
    def parse(text: str):
        parts = text.split(",")
        if len(parts) != 3 or not all(p.strip() for p in parts):
            raise argparse.ArgumentTypeError(f"expected three numbers x,y,z separated by commas, got {text[:40]!r}")
        return tuple(p.strip() for p in parts)

    parse.__name__ = name
    return parse


def _index(text: str) -> int:
    return integer(text, "--vertex", minimum=0, noun="a vertex index: an integer")


def register(sub) -> None:
    p = sub.add_parser(
        "design",
        help="a control net with prescribed limit position, normal, tangent, elliptic and hyperbolic parts (or the "
        "least change of a mesh's 1-ring for a normal / no hyperbolic part)",
        description="Build the 2-ring of a vertex of valence N as a sum of the 1-ring's eigencomponents (the paper's "
        "polygonal decomposition) so that its limit has the prescribed position, normal, tangent direction and "
        "elliptic/hyperbolic amounts; or, with --mesh and --vertex, change a vertex's 1-ring as little as possible "
        "(least squares) so that its limit normal is --normal and/or its hyperbolic heights vanish. Writes a mesh file "
        "and reports the achieved values, measured exactly on the written net where they are exact: the position "
        "(Catmull-Clark always, Loop where its mask is rational), the normal and the tangent direction (always without "
        "--hyperbolic; with it at even valences: at odd n a rational sequence without frequency 1 has no frequency 2 "
        "either). Example: symdecomp design --n 5 --normal 0,0,1 --position 1,2,3 "
        "--elliptic 1/2 --out ring.obj",
    )
    p.add_argument("--scheme", type=scheme_by_name, action=Once, default=None, metavar="NAME|FILE",
                   help="subdivision scheme: a name or a TOML scheme file (default catmull-clark; with --mesh: by the mesh's faces)")
    p.add_argument("--n", type=valence("design"), action=Once, default=None, metavar="N", help="valence of the new vertex")
    p.add_argument("--position", type=_vector("position"), action=Once, default=None, metavar="X,Y,Z",
                   help="limit position (default 0,0,0)")
    p.add_argument("--normal", type=_vector("normal"), action=Once, default=None, metavar="X,Y,Z", help="limit normal")
    p.add_argument("--tangent", type=_vector("tangent"), action=Once, default=None, metavar="X,Y,Z",
                   help="direction of the first tangent (projected off the normal)")
    p.add_argument("--elliptic", action=Once, default=None, metavar="A",
                   help="elliptic amount: the coefficient of the heights (along the unit normal) on the elliptic eigenvector of E_0, "
                   "scaled so that its largest class height (the a_i; the b_i for Catmull-Clark at n = 3) is 1")
    p.add_argument("--hyperbolic", action=Once, default=None, metavar="B",
                   help="hyperbolic amount B: heights B cos(2 (theta_i - T)) on the a_i, "
                   "the dominant eigenvector of the frequency-2 matrix on the others (valence >= 5)")
    p.add_argument("--angle", action=Once, default=None, metavar="T", help="hyperbolic angle in radians (default 0)")
    p.add_argument("--mesh", dest="mesh_file", action=Once, default=None, metavar="FILE", help="redesign a vertex of this mesh (.obj, .off, .ply)")
    p.add_argument("--vertex", type=_index, action=Once, default=None, metavar="I", help="the vertex to redesign (0-based)")
    flag(p, "--flatten-hyperbolic", help="with --mesh: remove the hyperbolic heights of the vertex's 1-ring")
    p.add_argument("--out", action=Once, required=True, metavar="FILE", help="the mesh file to write (.obj, .off, .ply)")
    p.add_argument("--format", choices=FORMATS, action=Once, default=None, help="the output format, if not the extension")
    flag(p, "--exact", help="print the limit position as exact rationals and write the net's coordinates exactly (terminating "
         "decimals in full, up to ~55 digits), so that the file's limit is exactly the one computed; by default the position "
         "is printed as decimals and each coordinate written as the shortest decimal that reads back as its double")
    flag(p, "--json", help="print the achieved values as JSON")
    add_plot_option(p, "the net it writes around the vertex (its 2-ring), the centre, and the limit point, normal and tangent "
                    "directions it reports (not the --out file)")
    p.set_defaults(func=run)


def _mode(args) -> str:
    from symdecomp.errors import InvalidInputError

    if args.mesh_file is None:
        for name in ("vertex", "flatten_hyperbolic"):
            if getattr(args, name):
                raise InvalidInputError(f"--{name.replace('_', '-')} needs --mesh")
        if args.n is None or args.normal is None:
            raise InvalidInputError("a new design needs --n N and --normal X,Y,Z (or give --mesh and --vertex to redesign)")
        return "new"
    for name in ("n", "position", "tangent", "elliptic", "hyperbolic", "angle"):
        if getattr(args, name) is not None:
            raise InvalidInputError(f"--{name} is for a new design; with --mesh give --vertex and --normal and/or --flatten-hyperbolic")
    if args.vertex is None:
        raise InvalidInputError("--mesh needs --vertex I")
    if args.normal is None and not args.flatten_hyperbolic:
        raise InvalidInputError("--mesh needs --normal X,Y,Z and/or --flatten-hyperbolic")
    return "redesign"


def _report(result, out, fmt) -> dict:
    a = result.achieved
    return {"scheme": result.scheme, "n": result.n, "vertex": result.vertex, "ring": list(result.ring), "out": str(out),
            "format": fmt, "position_exact": [str(x) for x in a.position], "position": [float(x) for x in a.position],
            "tangents": [list(t) for t in a.tangents], "normal": None if a.normal is None else list(a.normal),
            "normal_exact": a.normal_exact, "tangent_exact": a.tangent_exact, "elliptic": a.elliptic,
            "hyperbolic": a.hyperbolic, "angle": a.angle, "change": result.change}


def _decimal(x: float) -> str:
    """``x`` as the shortest decimal that reads back as it (``repr``), an integral value without ``.0``.

    >>> [_decimal(x) for x in (0.025, 144115188075855883 / 5764607523034234880, -3.0, -0.0, 1e-20)]
    ['0.025', '0.025', '-3', '0', '1e-20']
    """
    text = repr(x + 0.0)
    return text[:-2] if text.endswith(".0") else text


def _rounded(mesh, coordinate):
    """``mesh`` with every coordinate ``c`` replaced by ``coordinate(c)`` (``mesh`` itself when none changes)."""
    points = tuple(tuple(coordinate(c) for c in p) for p in mesh.points)
    return mesh if points == tuple(mesh.points) else mesh.with_points(points)


def _double(c) -> Fraction:
    return Fraction(float(c))


def _shortest(c) -> Fraction:
    """The shortest decimal that reads back as the double nearest ``c`` (``repr``), as the rational it spells."""
    return Fraction(repr(float(c)))


def _on_doubles(args, mode: str, scheme, result):
    """``result`` with its net rounded to doubles (what the file holds without ``--exact``) and the achieved values
    measured again on that net where rounding changed it (a non-dyadic coordinate, as from ``--position 1/3``)."""
    from dataclasses import replace

    from symdecomp.analysis.design import frame, limit_frame

    net = result.mesh  # (a control net, not a mesh kind)
    mesh = _rounded(net, _double)
    if mesh is net:
        return result
    if mode == "new":
        u, _, N = frame(args.normal, args.tangent)  # the frame the design was built in
        achieved = limit_frame(scheme, mesh, result.vertex, normal=N, tangent=u)
    else:
        achieved = limit_frame(scheme, mesh, result.vertex, normal=args.normal)
    return replace(result, mesh=mesh, achieved=achieved)


def _print(data: dict, exact_position: bool) -> None:
    def exact(flag_value, what):
        return {True: f"[exactly {what}]", False: "[to double precision]", None: ""}[flag_value]

    print(f"{data['scheme']}, valence {data['n']}: vertex {data['vertex']} -> {data['out']} ({data['format']})")
    position = data["position_exact"] if exact_position else [_decimal(x) for x in data["position"]]
    print(f"limit position  {', '.join(position)}")
    if data["normal"] is None:  # the tangents are parallel: no tangent plane, nothing to call exact
        print("normal          none (the tangents are parallel)")
    else:
        print(f"normal          {' '.join(f'{x + 0.0:.12g}' for x in data['normal'])}  {exact(data['normal_exact'], 'parallel to --normal')}")
    for k, t in enumerate(data["tangents"], 1):
        print(f"tangent t{k}      {' '.join(f'{x + 0.0:.12g}' for x in t)}" + (f"  {exact(data['tangent_exact'], 'along --tangent')}"
                                                                             if k == 1 else ""))
    print(f"elliptic        {data['elliptic']:.12g}")
    if data["hyperbolic"] is not None:
        print(f"hyperbolic      {data['hyperbolic']:.12g} at angle {data['angle']:.12g}")
    if data["change"]:
        print(f"change of the 1-ring (Euclidean norm)  {data['change']:.12g}")


def run(args) -> int:
    from symdecomp.analysis.design import design_ring
    from symdecomp.analysis.redesign import redesign_vertex
    from symdecomp.cli.files import check_output_file, write_output_file
    from symdecomp.schemes.meshfile import scheme_for_mesh
    from symdecomp.schemes.meshformats import encode_mesh, mesh_format, read_mesh
    from symdecomp.schemes.scheme import catmull_clark

    mode = _mode(args)
    out = check_output_file(args.out)
    fmt = mesh_format(out, args.format)
    plot = _check_plot(args, out)
    if mode == "new":
        scheme = args.scheme if args.scheme is not None else catmull_clark()
        amounts = {k: getattr(args, k) for k in ("elliptic", "hyperbolic", "angle") if getattr(args, k) is not None}
        result = design_ring(scheme, args.n, normal=args.normal, position=args.position or (0, 0, 0), tangent=args.tangent, **amounts)
    else:
        mesh = read_mesh(args.mesh_file)
        scheme = args.scheme if args.scheme is not None else scheme_for_mesh(mesh)
        result = redesign_vertex(scheme, mesh, args.vertex, normal=args.normal, flatten_hyperbolic=bool(args.flatten_hyperbolic))
    written = result.mesh
    if not args.exact:
        result = _on_doubles(args, mode, scheme, result)
        written = _rounded(result.mesh, _shortest)  # the same doubles, in at most 17 significant digits
    write_output_file(out, encode_mesh(written, fmt))
    data = _report(result, out, fmt)
    print_json(args, data) if args.json else _print(data, bool(args.exact))
    write_plot(plot, lambda: _figure(written, result, data))
    return 0


def _check_plot(args, out):
    """``--plot``'s target, refused before any work (:func:`~symdecomp.cli.plot_file.check_plot`) and when it is ``--out``."""
    from symdecomp.errors import InvalidInputError

    plot = check_plot(args)
    if plot is not None and plot.path.resolve() == out.resolve():
        raise InvalidInputError(f"--plot {args.plot}: the same file as --out; the figure and the mesh need two files")
    return plot


def _figure(written, result, data: dict):
    """The written net (its doubles) and the limit frame ``data`` reports, as printed."""
    from symdecomp.output.plotting.design_figure import design_figure

    title = f"{data['scheme']}, valence {data['n']}: vertex {data['vertex']}" + (", redesigned" if data["change"] else "")
    return design_figure(written.points_array, written.faces, result.ring, data["position"], data["normal"],
                         data["tangents"], title)
