"""The sign of the Gaussian curvature of a central surface ``(chi_1, chi_2, h)``, as Bernstein-Bezier nets in Arb.

For a parametric surface ``x(u, v)`` with unit normal ``nu = (x_u x x_v) / |x_u x x_v|`` the
Gaussian curvature is ``K = (L N - M^2) / |x_u x x_v|^4`` with the *unnormalised* second
fundamental form ``L = det(x_uu, x_u, x_v)``, ``M = det(x_uv, x_u, x_v)``,
``N = det(x_vv, x_u, x_v)`` (``x_uu . nu = L / |x_u x x_v|``, and ``EG - F^2 = |x_u x x_v|^2``). Where
the map is regular, ``K`` therefore has the sign of the polynomial ``L N - M^2``.

For ``x = (X, Y, H)`` with the planar map ``(X, Y)`` fixed, each form is *linear* in the height ``H``:
expanding the determinant along its last row,

    L = H_uu J + H_u (Y_uu X_v - X_uu Y_v) + H_v (X_uu Y_u - Y_uu X_u),   J = X_u Y_v - X_v Y_u,

and ``M``, ``N`` likewise with ``uv``, ``vv`` for ``uu``. So for a height ``H = sum_p w_p H_p``
(several eigenfunctions with amplitudes ``w_p``) the numerator is the quadratic form
``L N - M^2 = sum_(p,q) w_p w_q G_pq`` with ``G_pq = (L_p N_q + L_q N_p) / 2 - M_p M_q``: the nets
``G_pq`` are computed once, and each mixture is a linear combination of them.

Degrees: bicubic ``X, Y, H`` give ``L`` of bidegree ``(6, 8)``, ``M`` ``(7, 7)``, ``N`` ``(8, 6)`` and
``L N - M^2`` of bidegree ``(14, 14)`` (``J``: ``(5, 5)``); quartic triangular patches give ``J`` of
degree 6, the forms degree 8 and ``L N - M^2`` degree 16. Products are
:mod:`symdecomp.algebra.bernstein`'s (certified Arb convolutions).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import flint

from symdecomp.algebra.bernstein import net_scale, net_sum, tensor_derivative, tensor_product, triangle_product
from symdecomp.algebra.triangle_bezier import bezier_derivative
from symdecomp.schemes.box_spline import DEGREE
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice
from symdecomp.verify.bezier import SignCertificate, certify_sign, certify_sign_triangles

__all__ = ["PatchAlgebra", "patch_algebra", "jacobian_nets", "second_forms", "curvature_gram", "combine", "certify_nets"]


@dataclass(frozen=True)
class PatchAlgebra:
    """Bernstein arithmetic on the ring's sub-patches of one lattice: degrees, derivatives, products, signs."""

    #: The degree of the ring's patches: ``(3, 3)`` (bicubic) or ``4`` (quartic triangles).
    degree: object
    #: ``(net, degree, 'u' or 'v') -> net`` of the derivative.
    derivative: Callable
    #: ``(degree, 'u' or 'v') -> degree`` of the derivative.
    lower: Callable
    #: ``(f, g, degree_f, degree_g) -> net`` of the product.
    product: Callable
    #: ``(degree_f, degree_g) -> degree`` of the product.
    add: Callable
    #: ``(nets, degree, max_depth) -> SignCertificate``: one strict sign over all nets, subdividing to ``max_depth``.
    certify: Callable


def _tensor_lower(degree, direction):
    p, q = degree
    return (p - 1, q) if direction == "u" else (p, q - 1)


_ALGEBRAS = {
    BICUBIC: PatchAlgebra(
        (3, 3), tensor_derivative, _tensor_lower, tensor_product, lambda a, b: (a[0] + b[0], a[1] + b[1]),
        lambda nets, degree, depth: certify_sign(nets, depth),
    ),
    # a bisection halves a piece, a tensor split quarters it: twice the depth, as the C1 test does
    BOX_SPLINE: PatchAlgebra(
        DEGREE, bezier_derivative, lambda degree, direction: degree - 1, triangle_product, lambda a, b: a + b,
        lambda nets, degree, depth: certify_sign_triangles(nets, degree, 2 * depth),
    ),
}


def patch_algebra(lat: Lattice) -> PatchAlgebra:
    """The :class:`PatchAlgebra` of a lattice's ring patches."""
    return lat.select(_ALGEBRAS, "Bernstein arithmetic for the ring patches")


def _difference(alg: PatchAlgebra, a, b, c, d, da, db):
    """``a b - c d`` with ``a, c`` of degree ``da`` and ``b, d`` of degree ``db``."""
    return net_sum(alg.product(a, b, da, db), net_scale(alg.product(c, d, da, db), -1))


@dataclass(frozen=True)
class _Planar:
    """The derivatives of the planar map ``(X, Y)`` of one patch and the coefficients of the height's derivatives."""

    du: object
    dv: object
    #: ``J = X_u Y_v - X_v Y_u`` and its degree.
    jacobian: list
    #: Per second derivative (``uu``, ``uv``, ``vv``): ``(degree, A_u, A_v)``, the coefficients of ``H_u``, ``H_v``.
    seconds: tuple


def _planar(alg: PatchAlgebra, X, Y) -> _Planar:
    D = alg.degree
    Du, Dv = alg.lower(D, "u"), alg.lower(D, "v")
    Xu, Xv, Yu, Yv = (alg.derivative(f, D, d) for f, d in ((X, "u"), (X, "v"), (Y, "u"), (Y, "v")))
    jac = _difference(alg, Xu, Yv, Yu, Xv, Du, Dv)
    seconds = []
    for (f_x, f_y, dfirst), direction in (((Xu, Yu, Du), "u"), ((Xu, Yu, Du), "v"), ((Xv, Yv, Dv), "v")):
        Xs, Ys, Ds = alg.derivative(f_x, dfirst, direction), alg.derivative(f_y, dfirst, direction), alg.lower(dfirst, direction)
        seconds.append((Ds, _difference(alg, Ys, Xv, Xs, Yv, Ds, Dv), _difference(alg, Xs, Yu, Ys, Xu, Ds, Du)))
    return _Planar(Du, Dv, jac, tuple(seconds))


def jacobian_nets(alg: PatchAlgebra, planar_nets) -> list:
    """The Jacobian nets ``X_u Y_v - X_v Y_u`` of the patches ``[(X, Y), ...]``."""
    return [_planar(alg, X, Y).jacobian for X, Y in planar_nets]


def second_forms(alg: PatchAlgebra, X, Y, heights) -> list[tuple[list, list, list]]:
    """``[(L, M, N), ...]``: the unnormalised second fundamental forms of ``(X, Y, H)`` for each height net ``H``."""
    pl = _planar(alg, X, Y)
    D = alg.degree
    out = []
    for H in heights:
        Hu, Hv = alg.derivative(H, D, "u"), alg.derivative(H, D, "v")
        second = (alg.derivative(Hu, pl.du, "u"), alg.derivative(Hu, pl.du, "v"), alg.derivative(Hv, pl.dv, "v"))
        forms = []
        for Hs, (Ds, Au, Av) in zip(second, pl.seconds):
            forms.append(net_sum(
                alg.product(Hs, pl.jacobian, Ds, alg.add(pl.du, pl.dv)),
                alg.product(Hu, Au, pl.du, alg.add(Ds, pl.dv)),
                alg.product(Hv, Av, pl.dv, alg.add(Ds, pl.du)),
            ))
        out.append(tuple(forms))
    return out


def curvature_gram(alg: PatchAlgebra, X, Y, heights) -> tuple[dict, object]:
    """``({(p, q): G_pq}, degree)`` for ``p <= q``: the nets whose combinations are ``L N - M^2`` of ``(X, Y, sum w_p H_p)``."""
    forms = second_forms(alg, X, Y, heights)
    D = alg.degree
    first = alg.add(alg.lower(D, "u"), alg.lower(D, "v"))
    dL = alg.add(alg.lower(alg.lower(D, "u"), "u"), first)
    dM = alg.add(alg.lower(alg.lower(D, "u"), "v"), first)
    dN = alg.add(alg.lower(alg.lower(D, "v"), "v"), first)
    gram = {}
    for p in range(len(heights)):
        for q in range(p, len(heights)):
            (Lp, Mp, Np), (Lq, Mq, Nq) = forms[p], forms[q]
            LN = net_sum(alg.product(Lp, Nq, dL, dN), alg.product(Lq, Np, dL, dN))
            gram[(p, q)] = net_sum(net_scale(LN, flint.fmpq(1, 2)), net_scale(alg.product(Mp, Mq, dM, dM), -1))
    return gram, alg.add(dL, dN)


def combine(gram: dict, weights) -> list:
    """``sum_(p,q) w_p w_q G_pq`` (``gram`` over ``p <= q``, as :func:`curvature_gram` returns it)."""
    terms = []
    for (p, q), net in gram.items():
        w = flint.arb(weights[p]) * flint.arb(weights[q]) * (1 if p == q else 2)
        if not w.is_exact() or w != 0:  # only an exact 0 may be left out
            terms.append(net_scale(net, w))
    if not terms:
        return net_scale(next(iter(gram.values())), 0)
    return net_sum(*terms)


def certify_nets(alg: PatchAlgebra, nets, degree, max_depth: int) -> SignCertificate:
    """One strict sign over all ``nets`` (of ``degree``), certified by subdivision to ``max_depth`` (:mod:`symdecomp.verify.bezier`)."""
    return alg.certify(nets, degree, max_depth)
