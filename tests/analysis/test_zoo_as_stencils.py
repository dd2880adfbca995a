"""Today's 1-ring schemes converted to stencils (``as_stencils``) run through the zoo's engine: its spectrum holds the
1-ring matrix's, value by value with the multiplicities (the engine's neighbourhood by closure may be larger; its
other eigenvalues are those of the outer rings)."""

from __future__ import annotations

import pytest

from symdecomp import catmull_clark
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.schemes.loop import loop
from symdecomp.schemes.stencil_convert import as_stencils


@pytest.mark.parametrize("make, n", [(catmull_clark, 3), (catmull_clark, 5), (catmull_clark, 7), (loop, 4), (loop, 7)])
def test_the_engine_on_a_converted_scheme_holds_its_one_ring_spectrum(make, n):
    ours = zoo_spectrum(as_stencils(make()), n).eigenvalues
    for e in ring_spectrum(make(), n).eigenvalues:
        same = [f for f in ours if f.value.overlaps(e.value)]
        assert len(same) == 1 and same[0].multiplicity >= e.multiplicity
        assert e.exact is None or same[0].exact is None or (same[0].exact - e.exact).equals(0)
