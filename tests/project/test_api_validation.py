"""The public API validates its arguments before any cache and raises only the package's errors.

The tables walk the public functions (``symdecomp.__all__``) by the arguments they take: every
integer argument (valence, frequency, digits, bits, depth, rings, steps, levels) gets floats,
Fractions, numpy floats, booleans, text, ``None``, values below its minimum and, where it is
bounded, ``10**9``; every scheme argument gets things that are not schemes. Each is refused with
a :class:`~symdecomp.errors.SymdecompError` both on a cold cache and after the same call with a
good value (a bare ``lru_cache`` answers ``f(s, 5.0)`` from the entry of ``f(s, 5)``), and a
numpy integer is as good as an ``int``.
"""

from __future__ import annotations

import functools
import importlib
import inspect
import pkgutil
from fractions import Fraction

import numpy as np
import pytest

import symdecomp as sd
from symdecomp.algebra.triangle_bezier import bezier_indices
from symdecomp.analysis.charpoly import frequency_factors
from symdecomp.analysis.components import initial_vector_condition
from symdecomp.analysis.dual_evaldata import dual_evaldata
from symdecomp.analysis.elliptic import scale_ratio_squared
from symdecomp.analysis.evolution import subdivision_matrix_numeric
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.analysis.inspection import position_weights
from symdecomp.analysis.mesh_kinds import NeighbourhoodKind
from symdecomp.analysis.mesh_limits import kind_masks
from symdecomp.analysis.sector_evaldata import sector_evaldata
from symdecomp.analysis.support import limit_mask
from symdecomp.analysis.support_window import window
from symdecomp.analysis.tuning import eigenvalue_quadratic, ratio_target
from symdecomp.analysis.tuning_region import tuning_region
from symdecomp.errors import InvalidInputError, InvalidMeshError, InvalidSchemeError, InvalidTypeError, SymdecompError
from symdecomp.output.plotting.boundary import sector_modes, subdominant_eigenvalues
from symdecomp.schemes.box_spline import regular_limit_mask, regular_patch
from symdecomp.verify.mesh_verdicts import kind_verdict
from symdecomp.verify.predictions import toolkit_predictions
from symdecomp.verify.symmetric_functions import symmetric_functions
from symdecomp.verify.tuning_c1 import certified_tuning_region
from tests.analysis.zoo_engine_schemes import doo_sabin_stencils

CC, LOOP = sd.catmull_clark(), sd.loop()
DOO_SABIN = doo_sabin_stencils()
FREE = sd.catmull_clark(sd.symbols.alpha, sd.symbols.beta)
NOT_INTEGERS = [5.0, Fraction(5), np.float64(5), True, "5", None]
NOT_SCHEMES = [None, "catmull-clark", 5, {"edge": {}}]
MESH = sd.ring_mesh(4, 2)
BOUNDARY, SEMI = sd.SharpVertex.boundary(3, sd.QUAD), sd.SharpVertex.crease(2, 3, sd.QUAD, sharpness=Fraction(5, 2))
CUBE = sd.PolygonMesh.from_arrays([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)],
                                  [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])

#: ``(function, argument, the other arguments, a good value, the smallest good value, bounded)``:
#: ``bounded`` when ``10**9`` is beyond the argument's documented limit.
INTEGERS = [
    (sd.subdivision_matrix, "n", dict(scheme=CC), 5, 3, False),
    (sd.recursion_matrix, "n", dict(scheme=CC), 5, 3, False),
    (sd.per_frequency_matrix_at, "n", dict(scheme=CC, j=1), 5, 3, False),
    (sd.per_frequency_matrix_at, "j", dict(scheme=CC, n=5), 1, 0, True),
    (sd.invariant_ratio_at, "n", dict(scheme=CC, j=1), 5, 3, False),
    (sd.invariant_ratio_at, "j", dict(scheme=CC, n=5), 1, 0, True),
    (sd.invariant_ratio_limit, "j", dict(scheme=CC), 1, 1, False),
    (sd.closed_form_spectrum, "n", dict(scheme=CC), 5, 3, False),
    (sd.closed_form_spectrum, "digits", dict(scheme=CC, n=5), 10, 1, True),
    (sd.zoo_matrix, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.zoo_spectrum, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.zoo_spectrum, "digits", dict(scheme=DOO_SABIN, n=5), 10, 1, True),
    (dual_evaldata, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.zoo_masks, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.zoo_masks, "digits", dict(scheme=DOO_SABIN, n=5), 10, 1, True),
    (sd.certify_zoo, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.certify_zoo, "digits", dict(scheme=DOO_SABIN, n=5), 10, 1, True),
    (sd.zoo_artifacts, "n", dict(scheme=DOO_SABIN), 5, 3, False),
    (sd.neighbourhood, "n", dict(lattice=sd.QUAD, depth=1), 5, 3, False),
    (sd.elliptic_defect_table, "digits", dict(scheme=CC, valences=[5]), 10, 1, True),
    (sd.tune, "n", dict(scheme=CC), 5, 3, False),
    (sd.design_ring, "n", dict(scheme=CC, normal=(0, 0, 1)), 5, 3, True),
    (sd.hyperbolic_ring, "n", dict(), 5, 3, False),
    (sd.iterate_hyperbolic_ring, "n", dict(scheme=CC, steps=1), 5, 3, False),
    (sd.iterate_hyperbolic_ring, "steps", dict(scheme=CC, n=5), 1, 0, True),
    (sd.iterate_hyperbolic_ring, "digits", dict(scheme=CC, n=5, steps=1), 10, 1, True),
    (sd.limit_masks_at, "n", dict(scheme=CC), 5, 3, False),
    (sd.ring_mesh, "n", dict(rings=1), 5, 3, False),
    (sd.ring_mesh, "rings", dict(n=5), 1, 1, True),
    (sd.central_rings, "levels", dict(mesh=MESH, scheme=CC, center=0), 1, 0, True),
    (sd.classify_support, "levels", dict(mesh=sd.ring_mesh(4, 5), source=0, scheme=CC), 0, 0, True),
    (sd.ring_subdivision_matrix, "n", dict(scheme=LOOP), 5, 3, False),
    (sd.ring_subdivision_matrix, "rings", dict(scheme=LOOP, n=5), 1, 1, True),
    (sd.ring_blocks, "rings", dict(scheme=LOOP), 1, 1, True),
    (sd.ring_spectrum, "n", dict(scheme=LOOP), 5, 3, False),
    (sd.ring_spectrum, "rings", dict(scheme=LOOP, n=5), 1, 1, True),
    (sd.ring_spectrum, "digits", dict(scheme=LOOP, n=5), 10, 1, True),
    (sd.ring_masks, "n", dict(scheme=LOOP), 5, 3, False),
    (sd.ring_masks, "rings", dict(scheme=LOOP, n=5), 1, 1, True),
    (sd.ring_masks, "digits", dict(scheme=LOOP, n=5), 10, 1, True),
    (tuning_region, "n", dict(scheme=FREE), 5, 3, False),
    (certified_tuning_region, "n", dict(scheme=FREE), 4, 3, False),
    (sd.certify_ring, "n", dict(scheme=LOOP), 5, 3, False),
    (sd.certify_ring, "rings", dict(scheme=LOOP, n=5), 1, 1, True),
    (sd.certify_ring, "digits", dict(scheme=LOOP, n=5), 10, 1, True),
    (sd.patch_matrices, "n", dict(scheme=CC), 5, 3, False),
    (sd.certified_eigendata, "n", dict(scheme=CC), 3, 3, False),
    (sd.certified_eigendata, "prec", dict(scheme=CC, n=3), 256, 16, True),
    (sd.certified_eigendata, "max_prec", dict(scheme=CC, n=3), 4096, 16, True),
    (sd.numeric_check, "n", dict(scheme=CC, dps=20), 4, 3, False),
    (sd.numeric_check, "dps", dict(scheme=CC, n=4), 20, 5, True),
    (sd.numeric_check, "max_dps", dict(scheme=CC, n=4, dps=20), 100, 5, True),
    (sd.certify, "n", dict(scheme=CC), 4, 3, False),
    (sd.certify, "digits", dict(scheme=CC, n=4), 10, 1, True),
    (sd.certify, "max_prec", dict(scheme=CC, n=4), 4096, 128, True),
    (sd.c1_test, "n", dict(scheme=CC, max_depth=2), 3, 3, False),
    (sd.c1_test, "max_depth", dict(scheme=CC, n=3), 2, 0, True),
    (sd.second_order_eigenstructure, "n", dict(scheme=CC), 5, 3, False),
    (sd.artifact_indicators, "n", dict(scheme=LOOP), 5, 3, False),
    (sd.frequency_kind, "n", dict(frequency=2), 5, 3, False),
    (sd.frequency_kind, "frequency", dict(n=5), 2, 0, False),
    (sd.c1_test, "prec", dict(scheme=CC, n=3, max_depth=2), 64, 16, True),
    (sd.c1_sharp_test, "max_depth", dict(scheme=CC, vertex=BOUNDARY), 2, 0, True),
    (sd.c1_sharp_test, "prec", dict(scheme=CC, vertex=BOUNDARY, max_depth=2), 64, 16, True),
    (sd.classify_shape, "n", dict(scheme=CC, max_depth=2), 5, 3, False),
    (sd.classify_shape, "max_depth", dict(scheme=CC, n=5), 2, 0, True),
    (sd.classify_shape, "prec", dict(scheme=CC, n=5, max_depth=2), 64, 16, True),
    (sd.shape_chart, "n", dict(scheme=CC, ratios=[0, 1], angles=[0], max_depth=2), 5, 3, False),
    (sd.shape_chart, "max_depth", dict(scheme=CC, n=5, ratios=[0, 1], angles=[0]), 2, 0, True),
    (sd.shape_chart, "prec", dict(scheme=CC, n=5, ratios=[0, 1], angles=[0], max_depth=2), 64, 16, True),
    (sd.exact_subdivision_matrix, "n", dict(scheme=CC), 5, 3, False),
    (sd.characteristic_polynomial, "n", dict(scheme=CC), 5, 3, False),
    (sd.jordan_block_size, "n", dict(scheme=CC, eigenvalue=1), 5, 3, False),
    (sd.jordan_vertex_weights, "n", dict(scheme=FREE, eigenvalue=Fraction(3, 8)), 5, 3, False),
    (sd.ellipse_axes, "j", dict(ring=[[k, k * k, 1] for k in range(11)]), 1, 0, True),
    (sd.ellipse_axes, "digits", dict(ring=[[k, k * k, 1] for k in range(11)]), 10, 1, True),
    (sd.root_of_unity, "n", dict(), 5, 1, False),
    (sd.fourier_matrix, "n", dict(), 5, 1, False),
    (sd.circ_from_offsets, "n", dict(offsets={0: 1}), 5, 1, False),
    (sd.circulant_eigenvalue, "n", dict(offsets={0: 1}, k=1), 5, 1, False),
    # cached functions of the subpackages
    (limit_mask, "valence", dict(scheme=CC), 4, 3, False),
    (subdivision_matrix_numeric, "n", dict(scheme=CC), 5, 3, False),
    (toolkit_predictions, "n", dict(), 5, 3, False),
    (bezier_indices, "degree", dict(), 4, 0, True),
    (window, "rings", dict(), 2, 1, True),
    (position_weights, "n", dict(scheme=CC), 5, 3, False),
    (sd.sharp_subdivision_matrix, "rings", dict(scheme=CC, vertex=BOUNDARY), 1, 1, True),
    (sd.sharp_subdivision_matrix, "level", dict(scheme=CC, vertex=SEMI), 1, 0, True),
    (sd.exact_sharp_matrix, "rings", dict(scheme=LOOP, vertex=sd.SharpVertex.boundary(3, sd.TRIANGLE)), 1, 1, True),
    (sd.sharp_spectrum, "digits", dict(scheme=CC, vertex=BOUNDARY), 10, 1, True),
    (sd.certify_sharp, "digits", dict(scheme=CC, vertex=BOUNDARY), 10, 1, True),
]

#: ``(function, the other arguments)`` of the functions that take a scheme.
SCHEMES = [
    (sd.zoo_matrix, dict(n=5)),
    (sd.zoo_spectrum, dict(n=5)),
    (dual_evaldata, dict(n=5)),
    (sd.zoo_masks, dict(n=5)),
    (sd.certify_zoo, dict(n=5)),
    (sd.zoo_artifacts, dict(n=5)),
    (kind_masks, dict(kind=NeighbourhoodKind("smooth", 5, (5,), True))),
    (kind_verdict, dict(kind=NeighbourhoodKind("smooth", 5, (5,), True))),
    (sd.subdivision_matrix, dict(n=5)),
    (sd.circulant_blocks, dict()),
    (sd.per_frequency_matrix, dict()),
    (sd.per_frequency_matrix_at, dict(n=5, j=1)),
    (sd.recursion_matrix, dict()),
    (sd.recursion_matrix, dict(n=5)),
    (sd.tangent_eigenvalues, dict()),
    (sd.invariant_ratio, dict()),
    (sd.invariant_ratio_at, dict(n=5, j=1)),
    (sd.invariant_ratio_limit, dict()),
    (sd.closed_form_spectrum, dict(n=5)),
    (sd.recursion_eigenvalues, dict()),
    (sd.nice_elliptic_conditions, dict()),
    (sd.elliptic_defect_table, dict(valences=[5])),
    (sd.tune, dict(n=5)),
    (sd.joint_obstruction, dict()),
    (sd.hyperbolic_equality, dict()),
    (sd.iterate_hyperbolic_ring, dict(n=5, steps=1)),
    (sd.limit_masks, dict()),
    (sd.limit_masks_at, dict(n=5)),
    (sd.subdivision_block_form, dict()),
    (sd.closed_form_characteristic_polynomial, dict()),
    (sd.mesh_rules, dict()),
    (sd.central_rings, dict(mesh=MESH, center=0, levels=1)),
    (sd.classify_support, dict(mesh=MESH, source=0)),
    (sd.ring_subdivision_matrix, dict(n=5)),
    (sd.ring_blocks, dict()),
    (sd.ring_spectrum, dict(n=5)),
    (sd.ring_masks, dict(n=5)),
    (sd.certify_ring, dict(n=5)),
    (sd.patch_matrices, dict(n=5)),
    (sd.certified_eigendata, dict(n=3)),
    (sd.derived_closed_forms, dict()),
    (sd.numeric_check, dict(n=4)),
    (sd.certify, dict(n=4)),
    (sd.c1_test, dict(n=3)),
    (sd.c1_sharp_test, dict(vertex=BOUNDARY)),
    (sd.second_order_eigenstructure, dict(n=3)),
    (sd.artifact_indicators, dict(n=3)),
    (sd.classify_shape, dict(n=5)),
    (sd.shape_chart, dict(n=5, ratios=[0, 1], angles=[0])),
    (sd.exact_subdivision_matrix, dict(n=5)),
    (sd.characteristic_polynomial, dict(n=5)),
    (sd.jordan_block_size, dict(n=5, eigenvalue=1)),
    (sd.jordan_vertex_weights, dict(n=5, eigenvalue=Fraction(3, 8))),
    (sd.check_claim, dict(label="Eq. 1")),
    # cached functions of the subpackages
    (one_ring_matrices, dict()),
    (scale_ratio_squared, dict()),
    (initial_vector_condition, dict()),
    (limit_mask, dict(valence=4)),
    (subdivision_matrix_numeric, dict(n=5)),
    (eigenvalue_quadratic, dict()),
    (ratio_target, dict()),
    (tuning_region, dict(n=5)),
    (regular_limit_mask, dict()),
    (regular_patch, dict()),
    (position_weights, dict(n=5)),
    (sd.inspect_vertex, dict(mesh=CUBE, vertex=0)),
    (sd.inspect_mesh, dict(mesh=CUBE)),
    (sd.design_ring, dict(n=5, normal=(0, 0, 1))),
    (sd.redesign_vertex, dict(mesh=CUBE, vertex=0, normal=(-1, -1, -1))),
    (sd.limit_frame, dict(mesh=CUBE, vertex=0)),
    (sd.sharp_subdivision_matrix, dict(vertex=BOUNDARY)),
    (sd.exact_sharp_matrix, dict(vertex=BOUNDARY)),
    (sd.sharp_spectrum, dict(vertex=BOUNDARY)),
    (sd.sharp_masks, dict(vertex=BOUNDARY)),
    (sd.certify_sharp, dict(vertex=BOUNDARY)),
    (sd.sector_decomposition, dict(vertex=BOUNDARY)),
    (sd.sector_spectrum, dict(vertex=3)),
    (sector_modes, dict(vertex=BOUNDARY)),
    (subdominant_eigenvalues, dict(vertex=BOUNDARY)),
    (sd.sharp_patch_data, dict(vertex=BOUNDARY)),
    (sector_evaldata, dict(vertex=BOUNDARY)),
]

#: ``(function, argument, a good value)`` of the cached functions that take a computed object.
OBJECTS = [
    (frequency_factors, "blocks", sd.ring_blocks(LOOP)),
    (symmetric_functions, "cf", sd.derived_closed_forms(CC)),
]

#: The argument names the tables must cover wherever a public function has them.
WATCHED = {"n", "j", "digits", "prec", "max_prec", "dps", "max_dps", "max_depth", "rings", "steps", "levels", "scheme"}
#: Watched arguments that are not an integer or a scheme of the caller's, with the reason.
NOT_WALKED = {
    ("Scheme", "parameters"): "a field, checked by test_scheme_parts_of_the_wrong_kind_are_refused",
    ("ring_mesh", "values"): "not watched",
}


def _bad_integers(minimum: int, bounded: bool) -> list:
    return NOT_INTEGERS + [v for v in (-1, 0) if v < minimum] + ([10**9] if bounded else [])


def _name(entry) -> str:
    return f"{entry[0].__name__}-{entry[1] if isinstance(entry[1], str) else 'scheme'}"


@pytest.mark.parametrize("function, argument, others, good, minimum, bounded", INTEGERS, ids=map(_name, INTEGERS))
def test_bad_integers_are_refused_cold_and_after_a_warm_cache(function, argument, others, good, minimum, bounded):
    def call(value):
        return function(**others, **{argument: value})

    bad = _bad_integers(minimum, bounded)
    parameter = inspect.signature(function).parameters[argument]
    if parameter.default is None or "None" in str(parameter.annotation):  # None is documented: "not given", "exact"
        bad.remove(None)
    for value in bad:
        with pytest.raises(SymdecompError):
            call(value)
    expected = call(good)
    assert type(call(np.int64(good))) is type(expected)
    for value in bad:
        with pytest.raises(SymdecompError):
            call(value)


@pytest.mark.parametrize("function, others", SCHEMES, ids=[f"{f.__name__}-{'-'.join(o)}" for f, o in SCHEMES])
def test_what_is_not_a_scheme_is_refused(function, others):
    default_is_none = inspect.signature(function).parameters["scheme"].default is None  # None: the default scheme
    for value in NOT_SCHEMES[default_is_none:]:
        with pytest.raises(InvalidTypeError, match="scheme"):
            function(**others, scheme=value)


@pytest.mark.parametrize("function, argument, good", OBJECTS, ids=[f.__name__ for f, *_ in OBJECTS])
def test_what_is_not_the_computed_object_is_refused_before_the_cache(function, argument, good):
    function(good)
    for value in (None, "x", 5, CC):
        with pytest.raises(InvalidTypeError, match=argument.replace("cf", "closed forms")):
            function(value)


def _modules():
    yield sd
    for info in pkgutil.walk_packages(sd.__path__, "symdecomp."):
        if not info.name.endswith("__main__"):
            yield importlib.import_module(info.name)


def test_no_public_function_is_a_bare_cache_and_every_checked_one_is_walked():
    """A bare ``functools`` cache answers a float from an integer's entry: public caches are ``validate.cached``."""
    walked = {f.__name__ for f, *_ in INTEGERS + SCHEMES + OBJECTS}
    bare, unwalked = [], []
    for module in _modules():
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name, None)
            if isinstance(obj, functools._lru_cache_wrapper):
                bare.append(f"{module.__name__}.{name}")
            elif hasattr(obj, "cache_info") and obj.__name__ not in walked:
                unwalked.append(f"{module.__name__}.{name}")
    assert bare == [] and unwalked == []


def _public_functions():
    for name in sd.__all__:
        obj = getattr(sd, name)
        if inspect.isfunction(obj) or (inspect.isfunction(getattr(obj, "__wrapped__", None))):
            yield name, obj


def test_the_tables_walk_every_public_function_with_a_watched_argument():
    """A new public function that takes a valence, a precision, a depth, ... or a scheme joins the tables."""
    walked = {(f.__name__, a) for f, a, *_ in INTEGERS} | {(f.__name__, "scheme") for f, _ in SCHEMES}
    missing = []
    for name, function in _public_functions():
        for argument in inspect.signature(function).parameters:
            if argument in WATCHED and (name, argument) not in walked and (name, argument) not in NOT_WALKED:
                missing.append(f"{name}({argument})")
    assert missing == []


@pytest.mark.parametrize("function, others", [(sd.recursion_matrix, dict(scheme=CC)), (sd.patch_matrices, dict(scheme=CC))])
def test_a_cached_result_does_not_admit_an_equal_float(function, others):
    good = function(**others, n=5)
    for value in (5.0, Fraction(5), np.float64(5)):
        with pytest.raises(InvalidInputError, match="valence n must be an integer"):
            function(**others, n=value)
    assert function(**others, n=np.int64(5)) == good


def test_numpy_integers_are_valences_of_the_characteristic_polynomial():
    assert sd.characteristic_polynomial(CC, np.int64(5)) == sd.characteristic_polynomial(CC, 5)
    assert sd.exact_subdivision_matrix(CC, np.int32(4)) == sd.exact_subdivision_matrix(CC, 4)


@pytest.mark.parametrize("keywords, message", [
    (dict(max_depth=None), "max_depth must be an integer"),
    (dict(max_depth=13), "max_depth must be an integer"),
    (dict(prec=0), "prec must be an integer"),
    (dict(prec=10**9), "prec must be an integer"),
])
def test_c1_depth_and_precision_are_bounded(keywords, message):
    with pytest.raises(InvalidInputError, match=message):
        sd.c1_test(CC, 5, **keywords)


def test_raw_errors_of_the_issue_are_the_packages():
    with pytest.raises(InvalidInputError, match="rings must be an integer"):
        sd.ring_spectrum(LOOP, 5, "2")
    with pytest.raises(InvalidInputError, match="no claim labelled 'nope'"):
        sd.get_claim("nope")
    with pytest.raises(InvalidTypeError, match="label must be a string"):
        sd.get_claim(["Eq. 1"])
    with pytest.raises(InvalidInputError, match="no claim labelled"):
        sd.check_claim("nope", CC)
    with pytest.raises(InvalidTypeError, match="NoneType"):
        sd.aslatex(None)
    with pytest.raises(InvalidTypeError, match="scheme must be a Scheme"):
        sd.iterate_hyperbolic_ring(5, "1", 29)
    with pytest.raises(InvalidInputError, match="steps must be an integer"):
        sd.iterate_hyperbolic_ring(CC, 5, "1")


def test_scheme_parts_of_the_wrong_kind_are_refused():
    with pytest.raises(InvalidTypeError, match="edge_rule must be a Stencil"):
        sd.Scheme("x", {"center": 1}, CC.face_rule, CC.vertex_rule)
    with pytest.raises(InvalidTypeError, match="vertex_rule must be a VertexRule"):
        sd.Scheme("x", CC.edge_rule, CC.face_rule, (1, 0, 0))
    with pytest.raises(InvalidTypeError, match="scheme name must be a str"):
        sd.Scheme(5, CC.edge_rule, CC.face_rule, CC.vertex_rule)
    with pytest.raises(InvalidTypeError, match="parameters"):
        sd.Scheme("x", CC.edge_rule, CC.face_rule, CC.vertex_rule, parameters=("alpha",))
    same = sd.Scheme("catmull-clark", CC.edge_rule, CC.face_rule, CC.vertex_rule, parameters=[])
    assert same == CC


def test_a_mesh_label_that_is_not_an_integer_is_refused_not_truncated():
    values = {v: (0,) for v in range(4)}
    for label in (3.5, "3", 3.0, None):
        with pytest.raises(InvalidMeshError, match="vertex id must be an integer"):
            sd.QuadMesh(((0, 1, 2, label),), values)
    with pytest.raises(InvalidMeshError, match="values must be a mapping"):
        sd.QuadMesh(((0, 1, 2, 3),), [(0,)] * 4)
    assert sd.QuadMesh(((0, 1, 2, np.int64(3)),), values).faces == ((0, 1, 2, 3),)


def test_a_deeply_nested_scheme_file_is_one_line(tmp_path, capsys):
    from symdecomp.cli import main
    from symdecomp.schemes.files import load_scheme, scheme_from_text

    path = tmp_path / "deep.toml"
    path.write_text("a = " + "[" * 49_000 + "]" * 49_000)
    with pytest.raises(InvalidSchemeError, match="nested too deeply"):
        load_scheme(path)
    with pytest.raises(InvalidSchemeError, match="nested too deeply"):
        scheme_from_text("a = " + "[" * 100_000 + "]" * 100_000)
    with pytest.raises(InvalidTypeError, match="scheme name or a file path"):
        load_scheme(5)
    assert main(["claims", "--scheme", str(path), "--label", "Eq. 1"]) == 2
    err = capsys.readouterr().err
    assert "nested too deeply" in err and err.count("\n") == 1 and "Traceback" not in err


def test_cached_keeps_the_checks_before_the_lookup():
    from symdecomp.validate import cached, check_valence

    calls = []

    @cached(n=check_valence)
    def ring_size(n, rings=1):
        calls.append(n)
        return 2 * n * rings + 1

    assert ring_size(5) == ring_size(np.int64(5)) == ring_size(n=np.int32(5)) == 11
    assert calls[0] == 5 and all(type(n) is int for n in calls)
    with pytest.raises(InvalidInputError):
        ring_size(5.0)
    with pytest.raises(InvalidInputError):
        ring_size(n=Fraction(5))
    assert ring_size(5, 2) == 21
