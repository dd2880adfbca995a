"""The symbols shared by every module: the paper's notation as sympy objects."""

import sympy as sp

__all__ = ["n", "j", "omega", "alpha", "beta", "lam", "cos_jtheta", "sin_jtheta", "cos_theta"]

#: The valence of the central vertex O.
n = sp.Symbol("n", integer=True, positive=True)
#: A frequency index (a component of the decomposition).
j = sp.Symbol("j", integer=True, nonnegative=True)
#: ``omega`` stands for the root of unity ``omega_n^j`` of the frequency under study.
omega = sp.Symbol("omega")
#: The vertex-rule weights of Eq. 16 (weight of each ``a_i`` and of each ``b_i`` in the new O).
alpha = sp.Symbol("alpha", real=True)
beta = sp.Symbol("beta", real=True)
#: An eigenvalue.
lam = sp.Symbol("lambda")
#: ``c = cos(j*theta)`` with ``theta = pi/n``: the variable in which Eq. 34 is written (a real symbol).
cos_jtheta = sp.Symbol("c", real=True)
#: ``s = sin(j*theta)``; it disappears for mirror-symmetric schemes.
sin_jtheta = sp.Symbol("s", real=True)
#: ``c = cos(theta) = cos(pi/n)``: ``cos_jtheta`` at frequency ``j = 1``, positive (``>= 1/2`` for ``n >= 3``).
cos_theta = sp.Symbol("c", positive=True)
