"""Independent checks of the closed forms against the full matrices, and Reif's certified C1 test.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""
