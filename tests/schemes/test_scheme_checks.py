"""A scheme is validated once, at the door (issue 30): when it is built, by the API or by --scheme's parsing.

Every :class:`~symdecomp.schemes.scheme.Scheme` passes :func:`~symdecomp.schemes.scheme_checks.validate_scheme`
when it is built; the code that takes one trusts it (``check_scheme`` is a type test). These tests count, on
one trip through ``c1``, how often a scheme is validated and how often its rules are read as rules of the
whole mesh (sympy identities of the weights).
"""

import collections
import dataclasses
import pathlib

import pytest

import symdecomp.schemes.scheme as scheme_module
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.lattice import QuadLattice
from symdecomp.schemes.scheme import Scheme, catmull_clark

CORPUS = pathlib.Path(__file__).resolve().parents[1] / "corpus"


@pytest.fixture
def counts(monkeypatch):
    """Calls of the door (``validate_scheme``), of ``check_scheme`` and of the quad lattice's whole-mesh reading."""
    seen = {"validated": 0, "checked": 0, "read as mesh rules": collections.Counter()}
    validate, check_type, read = scheme_module.validate_scheme, scheme_module.check_type, QuadLattice.mesh_rules

    def counted_validate(scheme):
        seen["validated"] += 1
        return validate(scheme)

    def counted_check_type(value, kind, argument, **kw):
        seen["checked"] += kind is Scheme
        return check_type(value, kind, argument, **kw)

    def counted_read(scheme):
        seen["read as mesh rules"][scheme.name] += 1
        return read(scheme)

    monkeypatch.setattr(scheme_module, "validate_scheme", counted_validate)
    monkeypatch.setattr(scheme_module, "check_type", counted_check_type)
    monkeypatch.setattr(QuadLattice, "mesh_rules", staticmethod(counted_read))
    return seen


@pytest.mark.slow
def test_one_c1_run_validates_no_scheme_and_reads_the_rules_once(counts):
    from symdecomp.analysis import characteristic
    from symdecomp.analysis.frequency import ring_blocks
    from symdecomp.schemes import rings
    from symdecomp.verify.c1 import c1_test

    for cache in (characteristic._ring_layout, characteristic._inapplicable, ring_blocks, rings._whole_mesh_rules):
        cache.cache_clear()  # a cold start: the trip reads what it needs
    scheme = dataclasses.replace(catmull_clark(), name="catmull-clark, counted")  # new to every cache
    counts["validated"] = 0
    verdicts = [c1_test(scheme, n) for n in (3, 5, 6)]
    assert [v.verdict for v in verdicts] == ["c1"] * 3
    # the scheme was validated when built; the trip trusts it (the reference scheme too: built once per process)
    assert counts["validated"] == 0
    # the entry points' checks are type tests on the one scheme object, no re-validation
    assert counts["checked"] > 0
    # the rules of the reference scheme (whose ring layout the C1 test reads) are read as whole-mesh rules once, not
    # once per ring matrix; the scheme's own regular rules are compared with the reference's, never read so
    assert counts["read as mesh rules"] == {"catmull-clark": 1}


def test_the_command_line_validates_a_scheme_file_once_at_its_parsing(counts, capsys):
    assert main(["c1", "--n", "5", "--scheme", str(CORPUS / "catmull-clark.toml"), "--quiet"]) == 0
    assert "C1 certified" in capsys.readouterr().out
    assert counts["validated"] == 1


def test_the_door_refuses_rules_the_lattice_does_not_have():
    cc = catmull_clark()
    with pytest.raises(InvalidSchemeError, match=r"^scheme 'x': a quad scheme needs a face rule$"):
        Scheme("x", cc.edge_rule, None, cc.vertex_rule)
    with pytest.raises(InvalidSchemeError, match=r"^scheme 'y': a triangle scheme has no face rule$"):
        Scheme("y", cc.edge_rule, cc.face_rule, cc.vertex_rule, lattice="triangle")


def test_a_built_in_scheme_is_built_once():
    assert catmull_clark() is catmull_clark()
    assert catmull_clark().lattice.reference() is catmull_clark()
