"""``claims --scheme <zoo scheme>`` (issue 30): every claim listed, its status computed from the scheme's model.

The claims that involve no scheme (Section 2; Section 6's CB-matrices) keep the verdicts they have for every scheme,
the same on both routes (a zoo scheme, a 1-ring scheme on triangles); each other claim is
``not applicable`` with the reason of the first zoo requirement the scheme does not meet (its topology, its
support, then its lattice against the claim's), followed by what the claim needs, or, where the statement reaches
beyond the 1-ring, with the zoo command that answers it.
"""

import dataclasses
import json

import jsonschema
import pytest

from symdecomp.claims import Status, all_claims, check_claim, scope_summary
from symdecomp.claims.applicability import FACE_NEIGHBOURS, ONE_RING_SUPPORT, PRIMAL_SECTOR, PRIMAL_VERTEX, ZOO_REQUIREMENTS
from symdecomp.claims.batch import check_claims
from symdecomp.claims.zoo_claims import ENGINE_COMMANDS, zoo_claim_result
from symdecomp.cli import main
from symdecomp.cli.json_envelope import json_schema
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.lattice import QUAD, TRIANGLE, lattice
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from tests.analysis.zoo_engine_schemes import catmull_clark_stencils, doo_sabin_stencils, loop_stencils

#: The shipped zoo schemes and the first zoo requirement each does not meet: the table of the issue.
FIRST_UNMET = {"doo-sabin": PRIMAL_VERTEX, "midedge": PRIMAL_VERTEX, "sqrt3": PRIMAL_VERTEX,
               "modified-butterfly": ONE_RING_SUPPORT}


def _first_unmet(scheme, parameter="n"):
    return next(req for req in ZOO_REQUIREMENTS[parameter] if req.unmet(scheme) is not None)


@pytest.mark.parametrize("name", sorted(FIRST_UNMET))
def test_the_table_of_statuses_of_each_shipped_zoo_scheme(name, capsys):
    assert main(["claims", "--scheme", name, "--json", "--no-progress"]) == 0
    data = json.loads(capsys.readouterr().out)
    jsonschema.validate(data, json_schema())
    rows = {r["label"]: r for r in data["rows"]}
    claims = all_claims()
    assert list(rows) == [c.label for c in claims]
    scheme = load_scheme(name)
    assert _first_unmet(scheme) is FIRST_UNMET[name]
    reasons = {p: str(_first_unmet(scheme, p).unmet(scheme)) for p in ZOO_REQUIREMENTS}  # a vertex's, a sector's
    for c in claims:
        row = rows[c.label]
        assert row["scheme"] == name
        if c.involves_no_scheme:  # no scheme in the statement: the verdict every scheme gets
            assert row["status"] == check_claim(c.label).status.value
            assert row["evidence"].startswith("the statement involves no scheme: ")
        elif (instead := c.reads_instead(scheme)) is not None:  # read on another lattice: its reference's verdict
            read = check_claim(c.label, instead)
            assert row["status"] == read.status.value and row["evidence"].endswith(str(read.evidence))
            assert row["evidence"].startswith("the statement is about a scheme on ")
        elif c.module in ENGINE_COMMANDS:
            assert row["status"] == Status.NOT_APPLICABLE.value
            assert row["evidence"].endswith(f"{ENGINE_COMMANDS[c.module][1]} --scheme {name} --n N")
        elif lattice(scheme.lattice) not in c.lattices:  # the most basic reason first: the claim's 1-ring is on another lattice
            assert row["status"] == Status.NOT_APPLICABLE.value
            assert row["evidence"].startswith("the claim is about the (") and row["evidence"].endswith(f"'{name}' subdivides "
                                                                                                       f"{scheme.lattice} meshes")
        else:  # on the claim's lattice: what the scheme has, then what the claim needs
            assert row["status"] == Status.NOT_APPLICABLE.value
            about = "a sector of k faces" if c.parameter == "k" else "the ("  # a sector claim's, or a vertex's 1-ring
            assert row["evidence"].startswith(f"{reasons[c.parameter]}; the claim is about {about}") and "subdivides" not in row["evidence"]


def test_the_scheme_free_claims_have_one_verdict_for_two_different_schemes():
    for c in all_claims():
        if c.involves_no_scheme:
            a, b = check_claim(c.label, catmull_clark()), check_claim(c.label, loop())
            assert (a.status, str(a.evidence)) == (b.status, str(b.evidence))


class _Unreadable:
    """A scheme that fails on any use: a check that runs with it read no scheme."""

    def __getattribute__(self, name):
        raise AssertionError(f"the check read scheme.{name}")


def test_section_6_s_cb_matrix_claims_involve_no_scheme_on_both_routes():
    """Proposition 6.1-6.3, Eq. 46-50 and Remark 6.1 are about CB-matrices in general: they involve no scheme, so the zoo
    route checks them as the 1-ring route does for Loop (it said 'not applicable'); the table test above compares every
    row with Catmull-Clark's, test_the_scheme_free_claims_have_one_verdict_for_two_different_schemes Loop's."""
    labels = {c.label for c in all_claims() if c.section == "6" and c.involves_no_scheme}
    assert labels == {"Proposition 6.1", "Proposition 6.2", "Eq. 46", "Eq. 47", "Eq. 48", "Eq. 49", "Eq. 50", "Remark 6.1",
                      "Proposition 6.3"}
    cc, zoo = check_claim("Proposition 6.1"), check_claim("Proposition 6.1", load_scheme("doo-sabin"))
    assert cc.status is Status.CORRECTED
    assert (zoo.status, str(zoo.evidence)) == (cc.status, "the statement involves no scheme: " + str(cc.evidence))


def test_a_claim_that_requires_nothing_and_does_not_declare_it_reads_no_scheme_reads_one():
    """The declaration is complete: every claim without requirements that is not declared to read no scheme stops on a
    scheme that fails on any use (the declared ones run on it: tests/claims/test_mutations.py)."""
    for c in all_claims():
        if c.reads_scheme and not c.requires:
            with pytest.raises(AssertionError, match="the check read scheme"):
                c.check(_Unreadable())


def test_the_reasons_name_the_scheme_s_own_data():
    assert "n-sided face of a dual scheme" in str(PRIMAL_VERTEX.unmet(load_scheme("doo-sabin")))
    # a sector claim is about a sector of k faces around a vertex, not about the n-sided face
    sector = str(PRIMAL_SECTOR.unmet(load_scheme("doo-sabin")))
    assert sector.startswith("a sector of k faces is centred on its vertex O, which a step of a dual scheme does not keep")
    assert "n-sided face" not in sector and "'doo-sabin' makes a new point per face corner" in sector
    assert str(PRIMAL_SECTOR.unmet(load_scheme("sqrt3"))) == str(PRIMAL_VERTEX.unmet(load_scheme("sqrt3")))
    assert "√3 topology (analysed over 2 steps)" in str(PRIMAL_VERTEX.unmet(load_scheme("sqrt3")))
    assert str(ONE_RING_SUPPORT.unmet(load_scheme("modified-butterfly"))).startswith("the edge rule reaches two rings out")


def test_each_requirement_s_verdict_flips_with_the_scheme():
    primal_file, dual_file = load_scheme("modified-butterfly"), load_scheme("doo-sabin")
    assert PRIMAL_VERTEX.unmet(primal_file) is None and PRIMAL_VERTEX.unmet(dual_file) is not None
    cc = catmull_clark_stencils()
    assert PRIMAL_VERTEX.unmet(cc) is None
    assert PRIMAL_VERTEX.unmet(dataclasses.replace(cc, topology="dual")) is not None  # one field changed, nothing else
    assert ONE_RING_SUPPORT.unmet(loop_stencils()) is None and ONE_RING_SUPPORT.unmet(primal_file) is not None
    assert PRIMAL_VERTEX.unmet(doo_sabin_stencils()) is not None  # Doo-Sabin is on quads: its topology is what fails
    assert PRIMAL_SECTOR.unmet(cc) is None and PRIMAL_SECTOR.unmet(dataclasses.replace(cc, topology="dual")) is not None
    assert all(req.unmet(catmull_clark()) is None for reqs in ZOO_REQUIREMENTS.values() for req in reqs)  # the 1-ring primal model meets them all


def test_a_zoo_scheme_meeting_the_model_is_told_to_use_the_one_ring_format():
    label = next(c.label for c in all_claims()  # on its lattice: the reason is the scheme's support
                 if c.reads_scheme and c.module not in ENGINE_COMMANDS and TRIANGLE in c.lattices and not c.reads_on)
    result = zoo_claim_result(label, catmull_clark_stencils())
    assert result.status is Status.NOT_APPLICABLE
    assert "meets the 1-ring primal model" in str(result.evidence)


def test_the_summary_line_counts_add_up(capsys):
    assert main(["claims", "--scheme", "sqrt3", "--no-progress"]) == 0
    lines = capsys.readouterr().out.splitlines()
    head, counts = lines[-2].split(": ", 1)
    tally = {status: int(k) for k, status in (part.split(" ", 1) for part in counts.split(", "))}
    assert head == f"{len(all_claims())} claims" and sum(tally.values()) == len(all_claims())
    listed = [line for line in lines[:-2] if not line.startswith(" ")]
    assert {s: sum(f"  {s}  " in line for line in listed) for s in tally} == tally
    sqrt3 = load_scheme("sqrt3")
    assert lines[-1] == str(scope_summary(check_claim(c.label, sqrt3) for c in all_claims()))


def test_a_malformed_zoo_file_is_one_line_and_exit_2(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text('name = "x"\nmesh = "quad"\ntopology = "nowhere"\n')
    assert main(["claims", "--scheme", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--scheme" in err


def test_the_api_answers_a_zoo_scheme_as_the_command_does():
    scheme = load_scheme("modified-butterfly")
    label = next(c.label for c in all_claims()  # on its lattice: the reason is the scheme's support
                 if c.reads_scheme and c.module not in ENGINE_COMMANDS and TRIANGLE in c.lattices and not c.reads_on)
    result = check_claim(label, scheme)
    assert result.status is Status.NOT_APPLICABLE and str(result.evidence).startswith(str(ONE_RING_SUPPORT.unmet(scheme)) + "; ")
    assert [r.status for r in check_claims([label], scheme, jobs=2)] == [Status.NOT_APPLICABLE]


def test_a_claim_read_on_another_lattice_has_the_same_verdict_on_both_routes():
    """"Curvature regime: Catmull-Clark" reads a triangle scheme's lattice-mate Catmull-Clark on the 1-ring route (Loop)
    and, by the same test (Claim.reads_instead), on the zoo route (sqrt3, modified butterfly); it reads a quad scheme of
    the zoo itself, which the 1-ring model does not fit. Loop's claims the other way round."""
    by_label = {c.label: c for c in all_claims()}
    cc_claim, loop_claim = by_label["Curvature regime: Catmull-Clark"], by_label["Curvature regime: Loop"]
    sqrt3, butterfly, doo_sabin = (load_scheme(name) for name in ("sqrt3", "modified-butterfly", "doo-sabin"))
    assert [cc_claim.reads_instead(s) for s in (catmull_clark(), doo_sabin)] == [None, None]
    assert {cc_claim.reads_instead(s).name for s in (loop(), sqrt3, butterfly)} == {"catmull-clark"}
    assert loop_claim.reads_instead(doo_sabin).name == "loop" and loop_claim.reads_instead(sqrt3) is None
    primal, zoo = check_claim(cc_claim.label, loop()), check_claim(cc_claim.label, sqrt3)
    assert primal.status is Status.PROVED and zoo.status is primal.status
    assert str(zoo.evidence) == ("the statement is about a scheme on quad meshes and 'sqrt3' is on triangle meshes, so the "
                                 "check reads catmull-clark, as for every scheme on triangle meshes: " + str(primal.evidence))
    assert "for catmull-clark" in str(primal.evidence)
    assert check_claim(cc_claim.label, doo_sabin).status is Status.NOT_APPLICABLE  # it would read Doo-Sabin's rules
    assert check_claim(loop_claim.label, sqrt3).status is Status.NOT_APPLICABLE
    assert check_claim(loop_claim.label, doo_sabin).status is check_claim(loop_claim.label, loop()).status


def _reasons(name, capsys):
    assert main(["claims", "--scheme", name, "--json", "--no-progress"]) == 0
    return {r["label"]: r["evidence"] for r in json.loads(capsys.readouterr().out)["rows"] if r["status"] == "not applicable"}


@pytest.mark.parametrize("name", ["sqrt3", "modified-butterfly"])
def test_a_triangle_scheme_is_told_what_each_claim_needs_not_a_quad_mesh_for_loop_s_claims(name, capsys):
    """The reasons printed for a triangle scheme of the zoo: Loop's claims are about the triangle 1-ring (they told sqrt3
    it needs 'the (2n+1)-point 1-ring of a vertex of a quad mesh'); the paper's quad 1-ring claims say so and name the
    scheme's own lattice, the whole reason (its topology or support would not matter on triangles); a claim about
    either lattice names both, after what the scheme has."""
    reasons = _reasons(name, capsys)
    by_label = {c.label: c for c in all_claims()}
    loop_claims = {"Curvature regime: Loop", "Loop's vertex weight"}
    assert {label for label in loop_claims} <= set(reasons)
    for label in loop_claims:
        assert "the claim is about the (n+1)-point 1-ring of a vertex of a triangle mesh refined by a primal step" in reasons[label]
        assert "quad" not in reasons[label] and "subdivides" not in reasons[label]
    quad_ring = [label for label in reasons if FACE_NEIGHBOURS in by_label[label].requires and by_label[label].module not in ENGINE_COMMANDS]
    assert "Eq. 34" in quad_ring
    for label in quad_ring:
        assert reasons[label] == ("the claim is about the (2n+1)-point 1-ring of a vertex of a quad mesh refined by a "
                                  f"primal step, and '{name}' subdivides triangle meshes")
    either = reasons["1-ring suffices (after Eq. 51)"]
    assert "(2n+1)-point 1-ring of a vertex of a quad mesh or the (n+1)-point 1-ring of a vertex of a triangle mesh" in either
    own = {p: str(reqs[0 if name == "sqrt3" else 1].unmet(load_scheme(name))) for p, reqs in ZOO_REQUIREMENTS.items()}
    assert all(reason.startswith(own[by_label[label].parameter] + "; ") for label, reason in reasons.items()
               if by_label[label].module not in ENGINE_COMMANDS and TRIANGLE in by_label[label].lattices)


def test_the_claim_s_lattices_come_from_what_it_reads_and_requires():
    by_label = {c.label: c for c in all_claims()}
    assert by_label["Eq. 34"].lattices == (QUAD,)  # face neighbours: Loop does not meet it
    assert by_label["Curvature regime: Loop"].lattices == (TRIANGLE,)  # reads_on
    assert by_label["Curvature regime: Catmull-Clark"].lattices == (QUAD,)
    assert by_label["1-ring suffices (after Eq. 51)"].lattices == (QUAD, TRIANGLE)
    triangle_stencils = loop_stencils()  # primal, 1-ring, on triangles: only its lattice misses a quad claim
    eq34 = zoo_claim_result("Eq. 34", triangle_stencils)
    assert str(eq34.evidence) == ("the claim is about the (2n+1)-point 1-ring of a vertex of a quad mesh refined by a primal "
                                  f"step, and {triangle_stencils.name!r} subdivides triangle meshes")
    assert "meets the 1-ring primal model" in str(zoo_claim_result("Loop's vertex weight", triangle_stencils).evidence)


def test_a_sector_claim_tells_a_zoo_scheme_it_is_about_a_sector_not_the_1_ring_of_a_vertex(capsys):
    """The B.2 claims (parameter k) are about a sector of k faces between two sharp edges: the reason says so, with the
    sector's point count on each lattice, which agrees with the sector model's 1-ring at every k tried (k = 1..8)."""
    import re

    from symdecomp.schemes.sector import SharpVertex

    reasons = _reasons("doo-sabin", capsys)
    sector = [c for c in all_claims() if c.parameter == "k"]
    assert len(sector) == 6
    for c in sector:
        reason = reasons[c.label]
        assert "1-ring of a vertex" not in reason and "a sector of k faces between two sharp edges of a quad mesh" in reason
        counts = {x: (a, b) for x, a, b in re.findall(r"a (quad|triangle) mesh \(its \((\d*)k\+(\d+)\)-point 1-ring\)", reason)}
        assert set(counts) == {"quad", "triangle"}
        for name, (slope, offset) in counts.items():
            for k in range(1, 9):
                points = len(SharpVertex.boundary(k, lattice(name)).vertex_order())
                assert points == int(slope or 1) * k + int(offset), (name, k)
