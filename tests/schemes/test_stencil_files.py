"""The zoo's scheme files (``symdecomp.schemes.stencil_files``): the documented example is read by the parser,
every shipped family round-trips, a malformed file is one line naming the key, affinity is checked where the scheme
is built, and ``load_scheme`` hands the zoo's names and files with a ``topology`` key to this format."""

from __future__ import annotations

import re
import textwrap

import pytest
import sympy as sp

from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError, NotAffineError
from symdecomp.schemes import stencil_files as sf
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.stencils import J, M, N, StencilScheme

DOC = sf.__doc__

HEAD = 'name = "t"\nmesh = "quad"\ntopology = "dual"\n'


def _example() -> str:
    (block,) = re.findall(r"::\n\n((?:    .*\n|\n)+)", DOC)
    return textwrap.dedent(block)


def test_the_documented_example_is_the_shipped_doo_sabin():
    scheme = sf.stencil_scheme_from_text(_example())
    assert scheme == load_scheme("doo-sabin") == sf.load_zoo("doo-sabin")
    (term,) = scheme.rules_of("corner").rules[0].terms
    # the corner weights at m = 4 are the biquadratic B-spline's 9/16, 3/16, 1/16, 3/16
    assert [term.weight.subs({M: 4, J: j}) for j in range(4)] == [sp.Rational(9, 16), sp.Rational(3, 16), sp.Rational(1, 16),
                                                                  sp.Rational(3, 16)]
    # and Doo and Sabin's alpha_0 = 1/4 + 5/(4 m)
    assert sp.simplify(term.weight.subs(J, 0) - (sp.Rational(1, 4) + sp.Rational(5, 4) / M)) == 0


@pytest.mark.parametrize("name", sorted(sf.ZOO_FILES))
def test_each_shipped_family_round_trips_and_says_where_it_comes_from(name):
    scheme = sf.load_zoo(name)
    assert isinstance(scheme, StencilScheme) and scheme.name == name
    assert re.search(r"\b(19|20)\d\d\b", scheme.source), "the source names its year"
    text = sf.stencil_scheme_to_text(scheme)
    again = sf.stencil_scheme_from_text(text)
    assert again == scheme
    assert sf.stencil_scheme_to_text(again) == text


def test_a_scheme_with_parameters_round_trips():
    text = HEAD + 'parameters = ["w"]\n[[corner]]\nterms = [{walk = "", weight = "1 - 2*w"}, {walk = "next", weight = "w"},' \
        ' {walk = "prev", weight = "w"}]\n'
    scheme = sf.stencil_scheme_from_text(text)
    assert [str(p) for p in scheme.parameters] == ["w"]
    assert sf.stencil_scheme_from_text(sf.stencil_scheme_to_text(scheme)) == scheme


def test_the_butterfly_rules_are_chosen_by_the_valences_at_the_anchor():
    edge = sf.load_zoo("modified-butterfly").rules_of("edge")
    regular = 6

    def chosen(origin, tip):
        return next((i for i, r in enumerate(edge.rules) if r.applies(origin, tip, regular=regular)), None)

    assert chosen(6, 6) == 0 and chosen(3, 6) == 1 and chosen(4, 6) == 2 and chosen(5, 6) == 3 and chosen(9, 9) == 3
    assert chosen(6, 5) is None  # that orientation leaves the edge to its extraordinary end
    # the K = 3 and K = 4 stencils are Zorin, Schroeder and Sweldens' 5/12, -1/12, -1/12 and 3/8, 0, -1/8, 0
    s3 = edge.rules[1].terms[1].weight
    s4 = edge.rules[2].terms[1].weight
    assert [s3.subs(J, j) for j in range(3)] == [sp.Rational(5, 12), sp.Rational(-1, 12), sp.Rational(-1, 12)]
    assert [s4.subs(J, j) for j in range(4)] == [sp.Rational(3, 8), 0, sp.Rational(-1, 8), 0]


BAD = [
    ('[[corner]]\nterms = [{walk = "next", weight = "1"}, {walk = "nxt", weight = "0"}]',
     "[[corner]] 1: terms 2: walk: unknown move 'nxt' (known: next, prev, twin)"),
    ('[[corner]]\nterms = [{walk = "", weight = 0.5}, {walk = "next", weight = "1/2"}]',
     '[[corner]] 1: terms 1: weight: 0.5 is a float; give an exact rational such as "3/8"'),
    ('[[corner]]\nterms = [{walk = "", weight = "1", over = "all"}]',
     "[[corner]] 1: terms 1: over must be one of one, ring, face, got 'all'"),
    ('[[corner]]\norigin = 2\nterms = [{walk = "", weight = "1"}]',
     "[[corner]] 1: origin must be one of any, regular, irregular or a valence 3..64, got 2"),
    ('[[corner]]\nterms = [{walk = "", weight = "1", colour = "red"}]',
     "[[corner]] 1: terms 1: unknown key 'colour' (known: walk, weight, over, source)"),
    ('[[corner]]\nterms = [{walk = "", weight = "j"}]',
     '[[corner]] 1: terms 1: weight uses j, but the term is over one point (give over = "ring" or "face")'),
    ('[[corner]]\nterms = [{walk = "", weight = "1/2"}, {walk = "next", weight = "1/4"}]',
     "[[corner]] 1: not affine: the weights sum to 3/4, not 1"),
    ('[[corner]]\nterms = [{walk = "", weight = "cos(2*pi*j/m)/m", over = "face"}]',
     "[[corner]] 1: not affine: the weights sum to 0, not 1"),
    ('[[corner]]\nterms = [{walk = "", weight = "1"}]\n[[corner]]\nterms = [{walk = "", weight = "2"}]',
     "[[corner]] 2: not affine: the weights sum to 2, not 1"),
    ('[[edge]]\nends = "sum"\nterms = [{walk = "", weight = "1"}]\n[[edge]]\nends = "average"\nterms = [{walk = "", weight = "1"}]',
     "[[edge]]: ends is given as both average and sum; one kind has one way"),
    ('[[corner]]\nends = "sum"\nterms = [{walk = "", weight = "1"}]', "[[corner]] 1: ends: only [[edge]] rules have two ends"),
    ('[[corner]]\nterms = [{walk = "", weight = "cos(1)"}]', "[[corner]] 1: terms 1: weight: weight 'cos(1)': cos/sin of 1: only "
     "rational multiples of pi such as 2*pi/n are exact in the number fields the toolkit computes in (cyclotomic fields)"),
    ('[[edge]]\nterms = [{walk = "", weight = "1", source = "edge"}]',
     "[edge]: a term uses new edge points, which are not made before it (the order: edge)"),
    ('colour = 1\n[[corner]]\nterms = [{walk = "", weight = "1"}]',
     "unknown key 'colour' (known: name, mesh, topology, steps, parameters, source, interpolatory, vertex, edge, face, corner)"),
]


@pytest.mark.parametrize(("body", "message"), BAD, ids=[m[:40] for _, m in BAD])
def test_a_malformed_file_is_one_line_naming_the_key(body, message):
    with pytest.raises((InvalidSchemeError, NotAffineError)) as caught:
        sf.stencil_scheme_from_text(HEAD + body, source="bad.toml")
    assert str(caught.value) == f"bad.toml: {message}"


@pytest.mark.parametrize(("head", "message"), [
    ('mesh = "quad"\n', "missing key 'topology' (one of primal, dual, sqrt3)"),
    ('mesh = "hex"\ntopology = "dual"\n', "mesh 'hex' is not supported (known: quad, triangle)"),
    ('mesh = "quad"\ntopology = "dual"\nsteps = 3\n', "steps must be 1 or 2, got 3"),
    ('mesh = "quad"\ntopology = "dual"\nparameters = ["m"]\n', "parameters: 'm' is reserved (the size of the anchor's face)"),
])
def test_the_top_level_keys_are_checked(head, message):
    with pytest.raises(InvalidSchemeError) as caught:
        sf.stencil_scheme_from_text(head + '[[corner]]\nterms = [{walk = "", weight = "1"}]\n', source="bad.toml")
    assert str(caught.value) == f"bad.toml: {message}"


def test_an_interpolatory_scheme_keeps_its_old_vertices():
    text = 'mesh = "triangle"\ntopology = "primal"\ninterpolatory = true\n[[vertex]]\nterms = [{walk = "", weight = "1/2"}, ' \
        '{walk = "next", weight = "1/(2*n)", over = "ring"}]\n'
    with pytest.raises(InvalidSchemeError, match=r"^s: \[\[vertex\]\] 1: interpolatory = true, but the rule moves the old vertex"):
        sf.stencil_scheme_from_text(text, source="s")


def test_a_rule_for_one_valence_is_affine_there_only():
    # 5/12, -1/12, -1/12 sums with 3/4 to 1 at n = 3 and not at any other n: accepted with origin = 3, refused without
    rule = '[[edge]]\n{}terms = [{{walk = "", weight = "3/4"}}, {{walk = "next", weight = "KroneckerDelta(j, 0)/2 - 1/12", over = "ring"}}]\n'
    head = 'mesh = "triangle"\ntopology = "primal"\n'
    sf.stencil_scheme_from_text(head + rule.format("origin = 3\n"))
    with pytest.raises(NotAffineError, match=r"\[\[edge\]\] 1: not affine: the weights sum to -\(n - 15\)/12, not 1"):
        sf.stencil_scheme_from_text(head + rule.format(""), source="s")
    with pytest.raises(NotAffineError, match=r"the weights sum to 5/6 at n = 5, not 1"):
        sf.stencil_scheme_from_text(head + rule.format("origin = 5\n"), source="s")


@pytest.mark.slow
def test_a_sum_without_a_closed_form_is_checked_valence_by_valence():
    # cos(pi j/n)**2 has no closed sum here: its sum over the ring is n/2 exactly at every n >= 2, checked at each n
    ok = '[[vertex]]\nterms = [{walk = "", weight = "1/2"}, {walk = "next", weight = "cos(pi*j/n)**2/n", over = "ring"}]\n'
    sf.stencil_scheme_from_text('mesh = "triangle"\ntopology = "primal"\n' + ok)
    bad = ok.replace("1/2", "1/3", 1)
    with pytest.raises(NotAffineError, match=r"the weights sum to 5/6 at n = 3, m = 3, not 1"):
        sf.stencil_scheme_from_text('mesh = "triangle"\ntopology = "primal"\n' + bad, source="s")


def test_load_scheme_reads_a_file_with_a_topology_key_in_this_format(tmp_path):
    path = tmp_path / "my-doo-sabin.toml"
    path.write_text(_example().replace('name = "doo-sabin"\n', ""), encoding="utf-8")
    scheme = load_scheme(path)
    assert isinstance(scheme, StencilScheme) and scheme.name == "my-doo-sabin"
    assert scheme.kinds == load_scheme("doo-sabin").kinds
    bad = tmp_path / "bad.toml"
    bad.write_text(HEAD + '[[corner]]\nterms = [{walk = "nxt", weight = "1"}]\n', encoding="utf-8")
    with pytest.raises(InvalidSchemeError, match=r"bad.toml: \[\[corner\]\] 1: terms 1: walk: unknown move 'nxt'"):
        load_scheme(bad)


def test_a_malformed_zoo_file_on_the_command_line_is_one_line_and_exit_2(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text(HEAD + '[[corner]]\nterms = [{walk = "nxt", weight = "1"}]\n', encoding="utf-8")
    assert main(["spectrum", "5", "--scheme", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err == (f"symdecomp: error: argument --scheme: {bad}: [[corner]] 1: terms 1: walk: unknown move 'nxt' "
                   "(known: next, prev, twin) (see 'symdecomp spectrum --help')\n")


def test_the_weights_use_the_stencil_model_symbols():
    weight = sf.load_zoo("modified-butterfly").rules_of("edge").rules[3].terms[1].weight
    assert weight.free_symbols == {J, N}
