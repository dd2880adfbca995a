"""What the toolkit shows: LaTeX derivations, Stam's data files and matplotlib figures.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""
