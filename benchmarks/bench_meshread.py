"""Time and memory of reading and checking large meshes (``read_mesh``), beside the line-by-line reader.

The targets (issues 31 and 35): a 100,000-triangle OBJ read and checked in about 2 s; a 1,000,000-face
quad OBJ in about 20 s and under 1.5 GB (main took 116 s and 2.3 GB). The meshes are tori made here
(no download): a 250 x 200 grid of triangle pairs and a 1000 x 1000 grid of quads, coordinates with 9
decimals. Each read runs in a child process, so that its peak resident memory is its own; the figure
beside it is :func:`symdecomp.validate.mesh_memory`'s estimate, which ``read_mesh`` checks before reading.

The baseline of the OBJ files is the same read through the package's line-by-line OBJ reader (the one
that names a bad line; every line parsed in Python, exact coordinates built for every vertex), which is
what reading cost before the fast path. A third target (issue 35, item 6: a 61 MiB binary PLY of 1.56M
faces ran out of memory after 181 s at 3.6 GB) reads a 1.56M-triangle binary PLY beside ``plyfile``
reading the same bytes (the parsing alone, no checks).

    python benchmarks/bench_meshread.py            # both targets
    python benchmarks/bench_meshread.py --quick    # a 10,000-triangle and a 40,000-quad torus
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))

from symdecomp.validate import mesh_memory  # noqa: E402

#: ``(name, grid m x n, faces of a grid cell, limit seconds, limit megabytes)``.
CASES = (("triangles", (250, 200), 2, 2.0, None), ("quads", (1000, 1000), 1, 20.0, 1536.0), ("ply", (1000, 780), 2, 20.0, 1536.0))
QUICK = {"triangles": (50, 100), "quads": (200, 200), "ply": (100, 100)}
BASELINE = "the line-by-line OBJ reader (every line parsed in Python, exact coordinates for every vertex)"

_CHILD = """
import resource, sys, time
sys.path.insert(0, {root!r})
from symdecomp.schemes import mesh_obj
if {slow} == "plyfile":
    import plyfile
    start, cpu = time.perf_counter(), time.process_time()
    ply = plyfile.PlyData.read({path!r})
    print(time.perf_counter() - start, time.process_time() - cpu, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
          len(ply["face"].data))
    sys.exit(0)
if {slow}:
    mesh_obj._fast = lambda lines, name: (_ for _ in ()).throw(mesh_obj._Irregular())
from symdecomp.schemes.meshformats import read_mesh
start, cpu = time.perf_counter(), time.process_time()
mesh = read_mesh({path!r})
print(time.perf_counter() - start, time.process_time() - cpu, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
      len(mesh.faces))
"""


def torus(path: str, m: int, n: int, triangles: bool) -> None:
    """An ``m x n`` torus grid as OBJ: quads, or each quad as two triangles."""
    with open(path, "w", encoding="ascii") as out:
        for i in range(m):
            a = 2 * math.pi * i / m
            for j in range(n):
                b = 2 * math.pi * j / n
                r = 3 + math.cos(b)
                out.write(f"v {r * math.cos(a):.9f} {r * math.sin(a):.9f} {math.sin(b):.9f}\n")
        for i in range(m):
            for j in range(n):
                p, q, r, s = (i * n + j + 1, (i + 1) % m * n + j + 1, (i + 1) % m * n + (j + 1) % n + 1, i * n + (j + 1) % n + 1)
                out.write(f"f {p} {q} {r}\nf {p} {r} {s}\n" if triangles else f"f {p} {q} {r} {s}\n")


def binary_ply(path: str, m: int, n: int) -> None:
    """An ``m x n`` torus grid of triangle pairs as a binary little-endian PLY (float coordinates, int indices)."""
    import numpy as np

    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    quads = np.stack([(i % m) * n + j % n, (i + 1) % m * n + j % n, (i + 1) % m * n + (j + 1) % n, i * n + (j + 1) % n], -1).reshape(-1, 4)
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    a, b = np.meshgrid(2 * np.pi * np.arange(m) / m, 2 * np.pi * np.arange(n) / n, indexing="ij")
    r = 3 + np.cos(b)
    points = np.stack([r * np.cos(a), r * np.sin(a), np.sin(b)], -1).reshape(-1, 3).astype("<f4")
    faces = np.zeros(len(tris), dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"], faces["v"] = 3, tris
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\nproperty float x\nproperty float y\n"
            f"property float z\nelement face {len(tris)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as out:
        out.write(head.encode("ascii") + points.tobytes() + faces.tobytes())


def _child(path: str, slow) -> tuple[float, float, float, int]:
    code = _CHILD.format(root=os.path.join(HERE, ".."), slow=repr(slow), path=path)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    wall, cpu, mb, faces = run.stdout.split()
    return float(wall), float(cpu), float(mb), int(faces)


def _estimate(path: str, name: str, faces: int) -> int:
    if name != "ply":
        return mesh_memory(file_bytes=os.path.getsize(path))
    return os.path.getsize(path) + mesh_memory(corners=3 * faces, faces=faces, vertices=faces // 2)


def targets(quick: bool = False) -> list[dict]:
    """One dict per mesh: the read beside the line-by-line reader."""
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for name, grid, per_cell, limit, limit_mb in CASES:
            m, n = QUICK[name] if quick else grid
            path = os.path.join(folder, f"{name}.{'ply' if name == 'ply' else 'obj'}")
            binary_ply(path, m, n) if name == "ply" else torus(path, m, n, per_cell == 2)
            wall, cpu, mb, faces = _child(path, slow=False)
            base_wall, _, base_mb, _ = _child(path, slow="plyfile" if name == "ply" else True)
            out.append({
                "target": f"read_mesh of a {faces}-face {'triangle' if name == 'ply' else name} torus "
                          f"{'binary PLY' if name == 'ply' else 'OBJ'} ({os.path.getsize(path)} bytes)",
                "limit_seconds": None if quick else limit, "seconds": round(wall, 2), "cpu_seconds": round(cpu, 2),
                "megabytes": round(mb, 1), "limit_megabytes": None if quick else limit_mb,
                "estimated_megabytes": round(_estimate(path, name, faces) / 2**20, 1),
                "baseline": "plyfile.PlyData.read of the same file (parsing only)" if name == "ply" else BASELINE,
                "baseline_seconds": round(base_wall, 2), "baseline_megabytes": round(base_mb, 1),
            })
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small tori instead of the targets' sizes")
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, load {os.getloadavg()[0]:.1f}")
    for t in targets(args.quick):
        print(f"{t['target']}: {t['seconds']:.2f} s wall, {t['cpu_seconds']:.2f} s CPU, {t['megabytes']:.0f} MB peak "
              f"(estimated {t['estimated_megabytes']:.0f} MB)")
        print(f"  baseline ({t['baseline']}): {t['baseline_seconds']:.2f} s, {t['baseline_megabytes']:.0f} MB")
        if t["limit_seconds"] is not None:
            met = t["seconds"] <= t["limit_seconds"] and (t["limit_megabytes"] is None or t["megabytes"] <= t["limit_megabytes"])
            print(f"  target <= {t['limit_seconds']:.0f} s" + (f" and <= {t['limit_megabytes']:.0f} MB" if t["limit_megabytes"] else "")
                  + f": {'met' if met else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
