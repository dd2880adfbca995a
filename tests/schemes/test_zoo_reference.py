"""The zoo's families refined on explicit meshes (``tests/schemes/zoo_reference.py``, written from the papers and
importing nothing of the toolkit) have the eigenvalues the literature gives (``symdecomp.schemes.zoo_literature``),
and the shipped files' stencils, applied by walking halfedges on the same meshes, give the same matrices."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import J, M, N
from symdecomp.schemes.zoo_literature import FAMILIES
from tests.schemes import zoo_reference as ref

MATRICES = {
    "doo-sabin": lambda n: ref.dual_matrix(n, ref.doo_sabin_weights)[0],
    "midedge": lambda n: ref.dual_matrix(n, ref.midedge_weights)[0],
    "sqrt3": ref.sqrt3_matrix,
    "modified-butterfly": ref.butterfly_matrix,
}
VALENCES = {"midedge": range(4, 9)}
TOLERANCE = 1e-4  # a defective cluster (the butterfly at n = 6) splits by about the square root of rounding


def _cases():
    return [(name, n) for name in MATRICES for n in VALENCES.get(name, range(3, 9))]


@pytest.mark.parametrize(("name", "n"), _cases())
def test_the_reference_has_the_literature_s_eigenvalues(name, n):
    facts = FAMILIES[name]
    values = ref.spectrum(MATRICES[name](n))
    sub, rest = float(facts.subdominant.subs(N, n)), float(facts.rest_at_most.subs(N, n))
    assert abs(values[0] - 1) < 1e-12, "affine invariance: the dominant eigenvalue is 1"
    k = facts.multiplicity
    assert np.allclose(values[1:1 + k], sub, atol=1e-12), f"{name} at n = {n}: {values[:4]}"
    assert max(abs(v) for v in values[1 + k:]) <= rest + TOLERANCE
    assert rest < sub, "the subdominant eigenvalue dominates the rest"


@pytest.mark.parametrize("n", range(3, 9))
def test_doo_sabin_s_ngon_block_is_the_fourier_transform_of_its_weights(n):
    # the n-gon's own points map among themselves: their block is the circulant of the weights, so its eigenvalues
    # are the weights' discrete Fourier transform (derived here, not typed in)
    matrix, labels = ref.dual_matrix(n, ref.doo_sabin_weights)
    ngon = [i for i, (_, a, b) in enumerate(labels) if a == b == 0]
    block = np.linalg.eigvals(matrix[np.ix_(ngon, ngon)])
    transform = np.fft.fft(ref.doo_sabin_weights(n))
    assert np.allclose(sorted(block.real, reverse=True), sorted(transform.real, reverse=True), atol=1e-12)
    assert np.allclose(block.imag, 0, atol=1e-12) and np.allclose(transform.imag, 0, atol=1e-12)


@pytest.mark.parametrize("n", range(3, 9))
def test_doo_sabin_s_transform_is_doo_and_sabin_s_1_half_quarter(n):
    # a separate check against the source's closed form (D. Doo and M. Sabin, 1978, Behaviour of recursive division
    # surfaces near extraordinary points: 1, then 1/2 twice, then 1/4), as FAMILIES["doo-sabin"] records it
    transform = sorted(np.fft.fft(ref.doo_sabin_weights(n)).real, reverse=True)
    facts = FAMILIES["doo-sabin"]
    literature = [1.0] + [float(facts.subdominant)] * facts.multiplicity + [float(facts.rest_at_most)] * (n - 3)
    assert np.allclose(transform, literature, atol=1e-12)


# A walker over the reference meshes: the shipped files' terms applied as the stencil model defines its walks.
def _walk(mesh: ref.Mesh, h: tuple, moves: tuple[str, ...]) -> tuple:
    for move in moves:
        u, v = h
        face = mesh.faces[mesh.left[h]]
        i = face.index(u)
        h = {"next": (v, face[(i + 2) % len(face)]), "prev": (face[i - 1], u), "twin": (v, u)}[move]
    return h


def _family(mesh: ref.Mesh, h: tuple, over: str) -> list[tuple]:
    if over == "one":
        return [h]
    out, g = [], h
    while True:
        out.append(g)
        g = _walk(mesh, g, ("prev", "twin")) if over == "ring" else _walk(mesh, g, ("next",))
        if g == h:
            return out


def _apply(mesh, rule, h, points, regular):
    """The new point of one rule at anchor h (old points only: the families shipped use no new points)."""
    total = 0
    for term in rule.terms:
        assert term.source == "old"
        family = _family(mesh, h, term.over)
        values = {M: len(mesh.faces[mesh.left[h]])}
        if term.over == "ring" or term.weight.has(N):
            values[N] = len(_family(mesh, h, "ring"))
        for j, g in enumerate(family):
            weight = term.weight.subs({**values, J: j})
            total = total + float(sp.N(weight, 30)) * points[_walk(mesh, g, term.walk)[0]]
    return total


def _edge_point(mesh, kind, h, points, regular):
    """``ends = "average"``: the mean over the orientations at which a rule applies."""
    found = []
    for g in (h, (h[1], h[0])):
        n_origin = len(_family(mesh, g, "ring"))
        n_tip = len(_family(mesh, (g[1], g[0]), "ring"))
        rule = next((r for r in kind.rules if r.applies(n_origin, n_tip, regular=regular)), None)
        if rule is not None:
            found.append(_apply(mesh, rule, g, points, regular))
    assert kind.ends == "average" and found
    return sum(found) / len(found)


def test_the_shipped_butterfly_file_walks_to_the_paper_s_stencils():
    edge = load_zoo("modified-butterfly").rules_of("edge")
    for n in (3, 4, 5, 7):
        mesh = ref.Mesh(ref.triangle_disk(n, 5))
        points = ref._unit(mesh.vertices)
        for s in range(n):  # the 1-ring's edges and the edges between 1-ring neighbours
            for u, v in ((ref.CENTRE, (s, 1, 0)), ((s, 1, 0), ((s + 1) % n, 1, 0)), ((s, 1, 0), (s, 2, 0))):
                expected = ref.butterfly_edge_point(mesh, points, u, v)
                assert np.allclose(_edge_point(mesh, edge, (u, v), points, 6), expected, atol=1e-12), (n, u, v)


def test_the_shipped_dual_files_walk_to_the_paper_s_corner_weights():
    for name, weights in (("doo-sabin", ref.doo_sabin_weights), ("midedge", ref.midedge_weights)):
        (rule,) = load_zoo(name).rules_of("corner").rules
        for m in (3, 4, 5, 8):
            mesh = ref.Mesh([tuple(range(m)), *[(i, (i - 1) % m, m + i) for i in range(m)]])  # an m-gon with a ring of triangles
            points = ref._unit(mesh.vertices)
            for corner in range(m):
                got = _apply(mesh, rule, (corner, (corner + 1) % m), points, 4)
                expected = sum(w * points[(corner + j) % m] for j, w in enumerate(weights(m)))
                assert np.allclose(got, expected, atol=1e-12), (name, m, corner)


def test_the_shipped_sqrt3_file_is_kobbelt_s_rules():
    scheme = load_zoo("sqrt3")
    (face,) = scheme.rules_of("face").rules
    (vertex,) = scheme.rules_of("vertex").rules
    for n in (3, 4, 5, 7):
        mesh = ref.Mesh(ref.triangle_disk(n, 3))
        points = ref._unit(mesh.vertices)
        ring = [(s, 1, 0) for s in range(n)]
        alpha = (4 - 2 * np.cos(2 * np.pi / n)) / 9
        got = _apply(mesh, vertex, (ref.CENTRE, ring[0]), points, 6)
        assert np.allclose(got, (1 - alpha) * points[ref.CENTRE] + alpha / n * sum(points[p] for p in ring), atol=1e-12)
        got = _apply(mesh, face, (ref.CENTRE, ring[0]), points, 6)
        assert np.allclose(got, (points[ref.CENTRE] + points[ring[0]] + points[ring[1]]) / 3, atol=1e-12)


@pytest.mark.parametrize(("name", "n"), [("catmull-clark", 3), ("catmull-clark", 4), ("catmull-clark", 5), ("catmull-clark", 7),
                                         ("loop", 3), ("loop", 5), ("loop", 6), ("loop", 8)])
def test_today_s_schemes_as_stencils_give_today_s_one_ring_matrix(name, n):
    from symdecomp import subdivision_matrix
    from symdecomp.schemes.files import load_scheme
    from symdecomp.schemes.stencil_convert import as_stencils

    scheme = load_scheme(name)
    stencils = as_stencils(scheme)
    quad = stencils.lattice == "quad"
    regular = 4 if quad else 6
    mesh = ref.Mesh(ref.quad_disk(n, 3) if quad else ref.triangle_disk(n, 3))
    points = ref._unit(mesh.vertices)
    ring = [(s, 1, 0) for s in range(n)]
    labels = [ref.CENTRE, *ring, *([(s, 1, 1) for s in range(n)] if quad else [])]
    (vertex,) = stencils.rules_of("vertex").rules
    rows = [_apply(mesh, vertex, (ref.CENTRE, ring[0]), points, regular)]
    rows += [_edge_point(mesh, stencils.rules_of("edge"), (ref.CENTRE, p), points, regular) for p in ring]
    if quad:  # the face point of the face between a_s and a_(s+1), anchored at its halfedge leaving the centre
        face = stencils.rules_of("face")
        rows += [_apply(mesh, next(r for r in face.rules if r.applies(n, regular, regular=regular)), (ref.CENTRE, p), points, regular)
                 for p in ring]
    keep = [mesh.vertices.index(v) for v in labels]
    ours = np.array(rows)[:, keep]
    today = np.array(subdivision_matrix(scheme, n).evalf(30).tolist(), dtype=float)
    assert np.allclose(sorted(np.linalg.eigvals(ours), key=abs), sorted(np.linalg.eigvals(today), key=abs), atol=1e-9)
    assert np.allclose(ours.sum(axis=1), 1)


def _guide_family():
    import re
    from pathlib import Path

    from symdecomp.schemes.stencil_files import stencil_scheme_from_text

    guide = (Path(__file__).resolve().parents[2] / "docs" / "guide" / "adding-a-scheme.md").read_text(encoding="utf-8")
    return stencil_scheme_from_text("\n".join(re.findall(r"```toml\n(.*?)```", guide, re.S)))


def test_the_guide_s_sixth_family_walks_to_the_weights_of_its_description():
    # the file's terms, walked on an m-gon, give the mean of the corner, its two edge midpoints and the centroid
    (rule,) = _guide_family().rules_of("corner").rules
    for m in (3, 4, 5, 8):
        mesh = ref.Mesh([tuple(range(m)), *[(i, (i - 1) % m, m + i) for i in range(m)]])
        points = ref._unit(mesh.vertices)
        for corner in range(m):
            got = _apply(mesh, rule, (corner, (corner + 1) % m), points, 4)
            expected = sum(w * points[(corner + j) % m] for j, w in enumerate(ref.corner_mean_weights(m)))
            assert np.allclose(got, expected, atol=1e-12), (m, corner)


@pytest.mark.parametrize("n", range(3, 9))
def test_the_guide_s_ngon_eigenvalues_are_the_fourier_transform_it_derives(n):
    # the n-gon's block is the circulant of the weights: its eigenvalues are their discrete Fourier transform,
    # which the guide writes as 1/2 + cos(2 pi k/n)/4 at k = 1..n-1 (1 at k = 0)
    matrix, labels = ref.dual_matrix(n, ref.corner_mean_weights)
    ngon = [i for i, (_, a, b) in enumerate(labels) if a == b == 0]
    block = sorted(np.linalg.eigvals(matrix[np.ix_(ngon, ngon)]).real, reverse=True)
    transform = sorted(np.fft.fft(ref.corner_mean_weights(n)).real, reverse=True)
    k = sp.Symbol("k")
    guide = sp.Piecewise((1, sp.Eq(k, 0)), (sp.Rational(1, 2) + sp.cos(2 * sp.pi * k / n) / 4, True))
    derived = sorted((float(guide.subs(k, i)) for i in range(n)), reverse=True)
    assert np.allclose(block, transform, atol=1e-12)
    assert np.allclose(transform, derived, atol=1e-12)


def test_a_family_whose_rules_were_not_read_is_not_shipped():
    from symdecomp.errors import InvalidSchemeError
    from symdecomp.schemes.files import load_scheme
    from symdecomp.schemes.stencil_files import ZOO_FILES
    from symdecomp.schemes.zoo_literature import NOT_SHIPPED

    assert set(FAMILIES) == set(ZOO_FILES) and not set(NOT_SHIPPED) & set(ZOO_FILES)
    for name in NOT_SHIPPED:
        with pytest.raises(InvalidSchemeError, match=f"unknown family of the zoo '{name}'"):
            load_zoo(name)
        with pytest.raises(InvalidSchemeError, match=f"^'{name}' is not shipped: ") as refused:  # by name: the reason
            load_scheme(name)
        assert NOT_SHIPPED[name].summary and str(refused.value).endswith(NOT_SHIPPED[name].summary)


def test_a_user_s_file_named_as_an_unshipped_family_is_read_as_a_file(tmp_path, monkeypatch):
    from symdecomp.schemes.files import load_scheme

    monkeypatch.chdir(tmp_path)
    (tmp_path / "kobbelt-quad").write_text(_KOBBELT_REGULAR, encoding="utf-8")
    assert load_scheme("kobbelt-quad").name == "kobbelt-quad-regular-part"


def _implementation_face_points(n: int, w: float = 1.0):
    """The rules ``NOT_SHIPPED["kobbelt-quad"]`` read in an implementation, on a quad disk around a vertex of valence
    ``n``: each face at the centre's point along its one pair of opposite new edge points, and along the other."""
    mesh = ref.Mesh(ref.quad_disk(n, 4))
    points = ref._unit(mesh.vertices)
    after = {(f[i], f[(i + 1) % 4]): f[(i + 2) % 4] for f in mesh.faces for i in range(4)}  # a halfedge's next tip

    def ring(v):  # the neighbours q_i counter-clockwise and r_i, the corner across the face (v, q_i, r_i, q_(i+1))
        qs, rs = [next(b for a, b in after if a == v)], []
        while True:
            rs.append(after[(v, qs[-1])])
            if (q := after[(qs[-1], rs[-1])]) == qs[0]:
                return qs, rs
            qs.append(q)

    def virtual(p, q):  # the point behind p on the line from q
        qs, rs = ring(p)
        k, i = len(qs), qs.index(q)
        return (4 / k * sum(points[x] for x in qs) - sum(points[qs[(i + d) % k]] for d in (-1, 0, 1))
                + w / (4 + w) * sum(points[rs[(i + d) % k]] for d in (-2, -1, 0, 1)) - 4 * w / ((4 + w) * k) * sum(points[x] for x in rs))

    def four_point(a, b, c, d):
        return (8 + w) / 16 * (b + c) - w / 16 * (a + d)

    def edge(a, b):
        return four_point(virtual(a, b), points[a], points[b], virtual(b, a))

    def along(a, b):  # the face left of (a, b) is (a, b, c, d): its point along the edges (a, b) and (c, d)
        c = after[(a, b)]
        d = after[(b, c)]
        beyond_ab, beyond_cd = (after[(b, a)], after[(a, after[(b, a)])]), (after[(d, c)], after[(c, after[(d, c)])])
        return four_point(edge(*beyond_ab), edge(a, b), edge(c, d), edge(*beyond_cd))

    return [(along(ref.CENTRE, q), along(q, after[(ref.CENTRE, q)])) for q in ring(ref.CENTRE)[0]]


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_the_implementation_read_for_kobbelt_s_quad_scheme_has_a_face_point_per_direction(n):
    # what NOT_SHIPPED says: the two pairs of opposite edge points give one face point on the regular lattice only
    gap = max(np.abs(one - other).max() for one, other in _implementation_face_points(n))
    assert (gap < 1e-12) if n == 4 else (gap > 1e-4), gap


def test_at_a_regular_vertex_the_implementation_read_gives_the_tensor_product_four_point_face_point():
    # what NOT_SHIPPED says the implementations read agree on: at valence 4 the face point built from new edge
    # points is the four-point rule (-1, 9, 9, -1)/16 in each direction, 81/256, -9/256 and 1/256 on the 4 x 4 grid
    # around the face; the virtual point at valence 4 must be the opposite neighbour for this to hold
    mesh = ref.Mesh(ref.quad_disk(4, 4))
    after = {(f[i], f[(i + 1) % 4]): f[(i + 2) % 4] for f in mesh.faces for i in range(4)}
    directions = [(1, 0), (0, 1), (-1, 0), (0, -1)]

    def plane(label):  # the valence-4 disk is the square grid: sector s spans directions s and s + 1
        if label == ref.CENTRE:
            return (0, 0)
        s, a, b = label
        return tuple(a * directions[s][i] + b * directions[(s + 1) % 4][i] for i in range(2))

    one_d = {-1: Fraction(-1, 16), 0: Fraction(9, 16), 1: Fraction(9, 16), 2: Fraction(-1, 16)}
    labels = list(ref._unit(mesh.vertices))
    first_ring = [next(b for a, b in after if a == ref.CENTRE)]  # the neighbours counter-clockwise, as the helper
    while (q := after[(first_ring[-1], after[(ref.CENTRE, first_ring[-1])])]) != first_ring[0]:
        first_ring.append(q)
    face_points = _implementation_face_points(4)
    for q, (face_point, _) in zip(first_ring, face_points, strict=True):
        c = after[(ref.CENTRE, q)]
        corners = [plane(v) for v in (ref.CENTRE, q, c, after[(q, c)])]
        x0, y0 = min(x for x, _ in corners), min(y for _, y in corners)
        expected = [one_d.get(plane(v)[0] - x0, 0) * one_d.get(plane(v)[1] - y0, 0) for v in labels]
        assert sum(w != 0 for w in expected) == 16 and sum(expected) == 1
        assert np.allclose(face_point, [float(w) for w in expected], atol=1e-12), q


#: Kobbelt's regular rules as the texts read write them (NOT_SHIPPED["kobbelt-quad"]), no rule at an extraordinary
#: vertex: the four-point rule on an edge, and the same rule on the new edge points across a face.
_KOBBELT_REGULAR = '''
name = "kobbelt-quad-regular-part"
mesh = "quad"
topology = "primal"
interpolatory = true

[[vertex]]
terms = [{walk = "", weight = "1"}]

[[edge]]
origin = "regular"
tip = "regular"
terms = [
  {walk = "", weight = "9/16"},
  {walk = "next", weight = "9/16"},
  {walk = "prev twin prev twin next", weight = "-1/16"},
  {walk = "twin prev twin prev twin next", weight = "-1/16"},
]

[[face]]
origin = "regular"
terms = [
  {walk = "", weight = "9/16", source = "edge"},
  {walk = "next next", weight = "9/16", source = "edge"},
  {walk = "twin next next", weight = "-1/16", source = "edge"},
  {walk = "next next twin next next", weight = "-1/16", source = "edge"},
]
'''


def test_the_file_format_writes_kobbelt_s_regular_rules_and_the_engine_reads_the_tensor_product():
    # the format can say what the texts read say of the regular lattice (a face point made of new edge points);
    # what is missing for kobbelt-quad is only the rule at an extraordinary vertex, which no text read states
    from symdecomp.schemes.halfedge import halfedge_mesh
    from symdecomp.schemes.stencil_files import stencil_scheme_from_text
    from symdecomp.schemes.stencil_rows import kind_row, point_key

    scheme = stencil_scheme_from_text(_KOBBELT_REGULAR)
    size = 6  # a 6 x 6 grid of vertices x + size * y: the stencils of the middle face lie inside
    faces = [(x + size * y, x + 1 + size * y, x + 1 + size * (y + 1), x + size * (y + 1))
             for y in range(size - 1) for x in range(size - 1)]
    mesh = halfedge_mesh(faces)
    made = {}
    for h in range(len(mesh.origin)):
        key = point_key(mesh, "edge", h)
        if key not in made and (row := kind_row(mesh, scheme.rules_of("edge"), key, made, regular=4)) is not None:
            made[key] = row
    four_point = {-1: sp.Rational(-1, 16), 0: sp.Rational(9, 16), 1: sp.Rational(9, 16), 2: sp.Rational(-1, 16)}
    edge = made[point_key(mesh, "edge", mesh.halfedge(2 + size * 2, 3 + size * 2))]
    assert edge == {2 + i + size * 2: four_point[i] for i in range(-1, 3)}
    middle = faces.index((2 + size * 2, 3 + size * 2, 3 + size * 3, 2 + size * 3))
    face = kind_row(mesh, scheme.rules_of("face"), ("face", middle), made, regular=4)
    expected = {2 + x + size * (2 + y): four_point[x] * four_point[y] for x in range(-1, 3) for y in range(-1, 3)}
    assert face == expected
    assert sorted(set(expected.values())) == [sp.Rational(-9, 256), sp.Rational(1, 256), sp.Rational(81, 256)]


def test_kobbelt_s_regular_rules_are_the_tensor_product_of_the_four_point_scheme_at_valence_4():
    # the engine's matrix of the file above at a regular vertex (the 9 x 9 grid it finds closed under a step) has the
    # characteristic polynomial of the reference's tensor product of two four-point steps on 9 points, exactly
    import flint

    from symdecomp.analysis.zoo_matrix import zoo_matrix
    from symdecomp.errors import InvalidSchemeError
    from symdecomp.schemes.stencil_files import stencil_scheme_from_text

    engine = zoo_matrix(stencil_scheme_from_text(_KOBBELT_REGULAR), 4).matrix
    line = ref.four_point_line_matrix(4)
    reference = ref.tensor_product(line, line)
    assert engine.shape == (len(reference), len(reference)) == (81, 81)
    exact = flint.fmpq_mat([[flint.fmpq(int(x.p), int(x.q)) for x in engine.row(i)] for i in range(engine.rows)])

    def exact_of(rows):
        return flint.fmpq_mat([[flint.fmpq(x.numerator, x.denominator) for x in row] for row in rows])

    assert exact.charpoly() == exact_of(reference).charpoly()
    other = ref.four_point_line_matrix(4, Fraction(1, 8))  # another tension: the comparison tells them apart
    assert exact.charpoly() != exact_of(ref.tensor_product(other, other)).charpoly()
    with pytest.raises(InvalidSchemeError, match=r"no \[edge\] rule applies at either end of an edge"):
        zoo_matrix(stencil_scheme_from_text(_KOBBELT_REGULAR), 5)  # no text read gives the rule there
