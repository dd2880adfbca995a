"""matplotlib figures of the paper's geometry, for the notebooks (matplotlib is optional).

Each function returns a :class:`matplotlib.figure.Figure` built from the package's results
(no pyplot, no global figure state); the modules follow the paper's sections.

Importing this package does not import matplotlib; calling a plotting function does, and
says how to install it if it is missing.

The modules of this folder are listed, with the rest of the package, in the one module map: the docstring of :mod:`symdecomp`.
"""

from symdecomp.output.plotting import (
    boundary,
    c1_figures,
    cbmatrix,
    characteristic,
    check_chart,
    design_figure,
    elliptic,
    meshes,
    polygons,
    refine_figure,
    regime_chart,
    spectrum_chart,
    tangent,
    tuning,
    zoo_maps,
)

__all__ = ["polygons", "tangent", "elliptic", "cbmatrix", "characteristic", "meshes", "tuning", "boundary", "c1_figures",
           "spectrum_chart", "regime_chart", "check_chart", "zoo_maps",
           "refine_figure", "design_figure"]
