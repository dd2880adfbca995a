"""What a scheme's subdivision matrix says about the surface: the paper's Sections 3-6.

Per-frequency matrices (:mod:`.frequency`), closed-form spectra (:mod:`.spectrum`,
:mod:`.closed_forms`), the tangent plane (:mod:`.tangent`), elliptic and hyperbolic
properties (:mod:`.elliptic`, :mod:`.ellipses`, :mod:`.hyperbolic`), limit masks
(:mod:`.masks`), vertex-rule tuning (:mod:`.tuning`), the characteristic polynomial and the
bordered CB-matrix reduction (:mod:`.charpoly`, :mod:`.reduction`), defective eigenvalues
(:mod:`.defective`), supports of basis functions (:mod:`.support`) and rings iterated step by
step (:mod:`.evolution`).
"""
