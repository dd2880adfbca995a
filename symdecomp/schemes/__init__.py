"""Subdivision schemes as data, and the matrices and meshes built from their rules.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark, subdivision_matrix, vertex_order

__all__ = ["Scheme", "Stencil", "VertexRule", "catmull_clark", "subdivision_matrix", "vertex_order"]
