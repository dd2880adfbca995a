"""What a scheme's subdivision matrix says about the surface: the paper's Sections 3-6.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""
