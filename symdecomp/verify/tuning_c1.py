"""The tuning region with Reif's weight-independent conditions certified (issue 21, item 5).

:func:`symdecomp.analysis.tuning_region.tuning_region` cuts the vertex weights at ``O`` by exact
linear conditions; the rest of Reif's test (the eigenvalues of the other frequencies and of the
outer blocks, and the characteristic map, regular and injective) does not depend on those weights:
the characteristic map is spanned by the eigenvectors of ``lambda_1`` at frequencies ``1`` and
``n - 1``, which have ``O = 0`` and are made of ``M_1``'s eigenvector and the regular rules
(:mod:`symdecomp.analysis.characteristic`). So one run of :func:`~symdecomp.verify.c1.c1_test` at one
point of the open C1 set (the *witness*, :func:`~symdecomp.analysis.tuning_region.witness_scheme`)
decides it for every point: ``c1`` there means the whole open set is C1; ``not-c1`` means no vertex
weights make the scheme C1 at ``n`` (the regions are then empty).

>>> from symdecomp.schemes.files import scheme_from_text
>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.files import scheme_to_text
>>> text = scheme_to_text(catmull_clark()).replace('a = "3/(2*n**2)"', 'a = "alpha"').replace('b = "1/(4*n**2)"', 'b = "beta"')
>>> free = scheme_from_text('parameters = ["alpha", "beta"]\\n' + text)
>>> region = certified_tuning_region(free, 4)
>>> region.witness_verdict, str(region.classify((sp.Rational(3, 32), sp.Rational(1, 64))))
('c1', 'bounded')
"""

from __future__ import annotations

import dataclasses

import sympy as sp

from symdecomp.analysis.tuning_region import TuningRegion, tuning_region, witness_scheme
from symdecomp.errors import InternalError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_valence
from symdecomp.verify.c1 import c1_test

__all__ = ["certified_tuning_region"]


@cached(scheme=check_scheme, n=check_valence)
def certified_tuning_region(scheme: Scheme, n: int) -> TuningRegion:
    """:func:`~symdecomp.analysis.tuning_region.tuning_region` with the weight-independent conditions decided at its witness."""
    region = tuning_region(scheme, n)
    concrete = witness_scheme(region, scheme)
    if concrete is None:
        return dataclasses.replace(region, witness_verdict="not-c1",
                                   witness_reason="no vertex weights put the frequency-0 eigenvalues below lambda_1")
    result = c1_test(concrete, region.n)
    if region.witness is None:
        raise InternalError(f"n = {region.n}: a witness scheme was built without the region's witness point")
    point = ", ".join(f"{p} = {sp.sstr(v)}" for p, v in zip(region.parameters, region.witness))
    if region.n == scheme.lattice.regular_valence:
        point = f"{scheme.lattice.reference().name}'s vertex weights (O has the regular valence)"
    return dataclasses.replace(region, witness_verdict=str(result.verdict), witness_reason=f"at {point}: {result.reason}")
