"""Subdivision schemes as data, and the matrices and meshes built from their rules.

The lattice a scheme lives on, one object per kind of mesh (:mod:`.lattice`), a scheme's rules
and the one assembly of its subdivision matrix (:mod:`.scheme`), the full
matrix in FLINT rationals and its characteristic polynomial (:mod:`.full_matrix`), rules as
polynomials in the index shift (:mod:`.shift_stencil`), whole quad meshes refined by the
scheme's rules (:mod:`.mesh`), the 1-ring as a polygon pair (:mod:`.ring`), and the regular Loop patch (the quartic box
spline) in Bezier form, derived by exact refinement (:mod:`.box_spline`).
"""

from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark, subdivision_matrix, vertex_order

__all__ = ["Scheme", "Stencil", "VertexRule", "catmull_clark", "subdivision_matrix", "vertex_order"]
