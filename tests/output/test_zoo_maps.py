"""The characteristic map of a scheme of the zoo as ``c1 --plot`` draws it (issue 30): the control net refined by the
scheme's own rules is the eigenvector's, and the spline patches are the biquadratic B-spline's."""

from __future__ import annotations

import numpy as np
import pytest

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.errors import NotApplicableError
from symdecomp.output.plotting.spectrum_chart import as_complex
from symdecomp.output.plotting.zoo_maps import hole_boundary, refined_net, zoo_map_curves
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.zoo_characteristic import characteristic_points, spectral_conditions


@pytest.mark.parametrize("name", ["midedge", "sqrt3", "modified-butterfly"])
def test_refining_the_eigenvectors_net_by_the_rules_scales_the_hole_by_lambda(name):
    """X is an eigenvector of the matrix the rules make over ``steps`` steps, so ``2 steps`` of the rules applied to the
    points (refine_step, nothing from the spectrum) move the hole's corners to ``lambda^(2 steps / steps)`` times
    themselves, corner by corner in the tracked order."""
    scheme, n = load_zoo(name), 4
    spectral = spectral_conditions(zoo_spectrum(scheme, n, jordan=False), n)
    lam = complex(as_complex(spectral.subdominant.value))
    zm = zoo_matrix(scheme, n, zoo_matrix(scheme, n).depth + 1)
    points = {v: as_complex(z) for v, z in characteristic_points(zm, spectral.subdominant).items()}
    nb = zm.neighbourhood
    before = np.array(hole_boundary(nb.mesh, nb.start, nb.centred, points))
    mesh, start, refined = refined_net(scheme, zm, points, 2 * scheme.steps)
    after = np.array(hole_boundary(mesh, start, nb.centred, refined))
    assert abs(lam.imag) < 1e-15 and 0 < lam.real < 1 and np.abs(before).min() > 1e-3
    assert np.allclose(after, lam**2 * before, rtol=0, atol=1e-12)
    assert len(set(np.round(before, 9))) == len(before)  # the corners are distinct: the check is not 0 = 0


def test_doo_sabin_at_the_regular_valence_is_a_linear_map():
    """At n = 4 the biquadratic B-spline reproduces linear functions and the characteristic map is linear: every
    iso-parameter line of the patches is straight, and the hole's boundary (the centre quad's four patches) is a square."""
    curves = zoo_map_curves(load_zoo("doo-sabin"), 4)
    assert curves["drawn"] == "the ring of biquadratic B-spline patches" and len(curves["lines"]) > 10
    for z in curves["lines"]:
        d = z - z[0]
        assert np.abs((d * np.conj(d[-1])).imag).max() < 1e-12 * np.abs(d[-1]) ** 2
    inner = np.concatenate(curves["inner"])
    r = np.abs(inner).max()
    assert np.allclose(np.abs(inner.real) + np.abs(inner.imag), r, atol=1e-9 * r)  # on one square |x| + |y| = r
    corners = {complex(round(w.real / r, 9), round(w.imag / r, 9)) for w in inner if abs(abs(w) - r) < 1e-9 * r}
    c = np.array(sorted(corners, key=lambda w: np.angle(w)))
    assert len(c) == 4 and np.allclose(c * 1j, np.roll(c, -1), atol=1e-9)  # a quarter turn takes each corner to the next


def test_no_map_where_the_spectral_conditions_fail_says_why():
    with pytest.raises(NotApplicableError, match=r"^n = 3: the subdominant eigenvalue 0.25 is not a real double eigenvalue"):
        zoo_map_curves(load_zoo("midedge"), 3)


def test_midedge_draws_its_four_direction_patches_linear_at_the_regular_valence():
    """At n = 4 the box spline reproduces linear functions: every iso-parameter line is straight; at n = 5 the inner
    boundary (the ring's sides facing the pentagon) goes once around the origin."""
    curves = zoo_map_curves(load_zoo("midedge"), 4)
    assert curves["drawn"] == "the ring of piecewise quadratic patches on the four-direction mesh" and len(curves["lines"]) > 10
    for z in curves["lines"]:
        d = z - z[0]
        assert np.abs((d * np.conj(d[-1])).imag).max() < 1e-12 * np.abs(d[-1]) ** 2
    inner = zoo_map_curves(load_zoo("midedge"), 5)["inner"]
    assert len(inner) == 10  # two sides per sector
    sweeps = [np.angle(z[1:] / z[:-1]) for z in inner]  # each side turns one way around the origin (drawn either way)
    assert all((np.sign(w) == np.sign(w[0])).all() for w in sweeps)
    assert abs(sum(abs(w.sum()) for w in sweeps) / (2 * np.pi) - 1) < 1e-9  # the ten sides go round once
