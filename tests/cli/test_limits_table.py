"""Every bound of the limits table (``symdecomp.cli.common.LIMITS``, rendered by the docs) is enforced where it is named.

Each row has a case below: one step past the bound, which must be refused at once, in one line naming the bound
(exit status 2 on the command line, the package's error in the API). A new row without a case fails
:func:`test_every_bound_has_a_case`: a bound that nothing enforces is not a bound.
"""

import os
import socket
import struct
import threading
import time

import pytest

from symdecomp import (
    artifact_indicators,
    c1_test,
    catmull_clark,
    certify_ring,
    classify_shape,
    closed_form_spectrum,
    jordan_block_size,
    patch_matrices,
    ring_masks,
    ring_spectrum,
    second_order_eigenstructure,
)
from symdecomp.analysis.tuning_region import interval_region, placed_points, tuning_region
from symdecomp.cli import main
from symdecomp.cli.common import LIMITS
from symdecomp.errors import SymdecompError
from symdecomp.parallel.cluster import probe_scheduler
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA


def _over(key: str, kind=str):
    return kind(LIMITS[key][0] + 1)


DESIGN = ["design", "--n", "5", "--normal", "0,0,1"]
SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
#: A cube of side 1e13: every vertex's ring is past the design bound of a ring's coordinates.
SCALED_CUBE = "".join(f"v {x}e13 {y}e13 {z}e13\n" for z in (0, 1) for y in (0, 1) for x in (0, 1)) + "".join(
    "f " + " ".join(str(i + 1) for i in face) + "\n"
    for face in [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])


def _write(path, text: str) -> str:
    path.write_text(text)
    return str(path)


def _sparse(path, size: int) -> str:
    """A file of ``size`` bytes that takes no room: its size alone is past the bound."""
    with open(path, "wb") as fh:
        fh.truncate(size)
    return str(path)


def _fifo(path) -> str:
    os.mkfifo(path)
    return str(path)


def _bipyramid(directory, n: int) -> str:
    """Two apexes of valence ``n`` over a ring of ``n`` points: the apex 0 is interior."""
    import math

    ring = [f"v {math.cos(2 * math.pi * k / n):.17g} {math.sin(2 * math.pi * k / n):.17g} 0\n" for k in range(n)]
    faces = [f"f 1 {k + 3} {(k + 1) % n + 3}\n" for k in range(n)] + [f"f 2 {(k + 1) % n + 3} {k + 3}\n" for k in range(n)]
    return _write(directory / "fan.obj", "v 0 0 1\nv 0 0 -1\n" + "".join(ring + faces))


#: A call one step past each bound: a command line (a list), or a function of the API.
CASES = {
    "digits": ["spectrum", "5", "--digits", _over("digits")],
    "dps": ["check", "--n", "5", "--dps", _over("dps")],
    "check --dps (triangle schemes, --rings > 1)": ["check", "--n", "5", "--scheme", "loop", "--dps",
                                                    _over("check --dps (triangle schemes, --rings > 1)")],
    "spectrum": ["spectrum", _over("spectrum")],
    "masks": ["masks", _over("masks")],
    "charpoly": ["charpoly", _over("charpoly")],
    "tune": ["tune", _over("tune")],
    "tune --table": ["tune", _over("tune --table"), "--table"],
    "check": ["check", "--n", _over("check")],
    "check --certify": ["check", "--n", _over("check --certify"), "--certify", "--route", "charpoly"],
    "check --certify --route structural": ["check", "--n", _over("check --certify --route structural"), "--certify"],
    "design": ["design", "--n", _over("design")],
    "oracle": ["oracle", "--n", _over("oracle")],
    "levels": ["oracle", "--levels", _over("levels")],
    "jobs": ["check", "--n", "5", "--jobs", _over("jobs")],
    "c1": ["c1", "--n", _over("c1")],
    "artifacts": ["artifacts", "--n", _over("artifacts")],
    "artifacts --n A:B": ["artifacts", "--n", "3:2000"],
    "c1 --k": ["c1", "--boundary", "--k", _over("c1 --k")],
    "c1 --depth": ["c1", "--n", "5", "--depth", _over("c1 --depth")],
    "rings": ["spectrum", "5", "--rings", _over("rings")],
    "budget": ["claims", "--budget", _over("budget")],
    "report": ["report", "--n", _over("report")],
    "--boundary, --corner, --crease, --dart: faces": ["spectrum", _over("--boundary, --corner, --crease, --dart: faces"),
                                                      "--dart"],
    "--boundary, --corner, --crease: faces by the blocks": ["spectrum", "2000", "--crease",
                                                            str(_over("--boundary, --corner, --crease: faces by the blocks", int) - 2000)],
    "evaldata --k": ["evaldata", "--boundary", "--k", _over("evaldata --k")],
    "evaldata": ["evaldata", "--n", _over("evaldata")],
    "artifact_indicators(n)": lambda: artifact_indicators(catmull_clark(), LIMITS["artifact_indicators(n)"][0] + 1),
    "second_order_eigenstructure(n)": lambda: second_order_eigenstructure(
        catmull_clark(), LIMITS["second_order_eigenstructure(n)"][0] + 1),
    "c1_test(n)": lambda: c1_test(catmull_clark(), _over("c1_test(n)", int)),
    "classify_shape(n)": lambda: classify_shape(catmull_clark(), _over("classify_shape(n)", int)),
    "closed_form_spectrum(n)": lambda: closed_form_spectrum(catmull_clark(), _over("closed_form_spectrum(n)", int)),
    "ring_spectrum(n)": lambda: ring_spectrum(catmull_clark(), _over("ring_spectrum(n)", int)),
    "ring_masks(n)": lambda: ring_masks(catmull_clark(), _over("ring_masks(n)", int)),
    "certify_ring(n)": lambda: certify_ring(catmull_clark(), _over("certify_ring(n)", int)),
    "patch_matrices(n)": lambda: patch_matrices(catmull_clark(), _over("patch_matrices(n)", int)),
    "jordan_block_size(n)": lambda: jordan_block_size(catmull_clark(), LIMITS["jordan_block_size(n)"][0] + 1, "1/4"),
    "jordan_vertex_weights(n)": lambda: __import__("symdecomp").jordan_vertex_weights(
        catmull_clark(ALPHA, BETA), LIMITS["jordan_vertex_weights(n)"][0] + 1, "1/4"),
    # phi(7) = 6 > 4: the exact signs of n = 7 take minutes; the forms themselves stay cheap
    "tune --region, interval_region, placed_points: phi(n)": lambda: interval_region(
        tuning_region(catmull_clark(ALPHA, __import__("sympy").Rational(1, 16)), 7)),
}



def _peer(first: bytes | None):
    """Ask a local peer for a scheduler's greeting: it sends ``first`` (``None``: nothing) and then stays silent."""
    server = socket.create_server(("127.0.0.1", 0))
    held = []

    def serve():
        conn, _ = server.accept()
        held.append(conn)
        if first is not None:
            conn.sendall(first)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        probe_scheduler(f"tcp://127.0.0.1:{server.getsockname()[1]}", "--executor dask=...")
    finally:
        thread.join(5)
        for conn in held:
            conn.close()
        server.close()


CASES.update({
    "--executor dask=ADDRESS: seconds of each exchange": lambda: _peer(None),  # refused after the bound itself
    "--executor dask=ADDRESS: bytes of the greeting": lambda: _peer(struct.pack("Q", _over("--executor dask=ADDRESS: "
                                                                                           "bytes of the greeting", int))),
    "masks --boundary, ... (sharp_masks): unknowns of a mask's system": ["masks", "40", "--dart"],  # 81 x 16 = 1296
    "refine --steps (refine_mesh)": ["refine", "m.obj", "--steps", _over("refine --steps (refine_mesh)"), "--out", "o.obj"],
    "design_ring(n)": lambda: __import__("symdecomp").design_ring(catmull_clark(), _over("design_ring(n)", int), normal=(0, 0, 1)),
})

#: Cases that need files: a function of a fresh directory, giving the command line.
FILE_CASES = {
    "design --position, --elliptic, --hyperbolic: magnitude": lambda d: [*DESIGN, "--out", str(d / "o.obj"), "--elliptic",
                                                                         _over("design --position, --elliptic, --hyperbolic: magnitude")],
    "design --angle: magnitude (radians)": lambda d: [*DESIGN, "--out", str(d / "o.obj"), "--hyperbolic", "1", "--angle",
                                                      _over("design --angle: magnitude (radians)")],
    "design --normal, --tangent: integer entries of the direction": lambda d: [
        *DESIGN, "--out", str(d / "o.obj"), "--tangent", _over("design --normal, --tangent: integer entries of the direction") + ",1,0"],
    "mesh (inspect, design --mesh, refine, API): valence of an analysed vertex": lambda d: [
        "design", "--mesh", _bipyramid(d, LIMITS["mesh (inspect, design --mesh, refine, API): valence of an analysed "
                                               "vertex"][0] + 1), "--vertex", "0", "--normal", "0,0,1", "--out", str(d / "o.obj")],
    "mesh: magnitude of a coordinate": lambda d: ["inspect", _write(d / "m.obj", SQUARE + "v 1.8e308 0 0\nf 1 2 3 4\n")],
    "mesh: characters of one number": lambda d: ["inspect", _write(d / "m.obj", SQUARE + "v 0." + "1" * (
        LIMITS["mesh: characters of one number"][0] - 1) + " 0 0\nf 1 2 3 4\n")],
    "mesh, OBJ: bytes of a line": lambda d: [
        "refine", "--out", str(d / "o.obj"), _write(d / "m.obj", SQUARE + "#" * _over("mesh, OBJ: bytes of a line", int) + "\nf 1 2 3 4\n")],
    "mesh, PLY: bytes of the header": lambda d: ["inspect", _write(d / "m.ply", "ply\nformat ascii 1.0\ncomment " + "x" * LIMITS[
        "mesh, PLY: bytes of the header"][0] + "\nend_header\n")],
    "scheme file: bytes": lambda d: ["spectrum", "5", "--scheme", _write(d / "big.toml", "#" * _over("scheme file: bytes", int))],
    "mesh: bytes of a file": lambda d: ["inspect", _sparse(d / "m.obj", LIMITS["mesh: bytes of a file"][0] + 1)],
    "design --mesh: magnitude of a ring's coordinates (and 1/extent)": lambda d: [
        "design", "--mesh", _write(d / "big.obj", SCALED_CUBE), "--vertex", "0", "--normal", "0,0,1", "--out", str(d / "o.obj")],
    "--out FIFO: seconds to wait for its reader": lambda d: [*DESIGN, "--out", _fifo(d / "out.obj")],
}

#: What the refusal says, where it is not the bound itself (a time limit is shown in minutes).
SAYS = {"artifacts --n A:B": "more than the limit of 10 minutes", "tune --region, interval_region, placed_points: phi(n)": "> 4",
        "--executor dask=ADDRESS: seconds of each exchange": "sent nothing more for 10 s",
        "--executor dask=ADDRESS: bytes of the greeting": "not a Dask scheduler (it sent b'\\x01\\x00\\x01",
        "design --position, --elliptic, --hyperbolic: magnitude": "at most 1e+06 in magnitude",
        "design --angle: magnitude (radians)": "at most 1e+06 in magnitude",
        "design --normal, --tangent: integer entries of the direction": "needs integers beyond 1e+15",
        "mesh: magnitude of a coordinate": "at most 1.798e+308 in magnitude",
        "design --mesh: magnitude of a ring's coordinates (and 1/extent)": "1e+12 in magnitude",
        "--out FIFO: seconds to wait for its reader": "waited 2 s"}


def test_every_bound_has_a_case():
    assert set(LIMITS) == set(CASES) | set(FILE_CASES), f"rows without a case: {sorted(set(LIMITS) - set(CASES) - set(FILE_CASES))}"
    assert not set(CASES) & set(FILE_CASES)


@pytest.mark.slow
@pytest.mark.parametrize("key", sorted(CASES) + sorted(FILE_CASES))
def test_each_bound_is_enforced_at_once(key, capsys, tmp_path):
    start = time.monotonic()
    case = CASES[key] if key in CASES else FILE_CASES[key](tmp_path)
    says = SAYS.get(key, str(LIMITS[key][0]))
    if callable(case):
        with pytest.raises(SymdecompError) as refused:
            case()
        message = str(refused.value)
    else:
        code = main(case)
        err = capsys.readouterr().err.strip()
        assert code == 2, err
        assert "\n" not in err and "internal error" not in err, err
        message = err
    assert says in message, message
    assert time.monotonic() - start < 30  # refused before the work, not after it


def test_placed_points_share_the_region_bound():
    with pytest.raises(SymdecompError, match=r"phi\(n\) = 6 > 4"):
        placed_points(catmull_clark(ALPHA, BETA), 7)
