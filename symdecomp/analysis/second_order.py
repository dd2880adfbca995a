"""Second-order characteristic maps: the height fields of the elliptic and hyperbolic eigenvalues on the ring.

After the characteristic map ``chi`` (eigenvalue ``lambda``, frequency 1; see
:mod:`symdecomp.analysis.characteristic`) the next terms of the eigen-expansion of a limit
surface near the extraordinary vertex are the *second-order* eigenfunctions: the spline rings
of the eigenvectors of the eigenvalues ``mu`` that carry quadratic behaviour, the *elliptic* one
at frequency 0 (rotationally symmetric, like ``x^2 + y^2``) and the *hyperbolic* pair at
frequency 2 (the real and imaginary parts of one complex eigenvector, like ``x^2 - y^2`` and
``2 x y``). Over the characteristic map they are *height fields*: the surface
``(chi_1, chi_2, h)`` on one ring segment is Peters and Reif's central surface (see
:mod:`symdecomp.verify.shape`).

**Frequency ``j != 0``.** The eigenvector of the 2-ring matrix at frequency ``j`` with a simple
root ``mu`` of the 1-ring block is :func:`~symdecomp.analysis.characteristic.frequency_eigenvector`
(the centre ``O`` is 0 in it); its level-1 values give the control nets of the ring, and its
real and imaginary parts are the two real eigenfunctions.

**Frequency 0, without the centre's row.** The ``O`` column is left out of the blocks ``B_j``.
At frequency 0 the eigenvector has ``O = v_O != 0`` in general, but a height field matters only
up to a constant (curvature reads second derivatives), and every rule is affine (its weights sum
to 1), so a row applied to ``v - v_O`` gives the new point minus ``v_O`` with no ``O`` term:
``w = c - v_O`` (``c`` the 2-ring classes) satisfies ``B_0 w = mu w + (mu - 1) v_O``. With
``v_O = 1 / (mu - 1)`` this is the linear system ``(B_0 - mu I) w = 1``, solved in Arb; it has a
unique solution when ``mu`` is not an eigenvalue of ``B_0`` (the classes with ``O`` held at 0),
and then that solution *is* the eigenvector (unique up to scale), so the centre's row, which the
system does not contain, holds by itself. The level-1 values, minus the new centre value, are
``B_0 w - 1`` on the level-1 classes and 0 at ``O``: the height field of the eigenvector less a
constant, and the nets of :func:`~symdecomp.analysis.characteristic.subpatch_nets` (which put 0
at ``O``) are its nets.

>>> import flint
>>> from symdecomp.schemes.scheme import catmull_clark
>>> h = height_eigenvector(catmull_clark(), 4, 0, flint.acb(flint.fmpq(1, 4)))
>>> all(x.real.contains(u * u + v * v) for (u, v), x in h.values.items())   # regular: u^2 + v^2 at level 1
True
"""

from __future__ import annotations

import flint

from symdecomp.analysis.characteristic import FrequencyEigenvector, frequency_block, frequency_eigenvector, ring_layout
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_frequency, check_valence

__all__ = ["height_eigenvector", "frequency_zero_height"]


def frequency_zero_height(scheme: Scheme, n: int, eigenvalue: flint.acb) -> FrequencyEigenvector:
    """The frequency-0 eigenvector of ``eigenvalue`` (``!= 1``) less its centre value, on the level-1 3-ring.

    See the module docstring; scaled so that the new centre's value before the shift is
    ``mu / (mu - 1)``. Raises :class:`~symdecomp.errors.InvalidSchemeError` when ``B_0 - mu``
    cannot be shown invertible (``mu`` is then also an eigenvalue with ``O`` held at 0, and the
    height field is not determined this way).
    """
    layout = ring_layout(scheme.lattice)
    k2 = layout.two_ring
    B = frequency_block(scheme, n, 0, rows=len(layout.labels))
    A, ones = flint.acb_mat(k2, k2), flint.acb_mat(k2, 1)
    for r in range(k2):
        ones[r, 0] = 1
        for c in range(k2):
            A[r, c] = B[r, c] - (eigenvalue if r == c else 0)
    try:
        w = A.solve(ones)
    except ZeroDivisionError as exc:
        raise InvalidSchemeError(
            f"at n = {n} the frequency-0 eigenvalue {eigenvalue.real.str(6, radius=False)} is also an eigenvalue of the 2-ring "
            "classes with the centre held at 0 (such as an outer eigenvalue of the regular part), or too close to one at this precision: "
            "its eigenvector is not determined by the 1-ring"
        ) from exc
    values = {label: sum((B[r, m] * w[m, 0] for m in range(k2)), flint.acb(0)) - 1 for r, label in enumerate(layout.labels)}
    return FrequencyEigenvector(n, 0, eigenvalue, values, scheme.lattice)


def height_eigenvector(scheme: Scheme, n: int, j: int, eigenvalue: flint.acb) -> FrequencyEigenvector:
    """The eigenvector of the 2-ring matrix at frequency ``j`` for ``eigenvalue`` (a ball around a simple root), on the level-1 3-ring.

    ``j = 0``: :func:`frequency_zero_height` (less its centre value); otherwise
    :func:`~symdecomp.analysis.characteristic.frequency_eigenvector`. Normalised to the value 1 at the level-1
    point ``a_0 = (1, 0)`` (relative to the centre, which is 0), so that at the regular valence the elliptic
    field is ``|p|^2`` and the hyperbolic one ``p^2`` (complex) in lattice coordinates ``p`` of level 1, and
    mixtures of the two compare like ``x^2 + y^2`` and ``x^2 - y^2``. The ring's control nets are
    :func:`~symdecomp.analysis.characteristic.subpatch_nets` of the result (sector ``s``: times
    ``omega^(j s)``).
    """
    check_scheme(scheme)
    n = check_valence(n)
    j = check_frequency(j, n)
    if not isinstance(eigenvalue, (flint.acb, flint.arb)):
        raise InvalidSchemeError(f"eigenvalue must be an Arb ball (flint.acb), got {type(eigenvalue).__name__}")
    eigenvalue = flint.acb(eigenvalue)
    if j == 0:
        return _normalised(frequency_zero_height(scheme, n, eigenvalue))
    try:
        return _normalised(frequency_eigenvector(scheme, n, j, eigenvalue))
    except ZeroDivisionError as exc:
        raise InvalidSchemeError(
            f"at n = {n} the frequency-{j} eigenvalue {eigenvalue.real.str(6, radius=False)} is also an eigenvalue of the regular "
            "outer block (or too close to one at this precision): its eigenvector is not determined by the 1-ring"
        ) from exc


def _normalised(vec: FrequencyEigenvector) -> FrequencyEigenvector:
    """``vec`` divided by its level-1 value at ``a_0 = (1, 0)`` (the centre is 0 in it): the height there is 1."""
    scale = vec.values[(1, 0)]
    if scale.real.contains(0) and scale.imag.contains(0):
        raise InvalidSchemeError(f"at n = {vec.n} the frequency-{vec.j} eigenvector is not shown to be nonzero at a_0, where it is normalised")
    return FrequencyEigenvector(vec.n, vec.j, vec.eigenvalue, {k: x / scale for k, x in vec.values.items()}, vec.lattice)
