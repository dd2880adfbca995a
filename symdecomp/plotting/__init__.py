"""matplotlib figures of the paper's geometry, for the notebooks (matplotlib is optional).

Each function returns a :class:`matplotlib.figure.Figure` built from the package's results;
the modules follow the paper: :mod:`.polygons` (Sections 2 and 4, Fig. 2-3) and
:mod:`.tangent` (Section 5.1, Fig. 6). Importing this package does not import matplotlib;
calling a plotting function does, and says how to install it if it is missing.
"""

from .polygons import draw_polygon_2d, draw_polygon_3d, regular_polygons_figure
from .tangent import invariant_ratio_sweep_figure, invariant_ratios, invariant_ring_figure, tangent_eigenvalues_figure

__all__ = [
    "regular_polygons_figure",
    "draw_polygon_2d",
    "draw_polygon_3d",
    "tangent_eigenvalues_figure",
    "invariant_ring_figure",
    "invariant_ratio_sweep_figure",
    "invariant_ratios",
]
