"""matplotlib figures of the paper's geometry, for the notebooks (matplotlib is optional).

Each function returns a :class:`matplotlib.figure.Figure` built from the package's results
(no pyplot, no global figure state); the modules follow the paper:

* :mod:`.polygons`: Sections 2 and 4, the regular n-gons (Fig. 3), a polygon's decomposition
  into regular n-gons (Eq. 5-6), a 1-ring's 2n-gon splitting into parallel n-gons (Fig. 2);
* :mod:`.tangent`: Section 5.1, the eigenvalues of ``M_j``, the invariant ratio (Eq. 39,
  Fig. 6) and which 2n-gon components survive iteration (Prop. 5.1, Remark 5.1);
* :mod:`.elliptic`: Sections 5.2-5.3, the ellipses ``E_a``, ``E_b`` (Fig. 7), a hyperbolic
  configuration (Fig. 8), the elliptic defects and tuned weights;
* :mod:`.cbmatrix`: Section 6, the eigenvalues constant blocks and vertex weights move
  (Prop. 6.3);
* :mod:`.characteristic`: Reif's test, the characteristic map's ring per valence.

Importing this package does not import matplotlib; calling a plotting function does, and
says how to install it if it is missing.
"""

from symdecomp.output.plotting import cbmatrix, characteristic, elliptic, polygons, tangent

__all__ = ["polygons", "tangent", "elliptic", "cbmatrix", "characteristic"]
