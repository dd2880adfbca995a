"""Exact algebra with no knowledge of subdivision schemes.

Circulant matrices and the Fourier matrix (:mod:`.circulant`), matrices of circulant blocks
(:mod:`.cbmatrix`), cyclotomic fields (:mod:`.cyclotomic`), the polygonal decomposition of
Section 2 (:mod:`.polygons`), and fast exact or interval evaluation of sympy expressions
(:mod:`.compile`).
"""
