"""Time ``symdecomp inspect`` on large meshes beside the time to load the same file with numpy.

Two meshes are generated here (nothing is downloaded), written as binary PLY with coordinates on a 2^-20 grid:

* a bunny-sized triangle mesh: an icosahedron refined 6 times on the unit sphere (81,920 triangles) with random
  edge flips, so that about a fifth of its vertices get valence 5, 7 or more (a scan's mix of extraordinary
  vertices), Loop's scheme: target 10 s and 1 GB;
* a one-million-face quad mesh: a cube's faces each split into 409 x 409 quads, projected on the sphere
  (1,003,086 quads, eight valence-3 vertices), Catmull-Clark: target 60 s and 2 GB.

Each run is a child process (``symdecomp inspect MESH --json``, its output discarded), timed wall-clock with its
peak resident memory; the baseline is ``numpy.fromfile`` of the same PLY's vertex and face blocks in a child of its
own. Run from the repository root:

    python benchmarks/bench_meshes.py            # both meshes (minutes on 2 cores)
    python benchmarks/bench_meshes.py --quick    # 5,120 triangles and 24,576 quads
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

#: Runs ``python ARGV`` and prints [exit code, wall seconds, peak MB of the child, its stderr's last line].
LAUNCHER = r"""
import json, resource, subprocess, sys, time
start = time.perf_counter()
run = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
wall = time.perf_counter() - start
mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
print(json.dumps([run.returncode, wall, mb, (run.stderr.strip().splitlines() or [""])[-1]]))
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


def icosphere(levels: int, flips: float, seed: int = 0):
    """Points and triangles of a refined icosahedron on the unit sphere, with a fraction ``flips`` of edges flipped."""
    t = (1 + 5**0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
             (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]
    points = [np.array(p, dtype=float) / np.linalg.norm(p) for p in points]
    for _ in range(levels):
        middle, new = {}, []
        for a, b, c in faces:
            m = []
            for u, v in ((a, b), (b, c), (c, a)):
                key = (min(u, v), max(u, v))
                if key not in middle:
                    middle[key] = len(points)
                    mid = points[u] + points[v]
                    points.append(mid / np.linalg.norm(mid))
                m.append(middle[key])
            new += [(a, m[0], m[2]), (m[0], b, m[1]), (m[2], m[1], c), (m[0], m[1], m[2])]
        faces = new
    return _flip(np.array(points), faces, flips, seed)


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
    index, points, faces = {}, [], []

    def vertex(p):
        key = tuple(int(c) for c in p)
        if key not in index:
            index[key] = len(points)
            points.append(p)
        return index[key]

    for axis in range(3):
        for sign in (-1, 1):
            u, v = [a for a in range(3) if a != axis]
            grid = np.empty((m + 1, m + 1), dtype=np.int64)
            for i in range(m + 1):
                for j in range(m + 1):
                    p = np.zeros(3)
                    p[axis], p[u], p[v] = sign * m, 2 * i - m, 2 * j - m
                    grid[i, j] = vertex(p)
            for i in range(m):
                for j in range(m):
                    q = (grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1])
                    faces.append(q if sign > 0 else q[::-1])
    pts = np.array(points, dtype=float)
    return pts / np.linalg.norm(pts, axis=1)[:, None], _outward(pts, faces)


def _outward(points, faces):
    """Each quad turned counter-clockwise seen from outside (its normal along its centre)."""
    out = []
    for f in faces:
        p = points[list(f)]
        if np.dot(np.cross(p[1] - p[0], p[2] - p[0]), p.mean(axis=0)) < 0:
            f = f[::-1]
        out.append(tuple(int(x) for x in f))
    return out


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


def _child(argv: list[str]) -> tuple[float, float, str]:
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-c", LAUNCHER, sys.executable, *argv], cwd=ROOT, env=env, capture_output=True, text=True)
    code, wall, mb, last = json.loads(out.stdout)
    if code not in (0, 1):
        raise RuntimeError(f"{' '.join(argv)} failed ({code}): {last}")
    return wall, mb, last


def targets(quick: bool = False) -> list[dict]:
    """The two meshes of the module docstring (smaller with ``quick``, without targets)."""
    cases = [("bunny-sized triangles (Loop)", lambda: icosphere(4 if quick else 6, 0.1), BUNNY_TARGET),
             ("quad mesh (Catmull-Clark)", lambda: quad_sphere(64 if quick else 409), MILLION_TARGET)]
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for name, make, (seconds, megabytes) in cases:
            points, faces = make()
            path = os.path.join(folder, "mesh.ply")
            write_ply(path, points, faces)
            wall, mb, _ = _child(["-m", "symdecomp", "inspect", path, "--json"])
            base_wall, base_mb, _ = _child(["-c", NUMPY_LOAD, path])
            out.append({"target": f"inspect: {name}, {len(faces)} faces", "limit_seconds": None if quick else seconds,
                        "seconds": round(wall, 2), "megabytes": round(mb, 1), "limit_megabytes": None if quick else megabytes,
                        "baseline": "numpy load of the same PLY", "baseline_seconds": round(base_wall, 2),
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
