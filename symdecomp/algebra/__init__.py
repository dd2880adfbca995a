"""Exact algebra with no knowledge of subdivision schemes.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""
