"""The zoo's engine: one engine for every scheme written as stencils.

Catmull-Clark and Loop as StencilSchemes give through the engine the eigenvalues of today's route
(``ring_spectrum``); Doo-Sabin's are compared with a matrix the test builds itself by applying the
corner rule to an explicit primal ring mesh, face by face.
"""

import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.errors import InvalidSchemeError, LatticeFactMissing
from symdecomp.schemes.lattice import QUAD, Lattice
from symdecomp.schemes.loop import loop
from symdecomp.schemes.mesh import ring_mesh
from symdecomp.schemes.neighbourhood import neighbourhood
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.stencil_rows import is_zero
from symdecomp.schemes.stencils import KindRules, M, N, Rule, StencilScheme, Term
from tests.analysis.zoo_engine_schemes import (
    butterfly_stencils,
    catmull_clark_stencils,
    doo_sabin_stencils,
    doo_sabin_weight,
    loop_stencils,
    sqrt3_alpha,
    sqrt3_stencils,
)

VALENCES = range(3, 9)


def _same_spectrum(engine, reference):
    assert [e.multiplicity for e in engine.eigenvalues] == [e.multiplicity for e in reference.eigenvalues]
    assert [e.frequencies for e in engine.eigenvalues] == [e.frequencies for e in reference.eigenvalues]
    for a, b in zip(engine.eigenvalues, reference.eigenvalues):
        assert a.value.overlaps(b.value)
        if a.exact is not None and b.exact is not None:
            assert is_zero(a.exact - b.exact), (a.exact, b.exact)


@pytest.mark.parametrize("n", VALENCES)
def test_catmull_clark_as_stencils_is_ring_spectrum(n):
    engine = zoo_spectrum(catmull_clark_stencils(), n, digits=20)
    assert engine.size == 2 * n + 1 and engine.rings == 1
    _same_spectrum(engine, ring_spectrum(catmull_clark(), n, digits=20))


@pytest.mark.parametrize("n", VALENCES)
def test_loop_as_stencils_is_ring_spectrum(n):
    engine = zoo_spectrum(loop_stencils(), n, digits=20)
    assert engine.size == n + 1
    _same_spectrum(engine, ring_spectrum(loop(), n, digits=20))


def _doo_sabin_by_hand(n: int) -> np.ndarray:
    """Doo-Sabin's matrix on the faces around the centre face, built from an explicit primal ring mesh.

    The dual neighbourhood's points are the primal faces ``(s, u, v)``, ``u, v`` in ``{0, 1}``; after a
    step, the point at the fine face ``(s, U, V)`` is the corner point of the coarse face ``(s, 0, 0)`` at
    its corner ``(U, V)``: the corner rule over the faces around that primal vertex, counter-clockwise
    from ``(s, 0, 0)``, each face taken by its dual point. No halfedges, no labels, no blocks.
    """
    mesh = ring_mesh(n, 2)
    faces = mesh.faces
    label = {}
    for s in range(n):  # ring_mesh's faces run sector by sector, u then v
        for u in range(2):
            for v in range(2):
                label[faces[4 * s + 2 * u + v]] = (s, u, v)
    points = [(s, u, v) for s in range(n) for u in range(2) for v in range(2)]
    index = {p: i for i, p in enumerate(points)}
    S = np.zeros((4 * n, 4 * n))
    for s in range(n):
        home = faces[4 * s]
        for U in range(2):
            for V in range(2):
                corner = home[{(0, 0): 0, (1, 0): 1, (1, 1): 2, (0, 1): 3}[(U, V)]]
                around = _faces_around(faces, corner, home)
                m = len(around)
                for j, f in enumerate(around):
                    S[index[(s, U, V)], index[label[f]]] += float(doo_sabin_weight(sp.Integer(j), sp.Integer(m)))
    return S


def _faces_around(faces, vertex, first):
    """The faces at ``vertex``, counter-clockwise from ``first`` (the next face shares the edge before ``vertex``)."""
    out = [first]
    while True:
        f = out[-1]
        before = f[(f.index(vertex) - 1) % len(f)]
        nxt = next(g for g in faces if vertex in g and g[(g.index(vertex) + 1) % len(g)] == before)
        if nxt == first:
            return out
        out.append(nxt)


@pytest.mark.parametrize("n", VALENCES)
def test_doo_sabin_spectrum_is_the_refined_meshs(n):
    engine = zoo_spectrum(doo_sabin_stencils(), n, digits=20)
    values = np.linalg.eigvals(_doo_sabin_by_hand(n))
    assert engine.size == len(values) == 4 * n
    left = list(values)
    for e in engine.eigenvalues:  # each value of the engine's, as often as its multiplicity, among the matrix's
        z = complex(float(e.value.real.mid()), float(e.value.imag.mid()))
        for _ in range(e.multiplicity):
            nearest = min(range(len(left)), key=lambda i: abs(left[i] - z))
            assert abs(left[nearest] - z) < 1e-6, (z, left[nearest])
            left.pop(nearest)
    assert not left


@pytest.mark.slow
@pytest.mark.parametrize("n", VALENCES)
def test_doo_sabin_leading_eigenvalues_are_the_centre_faces_symbols(n):
    """The centre face's corners map among themselves: its eigenvalues are ``sum_j w_j zeta^(jk)`` (k = 0, 1, n-1)."""
    j = sp.Symbol("j")
    symbol = [sp.Add(*[doo_sabin_weight(sp.Integer(i), n) * sp.exp(2 * sp.pi * sp.I * i * k / n) for i in range(n)]) for k in range(n)]
    spectrum = zoo_spectrum(doo_sabin_stencils(), n, digits=20).eigenvalues
    assert spectrum[0].multiplicity == 1 and is_zero(spectrum[0].exact - symbol[0])
    assert spectrum[1].multiplicity == 2 and spectrum[1].frequencies == (1, n - 1)
    assert is_zero(spectrum[1].exact - symbol[1]) and is_zero(spectrum[1].exact - symbol[n - 1])
    assert spectrum[1].exact.is_Rational  # Q(cos 2 pi/n) collapses: the symbol is rational
    assert j not in spectrum[1].exact.free_symbols


def test_doo_sabin_matrix_rows_are_corner_rules():
    """Each row of the engine's matrix sums to 1 (affine invariance), exactly, and the centre face's rows are the rule."""
    zm = zoo_matrix(doo_sabin_stencils(), 5)
    for i in range(zm.matrix.shape[0]):
        assert is_zero(sum(zm.matrix.row(i)) - 1)
    nb = zm.neighbourhood
    centre = [nb.index()[v] for v in nb.order if nb.labels[v][1] == 0]
    for i in centre:
        row = [zm.matrix[i, c] for c in centre]
        s = nb.labels[nb.order[i]][0]
        for c in centre:
            t = nb.labels[nb.order[c]][0]
            assert is_zero(row[centre.index(c)] - doo_sabin_weight(sp.Integer((t - s) % 5), sp.Integer(5)))


def _sqrt3_two_steps_by_hand(n: int) -> np.ndarray:
    """sqrt(3) twice on the 1-ring ``(v, a_0..a_(n-1))``, written out: ``f_j = (v + a_j + a_(j+1))/3`` and the vertex
    rule, then ``g_j = (v' + f_(j-1) + f_j)/3`` (the triangle over ray ``j``: the lattice is back) and the vertex rule."""
    alpha = float(sqrt3_alpha(sp.Integer(n)))
    step1 = np.zeros((n + 1, n + 1))  # rows: v', f_0..f_(n-1)
    step1[0, 0], step1[0, 1:] = 1 - alpha, alpha / n
    for j in range(n):
        step1[1 + j, [0, 1 + j, 1 + (j + 1) % n]] += 1 / 3
    step2 = np.zeros((n + 1, n + 1))  # rows: v'', g_0..g_(n-1) on (v', f_0..)
    step2[0, 0], step2[0, 1:] = 1 - alpha, alpha / n
    for j in range(n):
        step2[1 + j, [0, 1 + (j - 1) % n, 1 + j]] += 1 / 3
    return step2 @ step1


@pytest.mark.slow
@pytest.mark.parametrize("n", VALENCES)
def test_sqrt3_is_analysed_over_two_steps(n):
    engine = zoo_spectrum(sqrt3_stencils(), n, digits=20)
    assert sqrt3_stencils().steps == 2 and engine.size == n + 1
    left = list(np.linalg.eigvals(_sqrt3_two_steps_by_hand(n)))
    for e in engine.eigenvalues:
        z = complex(float(e.value.real.mid()), float(e.value.imag.mid()))
        for _ in range(e.multiplicity):
            nearest = min(range(len(left)), key=lambda i: abs(left[i] - z))
            assert abs(left[nearest] - z) < 1e-9
            left.pop(nearest)
    # the subdominant value, from the face rule's weight (1/3 per corner): |(1 + zeta)/3|^2, exactly
    w = sqrt3_stencils().rules_of("face").rules[0].terms[0].weight.subs(M, 3)
    zeta = sp.exp(2 * sp.pi * sp.I / n)
    assert engine.eigenvalues[1].frequencies == (1, n - 1)
    assert is_zero(engine.eigenvalues[1].exact - sp.expand(w**2 * (1 + zeta) * (1 + 1 / zeta)))


@pytest.mark.parametrize("make", [catmull_clark_stencils, doo_sabin_stencils])
def test_fourier_vectors_are_mapped_by_the_blocks(make):
    """``S x = zeta^(sk) B_k y`` for ``x_(s, c) = zeta^(sk) y_c`` (exact, ``n = 4``: ``zeta = i``): the blocks are the matrix's."""
    n = 4
    zm = zoo_matrix(make(), n)
    b, nb = zoo_blocks(zm), zm.neighbourhood
    index = nb.index()
    for k in range(n):
        B = b.frequency_matrix(sp.I**k)
        for c in range(b.class_count):
            x = sp.zeros(len(nb.order), 1)
            for v, (s, e) in nb.labels.items():
                x[index[v]] = sp.I ** (s * k) if e == c else 0
            y = zm.matrix * x
            for v, (s, e) in nb.labels.items():
                expected = sp.I ** (s * k) * B[e, c]
                assert sp.expand(y[index[v]] - expected) == 0
            if k == 0 and nb.centre is not None:
                assert sp.expand(y[index[nb.centre]] - b.frequency_zero_matrix()[0, 1 + c]) == 0


def test_a_rule_that_is_not_rotation_invariant_is_refused():
    lopsided = KindRules("vertex", (Rule((Term(sp.Rational(1, 2)), Term(sp.Rational(1, 2), ("next",)))),))
    edge = KindRules("edge", (Rule((Term(sp.Rational(1, 2)), Term(sp.Rational(1, 2), ("next",)))),))
    scheme = StencilScheme("lopsided", "triangle", "primal", (edge, lopsided))
    with pytest.raises(InvalidSchemeError, match=r"the \[vertex\] rule is not rotation-invariant"):
        zoo_matrix(scheme, 5)


def test_a_weight_in_n_is_read_at_the_anchor():
    """Loop's vertex rule uses ``n``: at the centre it is the centre's valence, elsewhere the regular 6."""
    zm = zoo_matrix(loop_stencils(), 5)
    beta = (sp.Rational(5, 8) - (sp.Rational(3, 8) + sp.cos(2 * sp.pi / N) / 4) ** 2) / N
    assert is_zero(zm.matrix[0, 0] - (1 - 5 * beta.subs(N, 5)))


class _StubLattice(Lattice):
    """A lattice that states no meshes and no faces."""


STUB = _StubLattice("stub", 4, True, "none", "none", "none")


def test_a_stub_lattice_without_ring_meshes_fails_naming_the_fact():
    with pytest.raises(LatticeFactMissing, match="ring_mesh"):
        neighbourhood(STUB, 5, 1)
    scheme = StencilScheme("stub-doo-sabin", STUB, "dual", doo_sabin_stencils().kinds)  # type: ignore[arg-type]
    with pytest.raises(LatticeFactMissing, match="ring_mesh"):
        zoo_matrix(scheme, 5)


def test_a_lattice_without_a_face_size_fails_naming_it():
    nb = neighbourhood(QUAD, 4, 1, centred="face")
    stub = nb.__class__(STUB, *[getattr(nb, f) for f in ("n", "depth", "centred", "mesh", "start", "centre", "classes", "labels", "order")])
    with pytest.raises(LatticeFactMissing, match="regular_face_size"):
        assert stub.regular_valence is None


@pytest.mark.parametrize("make", [catmull_clark_stencils, loop_stencils, doo_sabin_stencils, sqrt3_stencils])
@pytest.mark.parametrize("n", [4, 5])
def test_certificates_agree(make, n):
    from symdecomp.verify.certify import certify_zoo
    from symdecomp.verify.result import CrossCheckStatus

    c = certify_zoo(make(), n)
    assert c.status == CrossCheckStatus.AGREE and c.multiplicities_certified
    rational = all(x.is_Rational for x in zoo_matrix(make(), n).matrix)
    assert c.route == ("charpoly" if rational else "structural")


def test_the_charpoly_route_refutes_a_matrix_that_is_not_the_blocks():
    """One weight moved (the row still sums to 1): chi_S's roots leave the blocks' balls."""
    from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks
    from symdecomp.verify.certify import _charpoly_verdict
    from symdecomp.verify.result import CrossCheckStatus

    zm = zoo_matrix(catmull_clark_stencils(), 4)
    spectrum = spectrum_of_blocks(zoo_blocks(zm), digits=20, exact=False)
    S = sp.Matrix(zm.matrix)
    S[0, 0] -= sp.Rational(1, 8)
    S[0, 1] += sp.Rational(1, 8)
    status, message, _, _ = _charpoly_verdict(S, spectrum, 192)
    assert status == CrossCheckStatus.DISAGREE and "no block gives" in message


@pytest.mark.parametrize("make", [catmull_clark_stencils, loop_stencils, doo_sabin_stencils, sqrt3_stencils])
def test_masks_are_left_eigenvectors_of_the_full_matrix(make):
    """``l S = l`` for the position mask (weights summing to 1) and ``t S = lambda_1 t`` for both tangent masks."""
    from symdecomp.analysis.zoo_masks import zoo_masks

    n = 5
    zm = zoo_matrix(make(), n)
    masks = zoo_masks(make(), n, digits=25)
    nb = zm.neighbourhood
    S = np.array([[float(x) for x in zm.matrix.row(i)] for i in range(zm.matrix.shape[0])])

    def vector(mask):
        return np.array([float(mask["O"]) if v == nb.centre else float(mask["classes"][str(nb.labels[v][1])][nb.labels[v][0]])
                         for v in nb.order])

    position = vector(masks["position"])
    assert abs(position.sum() - 1) < 1e-12 and np.abs(position @ S - position).max() < 1e-12
    lam1 = float(masks["subdominant"])
    for t in masks["tangents"]:
        tangent = vector(t)
        assert np.abs(tangent).max() > 0.5 and np.abs(tangent @ S - lam1 * tangent).max() < 1e-12


def test_masks_of_catmull_clark_as_stencils_are_ring_masks():
    from symdecomp.analysis.masks import ring_masks
    from symdecomp.analysis.zoo_masks import zoo_masks

    ours, theirs = zoo_masks(catmull_clark_stencils(), 7, digits=15), ring_masks(catmull_clark(), 7, digits=15)
    assert ours["subdominant"] == theirs["subdominant"]
    for a, b in zip([ours["position"], *ours["tangents"]], [theirs["position"], *theirs["tangents"]]):
        assert a["O"] == b["O"] and a["classes"]["0"] == b["a"] and a["classes"]["1"] == b["b"]


@pytest.mark.parametrize("n", VALENCES)
def test_modified_butterfly_reaches_two_rings_and_is_certified(n):
    """The butterfly's edge rule reaches two rings: the closure finds depth 2; its spectrum is certified at every n, at
    the regular valence through a factor with a repeated root (split exactly); old vertices are kept."""
    from symdecomp.verify.certify import certify_zoo
    from symdecomp.verify.result import CrossCheckStatus

    zm = zoo_matrix(butterfly_stencils(), n)
    assert zm.depth == 2
    centre = zm.neighbourhood.index()[zm.neighbourhood.centre]
    assert [zm.matrix[centre, c] for c in range(zm.matrix.shape[1])] == [int(c == centre) for c in range(zm.matrix.shape[1])]
    c = certify_zoo(butterfly_stencils(), n)
    assert c.status == CrossCheckStatus.AGREE and c.multiplicities_certified
    assert sum(c.multiplicities) == zm.matrix.shape[0]


def test_doo_sabin_symbol_in_m_is_the_engines_centre_face_at_every_n():
    """The corner rule's symbol, summed for every face size m, is an eigenvalue of the engine's block at each k."""
    from symdecomp.analysis.zoo_symbols import family_symbol

    weight = doo_sabin_stencils().rules_of("corner").rules[0].terms[0].weight
    symbol = family_symbol(weight, M)
    for n in (3, 5, 8):
        spectrum = zoo_spectrum(doo_sabin_stencils(), n, digits=20)
        for k in range(n):
            signed = k if k <= n // 2 else k - n
            value = symbol.value(signed)
            assert value.is_Rational
            assert any(k in e.frequencies and e.value.contains(float(value)) or (e.exact is not None and k in e.frequencies
                       and is_zero(e.exact - value)) for e in spectrum.eigenvalues)


def test_a_symbol_that_is_not_a_trigonometric_polynomial_is_refused():
    from symdecomp.analysis.zoo_symbols import family_symbol
    from symdecomp.errors import NotApplicableError

    with pytest.raises(NotApplicableError, match="not c"):
        family_symbol(sp.Symbol("j", nonnegative=True, integer=True) ** 2 / M, M)


@pytest.mark.parametrize("n", VALENCES)
def test_jordan_blocks_are_ring_spectrums(n):
    """Catmull-Clark and Loop as stencils: the Jordan block sizes the engine decides are today's route's."""
    for ours, theirs in ((catmull_clark_stencils(), catmull_clark()), (loop_stencils(), loop())):
        a, b = zoo_spectrum(ours, n, digits=20), ring_spectrum(theirs, n, digits=20)
        assert [x.jordan for x in a.eigenvalues] == [y.jordan for y in b.eigenvalues]


def test_a_jordan_block_is_a_nilpotent_part_of_the_full_matrix():
    """Where the engine reports a block of size 2 (Doo-Sabin's 1/4 at n = 6), (S - 1/4)^2 has a smaller kernel than the
    multiplicity would give with no Jordan block: rank(S - 1/4) > size - multiplicity, exactly."""
    zm = zoo_matrix(doo_sabin_stencils(), 6)
    quarter = next(e for e in zoo_spectrum(doo_sabin_stencils(), 6).eigenvalues if e.exact == sp.Rational(1, 4))
    assert quarter.jordan is not None and max(quarter.jordan) == 2
    A = sp.Matrix(zm.matrix) - sp.eye(zm.matrix.shape[0]) / 4
    blocks = len(quarter.jordan)
    assert A.rank() == zm.matrix.shape[0] - blocks
    assert (A**2).rank() == zm.matrix.shape[0] - blocks - sum(1 for s in quarter.jordan if s >= 2)
