"""Time ``symdecomp inspect`` on large meshes beside the time trimesh takes to load the same file.

The meshes are generated here (nothing is downloaded), with coordinates on a 2^-20 grid:

* a stand-in for the repaired Stanford bunny: a triangulated 251 x 203 torus (101,906 triangles, 50,953 vertices;
  the repaired bunny has 101,754) with 7 % of its edges flipped at random, so that about half of its vertices
  (25,700; the bunny about 25,000) get valence 4, 5, 7 or more, Loop's scheme: target 10 s and 1 GB;
* a stand-in for the bunny as scanned: the same torus with five holes cut into it and three faces added on edges
  that two faces already share (the scan's defect: edges of three faces). ``inspect`` must analyse the rest, list
  the three edges as non-manifold and exit 1; the same target;
* a one-million-face quad mesh: OpenSubdiv's car shape (``catmark_car``, in the tests' shapes) split five times
  (1,612,800 quads, 10,048 crease edges of sharpness 1: the topology and tags of five Catmull-Clark steps), as an OBJ
  with its ``t crease`` lines, Catmull-Clark: target 60 s and 2 GB.

And the real scan, when it is on the machine: the Stanford bunny as the Stanford 3D Scanning Repository ships it
(``bunny/reconstruction/bun_zipper.ply`` in its ``bunny.tar.gz``: 35,947 vertices, 69,451 triangles, five holes and
1,113 vertices in no triangle), looked for in the folder ``$SYMDECOMP_MESH_CACHE`` (default ``~/.cache/symdecomp/meshes``;
it is not downloaded here, nor shipped: the docs' guide page "Real meshes" says how to get it). Without it the row
says where it looked; with it, the same target as the repaired bunny and the report checked: exit 1, every vertex in a
triangle analysed, the isolated vertices listed.

Each run is a child process (``symdecomp inspect MESH --json``), timed wall-clock with its peak resident memory;
the baseline is ``trimesh.load`` of the same file in a child of its own (the row says so where trimesh is not
installed). The two bunny stand-ins are binary PLY files, the car an OBJ. Run from the repository root:

    python benchmarks/bench_meshes.py            # the three meshes (minutes on 2 cores)
    python benchmarks/bench_meshes.py --quick    # a 40 x 30 torus and the car split twice (25,200 quads)
"""

from __future__ import annotations

import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

#: The issue's targets: (seconds, megabytes).
BUNNY_TARGET, MILLION_TARGET = (10.0, 1024.0), (60.0, 2048.0)

#: Runs ``python ARGV`` with stdout to the file ``argv[1]`` and prints [exit code, wall seconds, peak MB of the child,
#: its stderr's last line].
LAUNCHER = r"""
import json, resource, subprocess, sys, time
start = time.perf_counter()
with open(sys.argv[1], "wb") as out:
    run = subprocess.run(sys.argv[2:], stdout=out, stderr=subprocess.PIPE, text=True)
wall = time.perf_counter() - start
mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
print(json.dumps([run.returncode, wall, mb, (run.stderr.strip().splitlines() or [""])[-1]]))
"""

#: The baseline: trimesh's load of the same file (its own reader, vertices merged, as a user of trimesh gets it).
TRIMESH_LOAD = r"""
import sys, trimesh
mesh = trimesh.load(sys.argv[1])
assert len(mesh.faces) >= int(sys.argv[2])
"""

def torus(m: int, n: int, flips: float, holes: int = 0, fins: int = 0, seed: int = 0):
    """A triangulated ``m x n`` torus grid, ``holes`` holes cut into it, a fraction ``flips`` of its edges flipped and
    ``fins`` triangles added on edges that two faces already share: ``(points, faces, fin edges)``.

    A hole is the faces at a 4 x 4 block of grid vertices (cut before the flips, so its rim is one loop); a fin is a
    third face on an interior edge (the scanner's defect: an edge of three faces), listed last as a reader meets it.
    """
    u, v = np.meshgrid(2 * np.pi * np.arange(m) / m, 2 * np.pi * np.arange(n) / n, indexing="ij")
    points = np.stack([(1 + 0.4 * np.cos(v)) * np.cos(u), (1 + 0.4 * np.cos(v)) * np.sin(u), 0.4 * np.sin(v)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    a, b, c, d = i * n + j, (i + 1) % m * n + j, (i + 1) % m * n + (j + 1) % n, i * n + (j + 1) % n
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    p = points[tris]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    angle = np.arctan2(p[:, :, 1].mean(1), p[:, :, 0].mean(1))
    outward = p.mean(1) - np.stack([np.cos(angle), np.sin(angle), 0 * angle], -1)  # from the core circle
    turn = np.einsum("ij,ij->i", normal, outward) < 0
    tris[turn] = tris[turn][:, ::-1]  # counter-clockwise seen from outside
    cut = np.zeros(m * n, dtype=bool)
    for k in range(holes):
        x, y = (k + 1) * m // (holes + 1), (3 * k + 1) * n // (3 * holes + 1)
        cut[((x + np.arange(4)[:, None]) % m * n + (y + np.arange(4)) % n).ravel()] = True
    tris = tris[~cut[tris].any(axis=1)]
    used, tris = np.unique(tris, return_inverse=True)  # the vertices of a hole go with it (a scan has none there)
    points, faces = _flip(points[used], [tuple(t) for t in tris.reshape(-1, 3).tolist()], flips, seed)
    shared = _interior_edges(faces)
    rng = random.Random(seed + 1)
    edges = sorted(rng.sample(shared, fins))
    extra = [(x, y, (x + len(points) // 2) % len(points)) for x, y in edges]  # a third face on (x, y), its apex far away
    return points, faces + extra, [tuple(sorted(e)) for e in edges]


def _interior_edges(faces) -> list[tuple[int, int]]:
    """The directed edges ``(x, y)`` of the faces whose reverse ``(y, x)`` is an edge too (two faces share them)."""
    directed = {(f[k], f[(k + 1) % 3]) for f in faces for k in range(3)}
    return sorted(e for e in directed if e[::-1] in directed and e[0] < e[1])


def _flip(points, faces, fraction: float, seed: int):
    """Flip a random ``fraction`` of the edges whose ends keep valence >= 4 (so no valence-3 pinch appears)."""
    rng = random.Random(seed)
    faces = [list(f) for f in faces]
    owner = {}
    for i, f in enumerate(faces):
        for k in range(3):
            owner[(f[k], f[(k + 1) % 3])] = i
    valence = np.bincount(np.array(faces).ravel(), minlength=len(points))
    edges = [e for e in owner if e[0] < e[1]]
    for u, v in rng.sample(edges, int(fraction * len(edges))):
        if (u, v) not in owner or (v, u) not in owner or valence[u] <= 4 or valence[v] <= 4:
            continue
        f, g = owner.pop((u, v)), owner.pop((v, u))
        x = next(w for w in faces[f] if w not in (u, v))
        y = next(w for w in faces[g] if w not in (u, v))
        if (x, y) in owner or (y, x) in owner:
            owner[(u, v)], owner[(v, u)] = f, g
            continue
        for a, b in ((v, x), (x, u), (u, y), (y, v)):
            owner.pop((a, b), None)
        faces[f], faces[g] = [u, y, x], [v, x, y]
        for i in (f, g):
            for k in range(3):
                owner[(faces[i][k], faces[i][(k + 1) % 3])] = i
        valence[u] -= 1
        valence[v] -= 1
        valence[x] += 1
        valence[y] += 1
    return points, faces


CAR = os.path.join(ROOT, "tests", "verify", "opensubdiv_shapes", "catmark_car.obj")


def car(steps: int):
    """OpenSubdiv's car shape (1,575 quads, 314 crease edges of sharpness 6) split ``steps`` times: every quad into
    four at its edge midpoints and centroid (the topology of as many Catmull-Clark steps, positions bilinear), each
    crease edge into two of sharpness one less (its decay). ``(points, quads, {edge: sharpness})``."""
    sys.path.insert(0, ROOT)
    from symdecomp.schemes.meshformats import read_mesh

    mesh = read_mesh(CAR)
    points, quads = mesh.points_array, np.array(mesh.faces, dtype=np.int64)
    creases = {e: float(s) for e, s in mesh.tags.creases.items()}
    for _ in range(steps):
        V, F = len(points), len(quads)
        ends = np.stack([quads, np.roll(quads, -1, axis=1)], -1).reshape(-1, 2)  # edge k of a face: corner k to k + 1
        lo, hi = ends.min(axis=1), ends.max(axis=1)
        keys, edge = np.unique(lo * V + hi, return_inverse=True)
        edge = edge.reshape(F, 4) + V
        centre = V + len(keys) + np.arange(F)
        a, b = keys // V, keys % V
        points = np.concatenate([points, (points[a] + points[b]) / 2, points[quads].mean(axis=1)])
        before = np.roll(edge, 1, axis=1)  # the edge from corner k - 1 to corner k
        quads = np.stack([quads, edge, np.repeat(centre[:, None], 4, axis=1), before], -1).reshape(-1, 4)
        middle = dict(zip(keys.tolist(), range(V, V + len(keys))))
        creases = {tuple(sorted((x, middle[u * V + v]))): s - 1 for (u, v), s in creases.items() for x in (u, v)}
    return points, quads, creases


def write_obj(path: str, points, faces, creases) -> None:
    """OBJ with OpenSubdiv's ``t crease`` lines; coordinates on a 2^-20 grid as in :func:`write_ply`."""
    points = np.round(np.asarray(points) * 2**20) / 2**20
    with open(path, "w") as fh:
        fh.write("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in points.tolist()))
        fh.write("".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in np.asarray(faces).tolist()))
        fh.write("".join(f"t crease 2/1/0 {u} {v} {s}\n" for (u, v), s in creases.items()))


def write_ply(path: str, points, faces) -> None:
    """Binary PLY with doubles on a 2^-20 grid (exact in a double; small denominators for the exact reader)."""
    points = np.round(np.asarray(points) * 2**20) / 2**20
    k = len(faces[0])
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\nproperty double x\nproperty double y\n"
              f"property double z\nelement face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    block = np.zeros(len(faces), dtype=np.dtype([("k", "u1"), ("v", "<i4", k)]))
    block["k"], block["v"] = k, np.asarray(faces)
    with open(path, "wb") as fh:
        fh.write(header.encode("ascii") + points.astype("<f8").tobytes() + block.tobytes())


def _child(argv: list[str], output: str = os.devnull) -> tuple[float, float, str]:
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-c", LAUNCHER, output, sys.executable, *argv], cwd=ROOT, env=env,
                         capture_output=True, text=True)
    code, wall, mb, last = json.loads(out.stdout)
    if code not in (0, 1):
        raise RuntimeError(f"{' '.join(argv)} failed ({code}): {last}")
    return wall, mb, last


def _baseline(path: str, faces: int) -> tuple[str, float | None, float | None]:
    try:
        import trimesh  # noqa: F401  (only whether it is there: it is loaded in the child)
    except ImportError:
        return "trimesh's load (not installed here: pip install trimesh)", None, None
    return ("trimesh.load of the same file",) + _child(["-c", TRIMESH_LOAD, path, str(faces)])[:2]


def _scan_check(report: dict, fins: list) -> str:
    """The scan stand-in's check: exit 1, the fins' edges listed as non-manifold, every vertex in a face analysed."""
    defects = report["defects"]
    listed = sorted(tuple(e) for e in defects["non_manifold_edges"])
    if report["exit_status"] != 1 or listed != fins or report["not_analysed"]:
        raise RuntimeError(f"the scan stand-in: exit {report['exit_status']}, non-manifold edges {listed} (added {fins}), "
                           f"{len(report['not_analysed'])} vertices not analysed")
    return f"exit 1, non-manifold edges {listed}, {len(defects['dropped_faces'])} faces left out"


#: The Stanford bunny as shipped: its file name in the cache folder, its vertices and triangles (the PLY header's).
SHIPPED_BUNNY = ("bun_zipper.ply", 35947, 69451)
#: Where to get it (the guide page "Real meshes" has the steps).
BUNNY_SOURCE = "https://graphics.stanford.edu/data/3Dscanrep/ (bunny.tar.gz: bunny/reconstruction/bun_zipper.ply)"


def cache_folder() -> str:
    """The folder where downloaded meshes are looked for: ``$SYMDECOMP_MESH_CACHE``, else ``~/.cache/symdecomp/meshes``."""
    return os.environ.get("SYMDECOMP_MESH_CACHE") or os.path.join(os.path.expanduser("~"), ".cache", "symdecomp", "meshes")


def _bunny_check(report: dict) -> str:
    """The shipped bunny's check: its header's counts, exit 1, every vertex with a verdict, and only the vertices in no
    triangle without a limit point (off the surface), and why."""
    name, vertices, faces = SHIPPED_BUNNY
    isolated = report["defects"]["isolated_vertices"]
    if (report["vertices"], report["faces"]) != (vertices, faces):
        raise RuntimeError(f"{name} in the cache has {report['vertices']} vertices and {report['faces']} faces, not the "
                           f"shipped scan's {vertices} and {faces}")
    off = sorted(int(v) for v, why in report["no_limit"].items() if why.startswith("no point on the limit surface: in no face"))
    if report["exit_status"] != 1 or report["not_analysed"] or off != sorted(isolated) or len(report["no_limit"]) != len(off):
        raise RuntimeError(f"{name}: exit {report['exit_status']}, {len(report['not_analysed'])} vertices not analysed, "
                           f"{len(report['no_limit'])} without a limit point, {len(isolated)} isolated")
    defects = {k: len(v) for k, v in report["defects"].items() if v}
    return "exit 1, " + ", ".join(f"{k.replace('_', ' ')} {v}" for k, v in sorted(defects.items()))


def shipped_bunny(quick: bool = False) -> dict:
    """The row of the Stanford bunny as shipped (module docstring), or a row saying why it was not measured."""
    name, _, faces = SHIPPED_BUNNY
    path = os.path.join(cache_folder(), name)
    row = {"limit_seconds": None, "seconds": None, "megabytes": None, "limit_megabytes": None, "baseline": None,
           "baseline_seconds": None, "baseline_megabytes": None}
    if quick or not os.path.isfile(path):
        why = "not in a quick run" if quick else f"not measured: no {name} in {cache_folder()} (get it from {BUNNY_SOURCE})"
        return dict(row, target=f"inspect: the Stanford bunny as shipped: {why}")
    with tempfile.TemporaryDirectory() as folder:
        report = os.path.join(folder, "report.json")
        wall, mb, _ = _child(["-m", "symdecomp", "inspect", path, "--json", "--quiet"], report)
        with open(report) as fh:
            data = json.load(fh)
    baseline, base_wall, base_mb = _baseline(path, faces)
    return dict(row, target=f"inspect: the Stanford bunny as shipped ({name}, Loop), {faces} faces ({_bunny_check(data)})",
                limit_seconds=BUNNY_TARGET[0], limit_megabytes=BUNNY_TARGET[1], seconds=round(wall, 2),
                megabytes=round(mb, 1), baseline=baseline, baseline_seconds=base_wall and round(base_wall, 2),
                baseline_megabytes=base_mb and round(base_mb, 1), file_bytes=os.path.getsize(path))


def targets(quick: bool = False) -> list[dict]:
    """The meshes of the module docstring (smaller with ``quick``, without targets)."""
    size = (40, 30) if quick else (251, 203)

    def scan(holes, fins):
        def write(path):
            points, faces, edges = torus(*size, 0.07, holes, fins)
            write_ply(path + ".ply", points, faces)
            return path + ".ply", len(faces), edges
        return write

    def quads(path):
        points, faces, creases = car(2 if quick else 5)
        write_obj(path + ".obj", points, faces, creases)
        return path + ".obj", len(faces), []

    cases = [("repaired-bunny stand-in, triangles (Loop)", scan(0, 0), BUNNY_TARGET),
             ("scanned-bunny stand-in, 5 holes and 3 edges of 3 faces (Loop)", scan(5, 3), BUNNY_TARGET),
             ("the car shape split into quads, with its creases (Catmull-Clark)", quads, MILLION_TARGET)]
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for k, (name, write, (seconds, megabytes)) in enumerate(cases):
            path, faces, fins = write(os.path.join(folder, f"mesh{k}"))
            report = os.path.join(folder, "report.json")
            wall, mb, _ = _child(["-m", "symdecomp", "inspect", path, "--json"], report)
            with open(report) as fh:
                data = json.load(fh)
            note = _scan_check(data, fins) if fins else f"exit {data['exit_status']}"
            baseline, base_wall, base_mb = _baseline(path, faces)
            out.append({"target": f"inspect: {name}, {faces} faces, {len(data['extraordinary'])} extraordinary vertices "
                                  f"({note})",
                        "limit_seconds": None if quick else seconds,
                        "seconds": round(wall, 2), "megabytes": round(mb, 1), "limit_megabytes": None if quick else megabytes,
                        "baseline": baseline, "baseline_seconds": base_wall and round(base_wall, 2),
                        "baseline_megabytes": base_mb and round(base_mb, 1), "file_bytes": os.path.getsize(path)})
            os.remove(path)
    return out + [shipped_bunny(quick)]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small meshes (a smoke run, no targets)")
    args = parser.parse_args(argv)
    rows = targets(quick=args.quick)
    for r in rows:
        limit = "" if r["limit_seconds"] is None else f" (target {r['limit_seconds']} s, {r['limit_megabytes']} MB)"
        if r["seconds"] is None:
            print(r["target"])
            continue
        print(f"{r['target']}: {r['seconds']} s, {r['megabytes']} MB{limit}; baseline {r['baseline']}: "
              f"{r['baseline_seconds']} s, {r['baseline_megabytes']} MB")
    met = all(r["limit_seconds"] is None or (r["seconds"] <= r["limit_seconds"] and r["megabytes"] <= r["limit_megabytes"])
              for r in rows)
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
