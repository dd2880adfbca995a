"""L N - M^2 of the central surface, from Bernstein products, against finite differences of the surface patches themselves."""

from __future__ import annotations

from math import comb

import flint
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.algebra.triangle_bezier import bernstein
from symdecomp.verify.curvature import combine, curvature_gram, patch_algebra
from symdecomp.verify.shape import height_fields

CC, LOOP = sd.catmull_clark(), sd.loop()


def _float(x) -> float:
    return float(x.mid())


def _flat(net) -> list:
    return [c for row in net for c in row] if isinstance(net[0], list) else list(net)


def _shaped(values: list, like) -> list:
    """Flat float ``values`` in the shape of the net ``like``, as balls."""
    balls = [flint.arb(x) for x in values]
    if isinstance(like[0], list):
        q = len(like[0])
        return [balls[i:i + q] for i in range(0, len(balls), q)]
    return balls


def _value(net, u: float, v: float) -> float:
    """The polynomial of a Bezier net at ``(u, v)``, in floats."""
    if isinstance(net[0], list):
        p, q = len(net) - 1, len(net[0]) - 1
        return sum(_float(net[i][k]) * comb(p, i) * u**i * (1 - u) ** (p - i) * comb(q, k) * v**k * (1 - v) ** (q - k)
                   for i in range(p + 1) for k in range(q + 1))
    degree = {15: 4, 153: 16}[len(net)]
    return sum(_float(c) * b for c, b in zip(net, bernstein(degree, u, v)))


def _derivatives(nets, h: float = 1e-3):
    """``u, v -> (x_uu, x_uv, x_vv, x_u, x_v)`` of the surface with coordinate nets ``nets``: central differences of its values."""
    def at(u, v):
        return sp.Matrix([_value(net, u, v) for net in nets])

    def derivatives(u, v):
        c, e, w, n_, s_ = at(u, v), at(u + h, v), at(u - h, v), at(u, v + h), at(u, v - h)
        ne, nw, se, sw = at(u + h, v + h), at(u - h, v + h), at(u + h, v - h), at(u - h, v - h)
        return [(e - 2 * c + w) / h**2, (ne - nw - se + sw) / (4 * h * h), (n_ - 2 * c + s_) / h**2, (e - w) / (2 * h), (n_ - s_) / (2 * h)]

    return derivatives


def _numerator(derivatives, u, v) -> float:
    """``L N - M^2`` with ``L = det(x_uu, x_u, x_v)`` and so on, from the derivative values."""
    uu, uv, vv, xu, xv = derivatives(u, v)
    L, M, N = (sp.Matrix.hstack(second, xu, xv).det() for second in (uu, uv, vv))
    return float(L * N - M**2)


@pytest.mark.parametrize("scheme, n, weights, point", [
    (CC, 5, (1, 0, 0), (sp.Rational(1, 3), sp.Rational(2, 7))),
    (CC, 5, (1, sp.Rational(1, 2), sp.Rational(-1, 3)), (sp.Rational(3, 4), sp.Rational(1, 5))),
    (LOOP, 7, (0, 1, 0), (sp.Rational(1, 5), sp.Rational(1, 3))),
    (LOOP, 25, (1, 0, 0), (sp.Rational(1, 7), sp.Rational(5, 7))),
])
def test_numerator_net_is_the_numerator_of_the_surface(scheme, n, weights, point):
    fields = height_fields(scheme, n)
    alg = patch_algebra(scheme.lattice)
    for (X, Y), heights in zip(fields.chi, fields.heights):
        gram, _ = curvature_gram(alg, X, Y, list(heights))
        ours = combine(gram, [flint.arb(flint.fmpq(int(w.p), int(w.q))) if isinstance(w, sp.Rational) else w for w in weights])
        H = [sum((float(w) * _float(x) for w, x in zip(weights, coefficients)), 0.0) for coefficients in zip(*map(_flat, heights))]
        want = _numerator(_derivatives([X, Y, _shaped(H, X)]), float(point[0]), float(point[1]))
        got = _value(ours, float(point[0]), float(point[1]))
        assert got == pytest.approx(want, rel=1e-4)


@pytest.mark.parametrize("n, both_signs", [(24, False), (25, True)])
def test_loop_hybrid_is_seen_by_sampling_the_surface_itself(n, both_signs):
    """Sampled in floats from the patches (no Bernstein bound): Loop's elliptic central surface has K of both signs at n = 25."""
    fields = height_fields(LOOP, n, hyperbolic=False)
    samples = [(sp.Rational(i, 12), sp.Rational(k, 12)) for i in range(13) for k in range(13 - i)]
    signs = set()
    for (X, Y), (H,) in zip(fields.chi, fields.heights):
        derivatives = _derivatives([X, Y, H])
        signs |= {1 if _numerator(derivatives, float(u), float(v)) > 0 else -1 for u, v in samples}
    assert (signs == {1, -1}) is both_signs
