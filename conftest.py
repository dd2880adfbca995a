"""One fixture for every test and doctest: precision is scoped, never left changed."""

import flint
import mpmath
import pytest


@pytest.fixture(autouse=True)
def _reset_precision():
    """Every test starts and ends at mpmath's and FLINT's default precision."""
    mpmath.mp.dps = 15
    flint.ctx.prec = 53
    yield
    mpmath.mp.dps = 15
    flint.ctx.prec = 53
