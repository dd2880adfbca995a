"""``inspect`` on a scan as it is shipped (issue 31): the Stanford bunny's PLY has holes and a few edges shared by three
faces. The file itself is not to be had here (no package on the reachable registries ships it: the npm package
``bunny`` holds a 3,674-triangle version without those edges), so a scan-like ASCII PLY is built with the same kinds
of defect: a triangulated torus with two holes cut into it and three faces added on edges that two faces already
share. The three edges are listed, the rest is analysed, the exit status is 1; ``--strict`` refuses the first one.
``benchmarks/bench_meshes.py`` runs the same at the bunny's size."""

import json

import numpy as np

from symdecomp.cli import main

M, N = 16, 12  # torus grid: vertex (i, j) is i * N + j


def scan(tmp_path):
    """The PLY file and, from its construction: the edges of three faces, the added faces' indices, the vertex count
    and the number of vertices on the holes' rims."""
    u, v = np.meshgrid(2 * np.pi * np.arange(M) / M, 2 * np.pi * np.arange(N) / N, indexing="ij")
    points = np.stack([(3 + np.cos(v)) * np.cos(u), (3 + np.cos(v)) * np.sin(u), np.sin(v)], -1).reshape(-1, 3)
    faces = []
    for i in range(M):
        for j in range(N):
            a, b, c, d = i * N + j, (i + 1) % M * N + j, (i + 1) % M * N + (j + 1) % N, i * N + (j + 1) % N
            faces += [(a, b, c), (a, c, d)]  # counter-clockwise seen from outside (the normal along u x v points out)
    holes = {i * N + j for i, j in ((3, 2), (3, 3), (4, 2), (4, 3), (11, 7), (11, 8), (12, 7), (12, 8))}
    rim = {x for f in faces if holes & set(f) for x in f} - holes  # the cut faces' other corners: the holes' rims
    faces = [f for f in faces if not holes & set(f)]
    used = sorted({x for f in faces for x in f})
    renumber = {x: k for k, x in enumerate(used)}  # a scan has no vertices in its holes
    faces = [tuple(renumber[x] for x in f) for f in faces]
    fins = [faces[k][:2] for k in (40, 100, 200)]  # edges (a, b) of interior faces away from the holes
    assert all(sum(e[0] in f and e[1] in f for f in faces) == 2 for e in fins)
    added = [(a, b, (a + len(used) // 2) % len(used)) for a, b in fins]  # a third face on each, far apex
    lines = [f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in points[used]] + [f"3 {a} {b} {c}" for a, b, c in faces + added]
    path = tmp_path / "scan.ply"
    path.write_text(f"ply\nformat ascii 1.0\nelement vertex {len(used)}\nproperty float x\nproperty float y\n"
                    f"property float z\nelement face {len(faces) + 3}\nproperty list uchar int vertex_indices\nend_header\n"
                    + "\n".join(lines) + "\n")
    return path, sorted(tuple(sorted(e)) for e in fins), list(range(len(faces), len(faces) + 3)), len(used), len(rim)


def test_the_three_edges_are_listed_the_rest_analysed_and_exit_1(tmp_path, capsys):
    path, edges, added, count, rim = scan(tmp_path)
    assert main(["inspect", str(path), "--json", "--quiet"]) == 1
    data = json.loads(capsys.readouterr().out)
    defects = data["defects"]
    assert sorted(tuple(e) for e in defects["non_manifold_edges"]) == edges
    assert defects["dropped_faces"] == added and not defects["isolated_vertices"] and not defects["non_manifold_vertices"]
    assert data["not_analysed"] == {} and data["exit_status"] == 1 and data["scheme"] == "loop"
    names = {k["name"] for k in data["kinds"]}
    assert names == {"smooth", "boundary"} and sum(k["count"] for k in data["kinds"]) == count
    assert sum(k["count"] for k in data["kinds"] if k["name"] == "boundary") == rim > 0


def test_the_table_names_what_was_left_out_and_strict_refuses_the_first_edge(tmp_path, capsys):
    path, edges, *_ = scan(tmp_path)
    assert main(["inspect", str(path), "--quiet"]) == 1
    out = capsys.readouterr().out
    assert "left out of the file: 3 non manifold edges, 3 dropped faces" in out
    assert main(["inspect", str(path), "--strict"]) == 2
    err = capsys.readouterr().err
    a, b = edges[0]
    assert err.count("\n") == 1 and f"edge ({a}, {b}) is shared by 3 faces" in err and "(non-manifold edge)" in err
