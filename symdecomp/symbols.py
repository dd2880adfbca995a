"""The symbols shared by every module: the paper's notation as sympy objects."""

import sympy as sp

__all__ = ["n", "j", "omega", "alpha", "beta", "lam", "cos_jtheta", "theta"]

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
#: ``theta = pi/n`` of Eq. 34.
theta = sp.pi / n
#: ``cos(j*theta)``, the variable in which Eq. 34 is written.
cos_jtheta = sp.cos(sp.pi * j / n)
