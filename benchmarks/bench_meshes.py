"""Time ``symdecomp inspect`` on large meshes beside the time trimesh takes to load the same file.

The meshes are generated here (nothing is downloaded), written as binary PLY with coordinates on a 2^-20 grid:

* a stand-in for the repaired Stanford bunny: a triangulated 251 x 203 torus (101,906 triangles, 50,953 vertices;
  the repaired bunny has 101,754) with 7 % of its edges flipped at random, so that about half of its vertices
  (25,700; the bunny about 25,000) get valence 4, 5, 7 or more, Loop's scheme: target 10 s and 1 GB;
* a stand-in for the bunny as scanned: the same torus with five holes cut into it and three faces added on edges
  that two faces already share (the scan's defect: edges of three faces). ``inspect`` must analyse the rest, list
  the three edges as non-manifold and exit 1; the same target;
* a one-million-face quad mesh: a cube's faces each split into 409 x 409 quads, projected on the sphere
  (1,003,686 quads, eight valence-3 vertices), Catmull-Clark: target 60 s and 2 GB.

Each run is a child process (``symdecomp inspect MESH --json``), timed wall-clock with its peak resident memory;
the baseline is ``trimesh.load`` of the same PLY in a child of its own (or, without trimesh, numpy reading the PLY's
vertex and face blocks; the row says which). Run from the repository root:

    python benchmarks/bench_meshes.py            # the three meshes (minutes on 2 cores)
    python benchmarks/bench_meshes.py --quick    # a 40 x 30 torus and 24,576 quads
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

#: The baseline: read the binary PLY's header, then its vertex and face blocks with numpy.
NUMPY_LOAD = r"""
import sys, numpy as np
data = open(sys.argv[1], "rb").read()
head, body = data.split(b"end_header\n", 1)
lines = head.decode().splitlines()
V = int(next(l for l in lines if l.startswith("element vertex")).split()[-1])
F = int(next(l for l in lines if l.startswith("element face")).split()[-1])
points = np.frombuffer(body, dtype="<f8", count=3 * V).reshape(V, 3)
k = body[24 * V]
faces = np.frombuffer(body[24 * V:], dtype=np.dtype([("k", "u1"), ("v", "<i4", k)]), count=F)["v"]
assert faces.shape == (F, k) and np.isfinite(points).all()
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


def quad_sphere(m: int):
    """A cube's faces each split into ``m x m`` quads, projected on the unit sphere (shared edges welded)."""
    grids, quads = [], []
    i, j = np.meshgrid(np.arange(m + 1), np.arange(m + 1), indexing="ij")
    for axis in range(3):
        for sign in (-1, 1):
            u, v = [a for a in range(3) if a != axis]
            p = np.zeros((m + 1, m + 1, 3), dtype=np.int64)
            p[..., axis], p[..., u], p[..., v] = sign * m, 2 * i - m, 2 * j - m
            at = sum(len(g) for g in grids) + i * (m + 1) + j
            grids.append(p.reshape(-1, 3))
            quads.append(np.stack([at[:-1, :-1], at[1:, :-1], at[1:, 1:], at[:-1, 1:]], -1).reshape(-1, 4))
    keys, weld = np.unique(np.concatenate(grids), axis=0, return_inverse=True)  # one vertex per lattice point
    faces = weld.ravel()[np.concatenate(quads)]
    p = keys[faces].astype(float)
    turn = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p.mean(axis=1)) < 0
    faces[turn] = faces[turn][:, ::-1]  # counter-clockwise seen from outside
    points = keys.astype(float)
    return points / np.linalg.norm(points, axis=1)[:, None], faces


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


def _baseline(path: str, faces: int) -> tuple[str, float, float]:
    try:
        import trimesh  # noqa: F401  (only whether it is there: it is loaded in the child)
    except ImportError:
        return ("numpy reading the PLY's blocks (trimesh is not installed)",) + _child(["-c", NUMPY_LOAD, path])[:2]
    return ("trimesh.load of the same PLY",) + _child(["-c", TRIMESH_LOAD, path, str(faces // 2)])[:2]


def _scan_check(report: dict, fins: list) -> str:
    """The scan stand-in's check: exit 1, the fins' edges listed as non-manifold, every vertex in a face analysed."""
    defects = report["defects"]
    listed = sorted(tuple(e) for e in defects["non_manifold_edges"])
    if report["exit_status"] != 1 or listed != fins or report["not_analysed"]:
        raise RuntimeError(f"the scan stand-in: exit {report['exit_status']}, non-manifold edges {listed} (added {fins}), "
                           f"{len(report['not_analysed'])} vertices not analysed")
    return f"exit 1, non-manifold edges {listed}, {len(defects['dropped_faces'])} faces left out"


def targets(quick: bool = False) -> list[dict]:
    """The meshes of the module docstring (smaller with ``quick``, without targets)."""
    size = (40, 30) if quick else (251, 203)
    cases = [("repaired-bunny stand-in, triangles (Loop)", lambda: torus(*size, 0.07), BUNNY_TARGET),
             ("scanned-bunny stand-in, 5 holes and 3 edges of 3 faces (Loop)", lambda: torus(*size, 0.07, 5, 3), BUNNY_TARGET),
             ("quad mesh (Catmull-Clark)", lambda: quad_sphere(64 if quick else 409) + ([],), MILLION_TARGET)]
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for name, make, (seconds, megabytes) in cases:
            points, faces, fins = make()
            path, report = os.path.join(folder, "mesh.ply"), os.path.join(folder, "report.json")
            write_ply(path, points, faces)
            wall, mb, _ = _child(["-m", "symdecomp", "inspect", path, "--json"], report)
            with open(report) as fh:
                data = json.load(fh)
            note = _scan_check(data, fins) if fins else f"exit {data['exit_status']}"
            baseline, base_wall, base_mb = _baseline(path, len(faces))
            out.append({"target": f"inspect: {name}, {len(faces)} faces, {len(data['extraordinary'])} extraordinary "
                                  f"vertices ({note})",
                        "limit_seconds": None if quick else seconds,
                        "seconds": round(wall, 2), "megabytes": round(mb, 1), "limit_megabytes": None if quick else megabytes,
                        "baseline": baseline, "baseline_seconds": round(base_wall, 2),
                        "baseline_megabytes": round(base_mb, 1), "file_bytes": os.path.getsize(path)})
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small meshes (a smoke run, no targets)")
    args = parser.parse_args(argv)
    rows = targets(quick=args.quick)
    for r in rows:
        limit = "" if r["limit_seconds"] is None else f" (target {r['limit_seconds']} s, {r['limit_megabytes']} MB)"
        print(f"{r['target']}: {r['seconds']} s, {r['megabytes']} MB{limit}; baseline {r['baseline']}: "
              f"{r['baseline_seconds']} s, {r['baseline_megabytes']} MB")
    met = all(r["limit_seconds"] is None or (r["seconds"] <= r["limit_seconds"] and r["megabytes"] <= r["limit_megabytes"])
              for r in rows)
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
