"""The frequency blocks of a StencilScheme at every valence, read once: the structural form of the zoo's matrix.

The matrix at valence ``n`` (:mod:`symdecomp.analysis.zoo_matrix`) depends on ``n`` only through the rules
applied at the centre: a family (``over="ring"`` at the centre vertex, ``over="face"`` on the centre face)
spreads the weights ``w(n, j)``, ``j = 0..n-1``, around all the sectors, and a single term may have a weight
in ``n``. Everything else is the regular lattice's, and the stencils reach a fixed number of sectors. So the
blocks are read once, at one valence ``n0``, from the matrix of the scheme in which every weight at the centre
is a *marker* (an opaque number: the exact zero tests of the engine still decide by value): an entry of the
row of class ``c`` at sector offset ``d`` is

* a *band* part, a number or an expression in the single-term markers, nonzero for small ``|d|`` only;
* plus, for each family ``t`` at the centre, ``coef * w_t(n, j)`` with ``d = j + e`` for a fixed small
  shift ``e`` and every ``j``: at frequency ``k`` these add up to ``coef * zeta^(e k) * sigma_t(k)``, with
  ``sigma_t`` the family's symbol, summed in closed form for every ``n`` (:mod:`symdecomp.analysis.zoo_symbols`).

The form read at ``n0`` is checked, entry by entry and exactly, against the explicit matrices at ``n0 + 1``
and ``n0 + 2`` (as :func:`symdecomp.analysis.frequency.ring_blocks` checks the primal 1-ring schemes); the block of
frequency ``k`` at any ``n`` then costs ``O(1)`` (:meth:`ZooStructure.frequency_block`).

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> st = zoo_structure(load_zoo("doo-sabin"))
>>> st.class_count, st.has_centre, [str(x) for x in st.frequency_block(100, 2).entries()][:2]
(4, False, ['0.250000000000000', '0'])
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.analysis.zoo_blocks import signed_offset, zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_symbols import FamilySymbol, family_symbol
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.stencil_rows import is_zero
from symdecomp.schemes.stencils import J, KindRules, M, N, Rule, StencilScheme, Term
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_int, check_type

__all__ = ["ZooStructure", "zoo_structure", "READ_AT"]

#: ``{(c, c', d): entry}``: the band part of the blocks by classes and sector offset.
Band = dict[tuple[int, int, int], sp.Expr]
#: ``{(c, c', t, e): {j: coef}}``: family ``t`` at shift ``e``, its coefficient at each ``j``.
Groups = dict[tuple[int, int, int, int], dict[int, sp.Expr]]

#: The valence the blocks are read at (checked at the next two): above every valence a rule names (3..6 in the
#: shipped files) and wide enough that a band of a few sectors is told apart from a family around the centre.
READ_AT = 16


class _Mark(sp.Function):
    """A weight at the centre while the blocks are read: ``_Mark(t, j)``, the ``j``-th weight of term ``t``.

    An opaque positive number (the logarithm of a prime of its own), so the engine's exact zero tests, which
    decide a clearly nonzero value numerically, treat it as a number and never mistake it for another.
    """

    nargs = 2

    def _eval_evalf(self, prec: int) -> sp.Float:
        t, j = (int(a) for a in self.args)
        return sp.log(sp.prime(40 + 64 * t + j)).evalf(prec_to_dps(prec))


def prec_to_dps(prec: int) -> int:
    """Decimal digits for ``prec`` bits (and a few more)."""
    return max(15, int(prec * 0.30103) + 5)


@dataclass(frozen=True)
class _Family:
    """A term applied at the centre: its weight and the symbol its size is (``n`` of a ring, ``m`` of a face)."""

    weight: sp.Expr
    size: sp.Symbol
    #: Whether it is a family indexed by ``j`` (else a single point whose weight depends on the size).
    indexed: bool


def _mark_term(term: Term, t: int, n0: int) -> tuple[Term, _Family | None]:
    size = {"ring": N, "face": M}.get(term.over)
    used = term.symbols() & {N, M}
    if size is None:
        if not used:
            return term, None
        if len(used) > 1:
            raise NotApplicableError(f"a weight uses both n and m ({term.weight}): not read structurally")
        size = next(iter(used))
    elif used - {size}:
        raise NotApplicableError(f"a family over the {term.over} uses the other size ({term.weight}): not read structurally")
    indexed = term.over != "one"
    # a family with one weight for every j is marked alike at every j: a vertex rule must stay rotation-invariant
    marker = _Mark(t, (J if J in term.symbols() else -1) if indexed else 0)
    weight = sp.Piecewise((marker, sp.Eq(size, n0)), (term.weight, True))
    return Term(weight, term.walk, term.over, term.source), _Family(term.weight, size, indexed)


def _marked(scheme: StencilScheme, n0: int) -> tuple[StencilScheme, tuple[_Family, ...]]:
    """``scheme`` with each weight at a centre of size ``n0`` a marker, and the marked terms in marker order."""
    families: list[_Family] = []
    kinds = []
    for kr in scheme.kinds:
        rules = []
        for rule in kr.rules:
            terms = []
            for term in rule.terms:
                new, family = _mark_term(term, len(families), n0)
                if family is not None:
                    families.append(family)
                terms.append(new)
            rules.append(Rule(tuple(terms), rule.origin, rule.tip))
        kinds.append(KindRules(kr.kind, tuple(rules), kr.ends))
    marked = StencilScheme(scheme.name, scheme.lattice, scheme.topology, tuple(kinds), scheme.steps, scheme.parameters,
                           scheme.source, scheme.interpolatory)
    return marked, tuple(families)


def _split(entry: sp.Expr, families: tuple[_Family, ...]) -> tuple[sp.Expr, list[tuple[int, int, sp.Expr]]]:
    """``(band, [(t, j, coef)])``: ``entry = band + sum coef * w_t(j)`` over the indexed families' markers."""
    band: sp.Expr = sp.Integer(0)
    parts: dict[tuple[int, int], sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(entry)):
        marks = [f for f in sp.Mul.make_args(term) if isinstance(f, _Mark) and families[int(f.args[0])].indexed]
        powers = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.Pow) and isinstance(f.base, _Mark)]
        if len(marks) > 1 or any(families[int(p.base.args[0])].indexed for p in powers):
            raise NotApplicableError("a point uses the centre's family twice (a product of its weights): not read structurally")
        if not marks:
            band += term
            continue
        key = (int(marks[0].args[0]), int(marks[0].args[1]))
        parts[key] = parts.get(key, 0) + term / marks[0]
    return band, [(t, j, sp.expand(coef)) for (t, j), coef in parts.items()]


@dataclass(frozen=True, eq=False)  # one object per scheme (cached): compared and hashed by identity
class ZooStructure:
    """The blocks of a StencilScheme's matrix for every valence ``n >=`` :attr:`valid_from` (module docstring)."""

    #: The scheme's name.
    scheme: str
    #: The valence the blocks were read at (and checked at the next two).
    read_at: int
    #: Whether there is a fixed centre point (vertex-centred).
    has_centre: bool
    #: The number of classes of points per sector.
    class_count: int
    #: The block ``B(omega)``, an expression in ``omega``, ``n`` and the families' symbols ``sigma_t``.
    block: sp.ImmutableMatrix
    #: The centre row summed over the sectors, and the centre's entries, as expressions in ``n`` and ``sigma_t(0)``.
    border: tuple[sp.Expr, ...]
    #: The families' symbols (closed forms for every size).
    symbols: tuple[FamilySymbol, ...]
    #: The symbols ``sigma_t`` standing for them in :attr:`block`.
    sigma: tuple[sp.Symbol, ...]
    #: The smallest valence the form holds at (every family's symbol valid, the band apart).
    valid_from: int
    #: The ring depth of the neighbourhood the matrix is on.
    depth: int = 1
    #: Which of the scheme's marked terms each ``sigma_t`` sums (in the order of :attr:`sigma`).
    terms: tuple[int, ...] = ()

    @functools.cached_property
    def _compiled(self) -> tuple[Any, ...]:
        variables = (OMEGA, N, *self.sigma)
        block = [compile_expression(e, variables, "arb") for e in self.block]
        border = [compile_expression(e, variables, "arb") for e in self.border]
        symbols = [(compile_expression(s.otherwise, (s.size,), "arb"),
                    {k: compile_expression(v, (s.size,), "arb") for k, v in s.at.items()}) for s in self.symbols]
        return block, border, symbols

    def sigma_values(self, n: int, k: int) -> list[flint.acb]:
        """The families' symbols ``sigma_t`` at valence ``n`` and frequency ``k`` in Arb (closed forms)."""
        ks = signed_offset(k, n)
        nb = flint.acb(n)
        return [at[ks](nb) if ks in at else other(nb) for other, at in self._compiled[2]]

    def frequency_block(self, n: int, k: int) -> flint.acb_mat:
        """The block of frequency ``k`` at valence ``n`` in Arb (at ``k = 0`` bordered by the centre when there is one)."""
        if n < self.valid_from:
            raise NotApplicableError(f"n = {n}: the structural form holds from n = {self.valid_from}")
        block, border, _ = self._compiled
        nb = flint.acb(n)
        sig = self.sigma_values(n, k)
        w = flint.acb(flint.arb(flint.fmpq(2 * k, n))).exp_pi_i()
        K = self.class_count
        values = [f(w, nb, *sig) for f in block]
        if k != 0 or not self.has_centre:
            return flint.acb_mat(K, K, values)
        b = [f(w, nb, *sig) for f in border]  # centre, row (K), column (K)
        rows = [[b[0], *b[1:K + 1]]] + [[b[K + 1 + c], *values[c * K:(c + 1) * K]] for c in range(K)]
        return flint.acb_mat(rows)


def _read(scheme: StencilScheme, n0: int, depth: int | None = None
          ) -> tuple[Any, dict[int, sp.Matrix], tuple[_Family, ...], int]:
    """The blocks read with markers, the centre's row by sector offset (``1 x K``), the marked terms, the depth."""
    marked, families = _marked(scheme, n0)
    zm = zoo_matrix(marked, n0, depth)
    blocks, nb = zoo_blocks(zm), zm.neighbourhood
    row: dict[int, sp.Matrix] = {}
    if nb.centre is not None:
        index = nb.index()
        at = {nb.labels[v]: index[v] for v in nb.order if v != nb.centre}
        o = index[nb.centre]
        row = {signed_offset(d, n0): sp.Matrix(1, blocks.class_count, [zm.matrix[o, at[(d, c)]] for c in range(blocks.class_count)])
               for d in range(n0)}
    return blocks, row, families, zm.depth


def _weight_at(family: _Family, n: int | sp.Expr, j: int | sp.Expr) -> sp.Expr:
    return sp.sympify(family.weight.xreplace({family.size: n, J: j}).doit(), strict=True)


def _scalars(expr: sp.Expr, families: tuple[_Family, ...], n: sp.Expr, n0: int) -> sp.Expr:
    """``expr`` with each single-term marker its weight at ``n``, each pointwise family marker its weight ``w(n, j)``."""
    subs = {}
    for m in sp.sympify(expr, strict=True).atoms(_Mark):
        f = families[int(m.args[0])]
        j = signed_offset(int(m.args[1]), n0)
        subs[m] = _weight_at(f, n, j % n if isinstance(n, int) else (j if j >= 0 else n + j))
    return sp.expand(sp.sympify(expr, strict=True).xreplace(subs))



def _groups(offsets: dict[int, sp.Matrix], n0: int, families: tuple[_Family, ...]) -> tuple[Band, Groups]:
    """``({(c, c', d): band}, {(c, c', t, e): {j: coef}})`` from the blocks read with markers.

    A family with one weight for every ``j`` (marked ``j = -1``) enters every offset: its coefficient far from
    the centre's sector is its group's (shift 0), the differences near it are band entries."""
    band: Band = {}
    groups: Groups = {}
    uniform: dict[tuple[int, int, int], dict[int, sp.Expr]] = {}
    for d, A in offsets.items():
        for c in range(A.rows):
            for e in range(A.cols):
                b, parts = _split(A[c, e], families)
                if b != 0:
                    band[(c, e, d)] = b
                for t, j, coef in parts:
                    if j < 0:
                        uniform.setdefault((c, e, t), {})[d] = coef
                        continue
                    key = (c, e, t, signed_offset(d - j, n0))
                    if j in groups.setdefault(key, {}):
                        raise NotApplicableError("a family's weight enters one entry twice: not read structurally")
                    groups[key][j] = coef
    for (c, e, t), by_d in uniform.items():
        far = by_d.get(n0 // 2, sp.Integer(0))
        groups[(c, e, t, 0)] = dict.fromkeys(range(n0), far)
        for d in {signed_offset(x, n0) for x in range(n0)}:
            rest = sp.expand(by_d.get(d, 0) - far)
            if rest != 0:
                band[(c, e, d)] = band.get((c, e, d), 0) + rest * _Mark(t, -1)
    return band, groups


def _whole(parts: dict[int, sp.Expr], n0: int, what: str) -> sp.Expr:
    """The common coefficient of a family's markers ``j = 0..n0-1`` (the family sums to its symbol), or an error."""
    coefs = set(parts.values())
    if set(parts) != set(range(n0)) or len(coefs) != 1:
        raise NotApplicableError(f"{what}: the centre's family does not enter every sector alike (not read structurally)")
    return coefs.pop()


def _reach(n0: int, *offsets: int) -> None:
    if any(abs(d) > n0 // 2 - 2 for d in offsets):
        raise NotApplicableError(f"the stencils reach {max(map(abs, offsets))} sectors, too far to read at n = {n0}")


def _form(scheme: StencilScheme, n0: int, depth: int | None = None
          ) -> tuple[ZooStructure, Band, Groups, tuple[_Family, ...]]:
    """The structure read at ``n0``, with its band and groups (for the checks)."""
    blocks, centre_row, families, depth = _read(scheme, n0, depth)
    K = blocks.class_count
    band, groups = _groups(blocks.offsets, n0, families)
    _reach(n0, *(d for _, _, d in band), *(e for *_, e in groups))
    sigma: dict[int, sp.Symbol] = {}
    B = sp.zeros(K, K)
    for (c, e, d), b in band.items():
        B[c, e] += _scalars(b, families, N, n0) * OMEGA**d
    for (c, e, t, shift), parts in groups.items():
        coef = _whole(parts, n0, f"block ({c}, {e})")
        B[c, e] += _scalars(coef, families, N, n0) * OMEGA**shift * sigma.setdefault(t, sp.Symbol(f"sigma{t}"))
    later = _read(scheme, n0 + 1, depth)[0] if blocks.has_centre else None
    border = _border(blocks, later, centre_row, families, sigma, n0)
    fams = sorted(sigma)
    symbols = tuple(family_symbol(families[t].weight, families[t].size) for t in fams)
    valid = max([n0] + [s.valid_from for s in symbols])
    st = ZooStructure(scheme.name, n0, blocks.has_centre, K, sp.ImmutableMatrix(B), border, symbols,
                      tuple(sigma[t] for t in fams), valid, depth, tuple(fams))
    return st, band, groups, families


def _border(blocks: Any, later: Any, centre_row: dict[int, sp.Matrix], families: tuple[_Family, ...],
            sigma: dict[int, sp.Symbol], n0: int) -> tuple[sp.Expr, ...]:
    """``(centre, row summed over the sectors..., column...)`` in ``n`` and ``sigma_t`` (at ``k = 0``)."""
    if not blocks.has_centre:
        return ()
    band, groups = _groups(centre_row, n0, families)
    _reach(n0, *(d for _, _, d in band), *(e for *_, e in groups))
    row = [sp.Integer(0)] * blocks.class_count
    for (_, e, _), b in band.items():
        row[e] += _scalars(b, families, N, n0)
    for (_, e, t, _), parts in groups.items():
        if t not in sigma:
            sigma[t] = sp.Symbol(f"sigma{t}")
        row[e] += _scalars(_whole(parts, n0, f"centre row {e}"), families, N, n0) * sigma[t]
    column = [_affine(a, b, families, n0) for a, b in zip(blocks.centre_column, later.centre_column)]
    return (_affine(blocks.centre, later.centre, families, n0), *[sp.expand(x) for x in row], *column)


def _affine(at_n0: sp.Expr, at_n1: sp.Expr, families: tuple[_Family, ...], n0: int) -> sp.Expr:
    """An entry at the centre, read at ``n0`` and ``n0 + 1``, as an expression in ``n``.

    A whole family may land on the centre point (each of its ``n`` weights once: ``n w(n)``), so the coefficient
    of each product of markers is taken as affine in ``n`` through the two readings (checked at two more valences).
    """
    names: dict[tuple[int, int], sp.Symbol] = {}

    def named(e: sp.Expr, n: int) -> sp.Expr:
        subs = {}
        for m in sp.sympify(e, strict=True).atoms(_Mark):
            key = (int(m.args[0]), signed_offset(int(m.args[1]), n))
            subs[m] = names.setdefault(key, sp.Symbol(f"w{key[0]}_{key[1]}"))
        return sp.expand(sp.sympify(e, strict=True).xreplace(subs))

    e0, e1 = named(at_n0, n0), named(at_n1, n0 + 1)
    gens = tuple(names.values())
    if not gens:
        return sp.expand(e0 + (e1 - e0) * (N - n0))
    p0, p1 = sp.Poly(e0, *gens), sp.Poly(e1, *gens)
    total = sp.Integer(0)
    for monomial in set(p0.monoms()) | set(p1.monoms()):
        c0, c1 = p0.coeff_monomial(monomial), p1.coeff_monomial(monomial)
        total += (c0 + (c1 - c0) * (N - n0)) * sp.Mul(*[g**k for g, k in zip(gens, monomial)])
    weights = {g: _weight_at(families[t], N, j if j >= 0 else N + j) for (t, j), g in names.items()}
    return sp.expand(total.xreplace(weights))


def _predicted(band: Band, groups: Groups, families: tuple[_Family, ...], n0: int, n: int, key: tuple[int, int, int]) -> sp.Expr:
    """The entry ``A_d[c, c']`` at valence ``n`` that the form read at ``n0`` predicts."""
    c, e, d = key
    total = _scalars(band.get((c, e, d), 0), families, sp.Integer(n), n0) if (c, e, d) in band else sp.Integer(0)
    for (gc, ge, t, shift), parts in groups.items():
        if (gc, ge) == (c, e):
            coef = _scalars(next(iter(parts.values())), families, sp.Integer(n), n0)
            total += coef * _weight_at(families[t], n, (d - shift) % n)
    return sp.expand(total)


def _check(scheme: StencilScheme, st: ZooStructure, band: Band, groups: Groups, families: tuple[_Family, ...], n: int) -> None:
    """The explicit matrix at ``n`` is, entry by entry and exactly, the form read at :attr:`ZooStructure.read_at`."""
    explicit = zoo_blocks(zoo_matrix(scheme, n, st.depth))
    K, n0 = st.class_count, st.read_at
    zero = sp.zeros(K, K)
    for d in {signed_offset(x, n) for x in range(n)}:
        A = explicit.offsets.get(d, zero)
        for c in range(K):
            for e in range(K):
                want = _predicted(band, groups, families, n0, n, (c, e, d))
                if not (A[c, e] == want or is_zero(A[c, e] - want)):
                    raise InvalidSchemeError(f"scheme {scheme.name!r}: the matrix at n = {n} is not the structural form read "
                                             f"at n = {n0} (block ({c}, {e}), offset {d}: {A[c, e]} against {want})")
    if not st.has_centre:
        return
    sums = {s: sp.Add(*[_weight_at(families[t], n, j) for j in range(n)]) for s, t in zip(st.sigma, st.terms)}
    want_border = [sp.sympify(x, strict=True).xreplace({N: n, **sums}) for x in st.border]
    got = [explicit.centre, *explicit.centre_row, *explicit.centre_column]
    for i, (a, b) in enumerate(zip(got, want_border)):
        if not (a == b or is_zero(a - b)):
            raise InvalidSchemeError(f"scheme {scheme.name!r}: the centre's entries at n = {n} are not the structural form "
                                     f"read at n = {n0} (border entry {i}: {a} against {b})")


def zoo_structure(scheme: StencilScheme, n0: int = READ_AT, depth: int | None = None) -> ZooStructure:
    """The blocks of ``scheme`` for every valence from :attr:`ZooStructure.valid_from`, read at ``n0`` (the centre's entries
    at ``n0 + 1`` too) and checked exactly at ``n0 + 2`` and ``n0 + 3`` against the explicit matrices; ``depth``: the
    neighbourhood's ring depth (default: the smallest invariant one, :func:`~symdecomp.analysis.zoo_matrix.zoo_matrix`).

    :class:`~symdecomp.errors.NotApplicableError` when the scheme's centre rules do not have the form (module
    docstring); :class:`~symdecomp.errors.InvalidSchemeError` when a check fails.
    """
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    if depth is not None:
        depth = check_int(depth, "depth", minimum=1)
    return _zoo_structure(scheme, check_int(n0, "n0", minimum=READ_AT), depth)


@functools.lru_cache(maxsize=16)
def _zoo_structure(scheme: StencilScheme, n0: int, depth: int | None = None) -> ZooStructure:
    st, band, groups, families = _form(scheme, n0, depth)
    for n in (n0 + 2, n0 + 3):
        _check(scheme, st, band, groups, families, n)
    return st
