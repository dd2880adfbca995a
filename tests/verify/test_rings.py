"""Triangle schemes (Loop), K-ring matrices by refinement, their frequency matrices and spectra."""

import json

import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.cyclotomic import cyclotomic_value
from symdecomp.analysis.defective import jordan_vertex_weights
from symdecomp.analysis.frequency import RingBlocks, ring_blocks
from symdecomp.analysis.masks import limit_masks_at, ring_masks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.cli import main
from symdecomp.schemes.loop import loop, loop_beta, loop_warren, triangle_scheme
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import alpha, beta
from symdecomp.symbols import n as N
from symdecomp.verify.certify import certify, certify_ring
from symdecomp.verify.numeric import ring_numeric_check
from symdecomp.verify.result import CrossCheckStatus

SCHEMES = {"loop": loop(), "loop-warren": loop_warren(), "catmull-clark": catmull_clark()}


def _zero(expr) -> bool:
    """Exactly zero: in a cyclotomic field (cosines of rational multiples of pi stay exact)."""
    return cyclotomic_value(sp.expand(expr)).poly == 0


@pytest.mark.parametrize("name", ["loop", "loop-warren"])
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 9])
def test_triangle_refinement_reproduces_the_one_ring_rules(name, n):
    scheme = SCHEMES[name]
    S = ring_subdivision_matrix(scheme, n, 1).exact_matrix()
    T = subdivision_matrix(scheme, n)
    assert S.shape == (n + 1, n + 1)
    assert all(_zero(S[r, c] - T[r, c]) for r in range(n + 1) for c in range(n + 1))


def test_loop_and_warren_weights():
    assert loop_beta().subs(N, 6) == sp.Rational(1, 16)
    assert loop_beta().subs(N, 3) == sp.Rational(3, 16)  # (5/8 - (3/8 - 1/8)^2)/3
    assert loop_warren().vertex_rule.each_a.subs(N, 3) == sp.Rational(3, 16)
    assert loop_warren().vertex_rule.each_a.subs(N, 10) == sp.Rational(3, 80)
    depends_on_n = triangle_scheme("bad", sp.Rational(1, 8), edge_end=sp.Rational(3, 8) + 1 / N, edge_side=sp.Rational(1, 8) - 1 / N)
    # the model: the edges at the centre read the rule at its valence, the others at 6 (issue 32; it was refused)
    assert ring_subdivision_matrix(depends_on_n, 5, 1).exact_matrix() == subdivision_matrix(depends_on_n, 5)
    two = ring_subdivision_matrix(depends_on_n, 5, 2).exact_matrix()
    assert two[:6, :6] == subdivision_matrix(depends_on_n, 5)
    assert ring_blocks(depends_on_n, 1).frequency_matrix().has(N)
    lopsided = triangle_scheme("lopsided", sp.Rational(1, 8), edge_end=sp.Rational(1, 2), edge_side=0)
    assert ring_subdivision_matrix(lopsided, 5, 2).size == 16


@pytest.mark.parametrize("name,rings,per_sector", [("catmull-clark", 2, 6), ("loop", 2, 3), ("catmull-clark", 3, 12), ("loop", 3, 6)])
def test_ring_sizes_and_closure(name, rings, per_sector):
    scheme = SCHEMES[name]
    for n in (3, 5):
        S = ring_subdivision_matrix(scheme, n, rings)
        assert S.size == 1 + per_sector * n
        inner = ring_subdivision_matrix(scheme, n, rings - 1)
        # the (K-1)-ring is invariant: its rows reach no further, and equal the smaller matrix
        for r in range(inner.size):
            assert max(S.rows[r]) < inner.size
            assert S.rows[r] == inner.rows[r]


@pytest.mark.parametrize("name", ["loop", "catmull-clark"])
@pytest.mark.parametrize("rings", [1, 2])
def test_blocks_rebuild_the_refined_matrix_at_small_valences(name, rings):
    scheme = SCHEMES[name]
    blocks = ring_blocks(scheme, rings)
    for n in (3, 4, 5, 6):
        S = ring_subdivision_matrix(scheme, n, rings)
        order = S.block_order()
        A, B = S.exact_matrix().extract(order, order), blocks.full_matrix(n)
        assert all(_zero(A[r, c] - B[r, c]) for r in range(S.size) for c in range(S.size))


@pytest.mark.parametrize("name", ["loop", "catmull-clark"])
def test_sparse_entries_are_the_dense_block_matrix_and_catch_a_changed_block(name):
    """``RingBlocks.entries`` (the check of :func:`ring_blocks` at two more valences) is ``full_matrix`` entry by
    entry, and the refinement's entries differ from blocks whose one offset weight was changed."""
    from symdecomp.analysis.frequency import _refined_entries
    from symdecomp.schemes.rings import CENTRE_WEIGHTS

    blocks, symbols = ring_blocks(SCHEMES[name], 2), {s: s for s in CENTRE_WEIGHTS}
    for n in (5, 16):
        dense = blocks.full_matrix(n, symbols).subs(N, n)
        sparse = blocks.entries(n, symbols)
        assert sparse == {(r, c): dense[r, c] for r in range(dense.rows) for c in range(dense.cols) if dense[r, c] != 0}
    S = ring_subdivision_matrix(SCHEMES[name], 16, 2, symbolic_centre=True)
    assert _refined_entries(S) == blocks.entries(16, symbols)
    (l, c), *rest = blocks.offsets[0][0]
    changed = RingBlocks(blocks.scheme, blocks.lattice, blocks.rings, blocks.classes, blocks.centre, blocks.centre_row,
                         blocks.centre_column, (((((l, c + sp.Rational(1, 64)), *rest), *blocks.offsets[0][1:]),
                                                 *blocks.offsets[1:])), blocks.weights)
    assert _refined_entries(S) != changed.entries(16, symbols)

def test_loop_spectrum_at_seven_is_the_closed_forms():
    spectrum = ring_spectrum(loop(), 7, digits=30)
    beta7 = loop_beta().subs(N, 7)
    expected = [sp.Integer(1), sp.Rational(5, 8) - 7 * beta7] + [sp.Rational(3, 8) + sp.cos(2 * sp.pi * k / 7) / 4 for k in range(1, 7)]
    found = [(e.exact, e.multiplicity) for e in spectrum.eigenvalues]
    assert sum(m for _, m in found) == 8
    for value in expected:  # each expected value is, exactly, one of the listed ones
        assert any(_zero(value - x) for x, _ in found)
    assert _zero(spectrum.eigenvalues[1].exact - (sp.Rational(3, 8) + sp.cos(2 * sp.pi / 7) / 4))
    assert spectrum.eigenvalues[1].multiplicity == 2 and spectrum.eigenvalues[1].frequencies == (1, 6)
    with mpmath.workdps(40):  # the printed value is the closed form to the stated digits
        assert abs(mpmath.mpf(spectrum.eigenvalues[1].text) - (mpmath.mpf(3) / 8 + mpmath.cos(2 * mpmath.pi / 7) / 4)) < mpmath.mpf(10) ** -29


@pytest.mark.parametrize("name", ["loop", "loop-warren", "catmull-clark"])
def test_two_ring_spectrum_contains_the_one_ring_spectrum(name):
    for n in (3, 4, 5, 7):
        one = {(e.text, e.multiplicity) for e in ring_spectrum(SCHEMES[name], n, 1, digits=25).eigenvalues}
        two = {e.text: e.multiplicity for e in ring_spectrum(SCHEMES[name], n, 2, digits=25).eigenvalues}
        assert all(two.get(text, 0) >= m for text, m in one)


def test_regular_two_ring_spectra():
    cc = {e.text: e.multiplicity for e in ring_spectrum(catmull_clark(), 4, 2, digits=10).eigenvalues}
    assert cc["1.0"] == 1 and cc["0.5"] == 2 and cc["0.25"] == 3 and sum(cc.values()) == 25
    lp = {e.text: e.multiplicity for e in ring_spectrum(loop(), 6, 2, digits=10).eigenvalues}
    assert lp["1.0"] == 1 and lp["0.5"] == 2 and lp["0.25"] == 3 and sum(lp.values()) == 19


def test_jordan_block_of_a_defective_vertex_rule():
    tuned = catmull_clark(alpha, beta)
    weights = jordan_vertex_weights(tuned, 5, sp.Rational(3, 8))
    spectrum = ring_spectrum(tuned.substitute(weights), 5, 1, digits=15)
    entry = next(e for e in spectrum.eigenvalues if e.text == "0.375")
    assert entry.jordan == (2,) and entry.multiplicity == 2
    plain = next(e for e in ring_spectrum(catmull_clark(), 4, 1, digits=15).eigenvalues if e.text == "0.25")
    assert plain.jordan == (1, 1, 1)


@pytest.mark.parametrize("name", ["loop", "loop-warren", "catmull-clark"])
@pytest.mark.parametrize("rings", [1, 2])
def test_certified_ring_spectra(name, rings):
    for n in (3, 4, 5, 7):
        c = certify_ring(SCHEMES[name], n, rings)
        assert c.ok and c.multiplicities_certified, c.message
        assert sum(c.multiplicities) == ring_subdivision_matrix(SCHEMES[name], n, rings).size


@pytest.mark.slow
@pytest.mark.parametrize("name", ["loop", "loop-warren", "catmull-clark"])
@pytest.mark.parametrize("rings", [1, 2, 3])
def test_certified_ring_spectra_wider(name, rings):
    for n in range(3, 25):
        c = certify_ring(SCHEMES[name], n, rings)
        assert c.ok and c.multiplicities_certified, c.message


def test_ring_certificate_agrees_with_the_one_ring_certificate():
    for n in (3, 4, 5, 8):
        a, b = certify_ring(catmull_clark(), n, 1), certify(catmull_clark(), n)
        assert (a.distinct, a.multiplicities) == (b.distinct, b.multiplicities)


def test_wrong_blocks_are_refuted():
    b = ring_blocks(loop(), 1)
    (offsets,), = b.offsets
    wrong = tuple((l, c + (sp.Rational(1, 64) if l == 0 else 0)) for l, c in offsets)
    bad = RingBlocks(b.scheme, b.lattice, b.rings, b.classes, b.centre, b.centre_row, b.centre_column, ((wrong,),), b.weights)
    c = certify_ring(loop(), 5, 1, blocks=bad)
    assert c.status is CrossCheckStatus.DISAGREE and "refuted" in c.message
    c = certify_ring(loop(), 5, 1, blocks=bad, method="structure")
    assert c.status is CrossCheckStatus.DISAGREE and "refuted" in c.message


@pytest.mark.parametrize("name", ["loop", "catmull-clark"])
def test_structural_certificate(name):
    for n in (3, 4, 7, 40):
        for rings in (1, 2):
            c = certify_ring(SCHEMES[name], n, rings, method="structure")
            assert c.ok, c.message
            assert c.multiplicities == certify_ring(SCHEMES[name], n, rings).multiplicities


def test_numeric_ring_check():
    for name in ("loop", "catmull-clark"):
        for n in (3, 6, 10):
            r = ring_numeric_check(SCHEMES[name], n, 2, digits=10)
            assert r.ok, r.message


def test_numeric_ring_check_crosses_the_pool(capsys):
    """A K-ring check travels from a worker: its matches hold no Arb ball (the factored spectrum's hull does not pickle)."""
    import pickle

    r = ring_numeric_check(loop(), 4, 2, digits=10)
    assert pickle.loads(pickle.dumps(r)).matches == r.matches
    assert main(["check", "--scheme", "loop", "--n", "3:5", "--rings", "2", "--quiet"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].startswith("3 valences: 3 agree")


def test_masks_match_the_one_ring_masks_and_loop_limit_formula():
    for n in (3, 5, 8):
        a = ring_masks(catmull_clark(), n, 1, digits=15)
        b = limit_masks_at(catmull_clark(), n).as_json(15)
        for key in ("a", "b"):
            assert a["position"][key] == b["position"][key]
            assert all(float(x) == pytest.approx(float(y), abs=1e-14) for x, y in zip(a["tangents"][0][key], b["tangents"][0][key]))
        # Loop: limit position (1 - n chi) O + chi sum a_i, chi = 1/(3/(8 beta) + n)
        m = ring_masks(loop(), n, 1, digits=20)
        with mpmath.workdps(30):
            bn = mpmath.mpf(sp.N(loop_beta().subs(N, n), 40))
            chi = 1 / (3 / (8 * bn) + n)
            assert abs(mpmath.mpf(m["position"]["a"][0]) - chi) < mpmath.mpf(10) ** -18
            assert abs(mpmath.mpf(m["position"]["O"]) - (1 - n * chi)) < mpmath.mpf(10) ** -18


def _cli(capsys, *args):
    """Run the command in-process: ``(exit code, stdout, stderr)`` (argparse errors exit 2)."""
    try:
        code = main(list(args))
    except SystemExit as exc:
        code = exc.code
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_any_scheme_route(capsys):
    code, out, err = _cli(capsys, "spectrum", "7", "--scheme", "loop", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["eigenvalues"][0]["exact"] == "1" and data["eigenvalues"][1]["multiplicity"] == 2
    code, out, _ = _cli(capsys, "check", "--scheme", "loop", "--rings", "2", "--n", "3:6", "--certify", "--json", "--jobs", "1")
    assert code == 0 and json.loads(out)["summary"]["agree"] == 4
    code, out, _ = _cli(capsys, "check", "--n", "3:5", "--certify", "--structural", "--json", "--jobs", "1")
    assert code == 0 and json.loads(out)["summary"]["agree"] == 3
    for bad in (("spectrum", "5", "--rings", "4"), ("check", "--scheme", "loop", "--n", "5", "--dps", "30"),
                ("charpoly", "5", "--scheme", "loop", "--free-weights"), ("spectrum", "5", "--scheme", "nope"),
                ("tune", "5", "--scheme", "loop"), ("check", "--n", "5", "--structural")):
        code, _, err = _cli(capsys, *bad)
        assert code == 2 and "error:" in err.strip().splitlines()[-1] and "Traceback" not in err
    code, out, _ = _cli(capsys, "charpoly", "5", "--scheme", "loop", "--json")
    assert code == 0 and json.loads(out)["matches_matrix"] is True
    code, out, _ = _cli(capsys, "masks", "5", "--scheme", "loop", "--rings", "2", "--json")
    assert code == 0 and json.loads(out)["position"]["classes"]["2,0"][0] == "0.0"


def test_cyclotomic_values_are_exact():
    m = sp.Symbol("m")
    c7 = cyclotomic_value(sp.cos(2 * sp.pi / m), {m: 7})
    # 8 c^3 + 4 c^2 - 4 c - 1 = 0 for c = cos(2 pi/7): exact in Q(zeta_14)
    assert (c7 * c7 * c7 * 8 + c7 * c7 * 4 - c7 * 4 - 1).poly == 0
    assert cyclotomic_value(sp.cos(2 * sp.pi / m) ** 2 + sp.sin(2 * sp.pi / m) ** 2, {m: 9}).poly == 1
    with pytest.raises(ValueError):
        cyclotomic_value(sp.sqrt(2))


@pytest.mark.parametrize("scheme, rings, valences", [(catmull_clark(), 1, range(3, 11)), (loop(), 1, range(3, 11)), (loop(), 2, range(3, 7))])
def test_structural_certificate_certifies_the_dense_multiplicities(scheme, rings, valences):
    for n in valences:
        fast = certify_ring(scheme, n, rings, method="structure")
        dense = certify_ring(scheme, n, rings)
        assert fast.multiplicities_certified and dense.multiplicities_certified, fast.message
        assert fast.multiplicities == dense.multiplicities and fast.distinct == dense.distinct


def test_cluster_multiplicities_refuse_what_they_cannot_prove():
    """Merging two clusters, or listing one twice, is caught (exactly: unequal roots; in Arb: overlap)."""
    import dataclasses

    from symdecomp.verify.multiplicities import cluster_multiplicities

    def merge_two(spectrum):
        a, b, *rest = spectrum.eigenvalues[1:]
        merged = dataclasses.replace(a, members=a.members + b.members, multiplicity=a.multiplicity + b.multiplicity)
        return dataclasses.replace(spectrum, eigenvalues=(spectrum.eigenvalues[0], merged, *rest))

    for scheme, n, why in ((loop(), 7, "not all equal"), (catmull_clark(), 5, "not decidable exactly")):
        spectrum = ring_spectrum(scheme, n, 1, exact=False, jordan=False)
        blocks = ring_blocks(scheme, 1)
        assert cluster_multiplicities(scheme, blocks, spectrum) is None
        assert why in cluster_multiplicities(scheme, blocks, merge_two(spectrum))
        twice = dataclasses.replace(spectrum, eigenvalues=spectrum.eigenvalues + spectrum.eigenvalues[-1:])
        assert "overlap" in cluster_multiplicities(scheme, blocks, twice)
