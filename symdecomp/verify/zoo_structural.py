"""The certificate of a StencilScheme's spectrum at a large valence: the structural blocks in Arb, ``O(n)`` per valence.

The matrix at valence ``n`` is the bordered block-circulant matrix of the structural form
(:mod:`symdecomp.analysis.zoo_structure`: read at one valence with the centre's weights as markers, checked
exactly against the explicit matrices at two more; the rules at a centre of valence ``n`` are the same for every
``n`` from there, and the families' sums are closed forms for every ``n``), so its spectrum is the union of the
blocks' (the Fourier transform block-diagonalises it). Each block's eigenvalues come from the characteristic
polynomials factored once (:mod:`symdecomp.analysis.zoo_large`), as Arb balls; balls are grouped where their
real or imaginary projections overlap, so values in different groups are proved distinct. A group's values are
proved *equal* when each is the same closed-form root: one exact value (free of ``omega``) at every frequency,
or a root in ``c_k = cos(2 pi k/n)`` at ``k`` and ``n - k``; then the multiplicities are certified.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> c = structural_zoo_certificate(load_zoo("doo-sabin"), 1000)
>>> c.status.value, c.route, c.multiplicities_certified, c.multiplicities[:3], sum(c.multiplicities)
('agree', 'structural-form', True, (1, 2, 1997), 4000)
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.analysis.charpoly import COSK
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.zoo_blocks import signed_offset
from symdecomp.analysis.zoo_large import StructuralFactors, frequency_balls, proved_distinct_groups, structural_factors
from symdecomp.errors import PrecisionError
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_valence
from symdecomp.verify.certify import Certificate
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["structural_zoo_certificate"]


def _apart(items: list[tuple[flint.acb, object]], groups: list[list[int]]) -> bool:
    """Whether the groups' hulls (exact Arb unions) are pairwise disjoint: neighbours in the real order, then all
    groups sharing a real stretch."""
    hulls = []
    for g in groups:
        h = items[g[0]][0]
        for i in g[1:]:
            h = h.union(items[i][0])
        hulls.append(h)
    order = sorted(range(len(hulls)), key=lambda i: float(hulls[i].real.lower()))
    for a, i in enumerate(order):
        for j in order[a + 1:]:
            if float(hulls[j].real.lower()) > float(hulls[i].real.upper()) + 1e-9:
                break
            if hulls[i].overlaps(hulls[j]):
                return False
    return True


def _key(factors: StructuralFactors, n: int, k: int, i: int, j: int, cache: dict[object, object]) -> object:
    """What makes two roots equal by an exact argument (module docstring); equal keys, equal values."""
    st = factors.structure
    ks = signed_offset(k, n)
    signature = tuple(s.value(ks) for s in st.symbols)
    f = (factors.zero if k == 0 else factors.other)[i]
    if f.roots is None:
        return ("ball", k, i, j)
    root = f.roots[j].xreplace(factors.atoms)
    varying = root.has(OMEGA) or root.has(COSK)
    if not varying or (12 * k) % n == 0:  # a value that is one number (at every k, or at k/n with a rational cosine)
        key = (k, i, j, signature) if varying else (k == 0, i, j, signature)
        if key not in cache:
            at = {OMEGA: sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)), COSK: sp.cos(2 * sp.pi * sp.Rational(k, n)), N: n}
            cache[key] = sp.simplify(root.xreplace(dict(zip(st.sigma, signature))).xreplace(at))
        value = cache[key]
        if not varying or isinstance(value, sp.Rational):
            return ("value", value)
    # the same root at k and n - k when it is symmetric in omega -> 1/omega and the symbols agree there
    mirrored = tuple(s.value(-ks) for s in st.symbols) == signature and _symmetric(root, (k == 0, i, j), cache)
    return ("cos", min(k, n - k) if mirrored else k, i, j)


def _symmetric(root: sp.Expr, key: tuple[bool, int, int], cache: dict[object, object]) -> bool:
    if ("symmetric", key) not in cache:
        cache[("symmetric", key)] = sp.simplify(root - root.xreplace({OMEGA: 1 / OMEGA})) == 0
    return bool(cache[("symmetric", key)])


def structural_zoo_certificate(scheme: StencilScheme, n: int, *, digits: int = 20) -> Certificate:
    """The spectrum of ``scheme``'s matrix at valence ``n`` from its structural blocks (module docstring)."""
    n, digits = check_valence(n), check_digits(digits)
    factors = structural_factors(scheme)
    st = factors.structure
    prec = max(128, 4 * digits + 64)
    items: list[tuple[flint.acb, object]] = []
    cache: dict[object, object] = {}
    try:
        with flint.ctx.workprec(prec):
            for k in range(n):
                items += [(b, (k, i, j)) for b, i, j in frequency_balls(factors, n, k)]
    except PrecisionError as exc:
        return _undecided(scheme, n, str(exc))
    size = st.class_count * n + st.has_centre
    if len(items) != size:
        return _undecided(scheme, n, f"the blocks give {len(items)} eigenvalues for a matrix of size {size}")
    groups = proved_distinct_groups(items)
    apart = _apart(items, groups)
    members: list[tuple[int, int, int]] = [m for _, m in items]  # type: ignore[misc]  # (k, factor, root) of each ball
    equal = all(len({_key(factors, n, *members[x], cache) for x in g}) == 1 for g in groups)
    certified = apart and equal
    note = "multiplicities certified" if certified else "multiplicities not certified (a group of balls holds roots not proved equal)"
    method = (f"S = the bordered block-circulant matrix of the structural blocks (read at n = {st.read_at}, checked exactly at "
              f"n = {st.read_at + 2}, {st.read_at + 3}); block roots in Arb")
    steps = f" over {scheme.steps} steps" if scheme.steps > 1 else ""
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE,
                       message=f"n = {n}{steps}: proved: {method}; {len(groups)} distinct eigenvalues, {note}", method=method,
                       distinct=len(groups), multiplicities=tuple(len(g) for g in groups),
                       values=tuple(acb_text(items[g[0]][0], digits) for g in groups), multiplicities_certified=certified,
                       height_bits=0, route="structural-form")


def _undecided(scheme: StencilScheme, n: int, why: str) -> Certificate:
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.UNDECIDED, message=f"n = {n}: undecided: {why}",
                       method="structural blocks in Arb", distinct=0, multiplicities=(), values=(), multiplicities_certified=False,
                       height_bits=0, route="structural-form")
