"""The symbols shared by every module: the paper's notation as sympy objects."""

import re

import sympy as sp
from sympy.printing.latex import greek_letters_set, translate

__all__ = [
    "n", "j", "omega", "alpha", "beta", "lam", "cos_jtheta", "sin_jtheta", "cos_theta", "theta_k", "sector_faces", "Parameter",
    "RESERVED_NAMES",
]

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
#: The sector angle of a sharp feature's rules (Biermann-Levin-Zorin's ``theta_k``): ``pi/k`` in a crease or
#: boundary sector of ``k`` faces, ``alpha/k`` in a corner sector of angle ``alpha``.
theta_k = sp.Symbol("theta_k", positive=True)
#: The number ``k`` of faces of a sector between two sharp edges.
sector_faces = sp.Symbol("k", integer=True, positive=True)


class Parameter(sp.Symbol):
    """A free parameter named by a user (a scheme file's ``parameters``, a symbol in a weight given to the API).

    A class of its own, so that a user's names live in their own namespace: ``Parameter("c", real=True)``
    is never equal to :data:`cos_jtheta` (``Symbol("c", real=True)``), nor to any symbol the toolkit makes
    for its own derivations (``t``, ``r1``, ``x``, ...), although it prints the same. sympy compares
    symbols by class, name and assumptions, so substituting the toolkit's ``c`` can never touch it.
    The paper's vertex weights :data:`alpha` and :data:`beta` are the exception: a scheme that names its
    vertex-rule weights ``alpha``, ``beta`` means the paper's (tuning reads them).

    In LaTeX a parameter is its name and nothing else: a Greek name is the letter, digits and the
    parts after ``_`` are subscripts; no other part of a name becomes a command (sympy would read
    ``xscr`` as ``\\mathscr{x}``, ``xhat`` as ``\\hat{x}``), and characters other than letters, digits
    and ``_`` are dropped (the scheme refuses such names; :func:`symdecomp.schemes.scheme.Scheme`).

    >>> sp.latex(Parameter("gamma2") + Parameter("xscr") + Parameter("t_k"))
    '\\\\gamma_{2} + t_{k} + xscr'
    """

    __slots__ = ()

    def _latex(self, printer) -> str:
        base, *subscripts = [part for part in re.sub(r"[^A-Za-z0-9_]", "", self.name).split("_") if part] or ["p"]
        letters, digits = re.fullmatch(r"(.*?)(\d*)", base).groups()
        subscripts = [digits, *subscripts] if digits and letters else subscripts

        def word(text: str) -> str:
            return translate(text) if text.lower() in greek_letters_set else text

        head = word(letters or base)
        return head + ("_{%s}" % " ".join(map(word, subscripts)) if subscripts else "")


#: Names a user may not give a parameter: the toolkit's own symbols (which would print the same as
#: the parameter in every derivation, or are the sector's face count ``k`` of the sharp rules) and the functions
#: and constants of the weight grammar.
RESERVED_NAMES = ("n", "j", "c", "s", "omega", "lambda", "pi", "sqrt", "cos", "sin", "k")
