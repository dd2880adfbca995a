"""Independent checks of the closed forms against the full matrices.

Numeric (:mod:`.numeric`, mpmath at raised precision until the answer stops moving),
certified (:mod:`.certify`, FLINT exact characteristic polynomials and Arb balls), both returning a
:class:`~.result.CrossCheckResult`, and the
OpenSubdiv oracle (:mod:`.oracle`, through the bridge in :mod:`.opensubdiv`).
"""
