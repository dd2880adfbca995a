"""symdecomp: exact, symbolic eigenanalysis of subdivision surfaces through polygonal decompositions.

Implements and checks I.P. Ivrissimtzis, R. Zayer, H.-P. Seidel, *Polygonal decompositions of
quadrilateral subdivision meshes*. The public API at a glance:
"""

from . import symbols
from .cbmatrix import (
    CBMatrix,
    SymbolicCBMatrix,
    SymbolicCirculant,
    block_diagonalization,
    cb_eigensystem,
    cb_matrix,
    cb_matrix_from,
    constant_blocks,
    frequency_matrix,
    lifted_vector,
    perturbed_frequency_zero_matrix,
)
from .charpoly import ClosedFormCharpoly, closed_form_characteristic_polynomial, matrix_characteristic_polynomial
from .circulant import circ, circ_from_offsets, circulant_eigenvalue, fourier_matrix, generating_polynomial, root_of_unity
from .claims import CheckResult, Claim, Status, Step, all_claims, check_claim, get_claim
from .errors import (
    FrequencyOutOfRangeError,
    InvalidPolygonError,
    InvalidSchemeError,
    InvalidValenceError,
    NotAffineError,
    SymdecompError,
)
from .latex import aslatex
from .reduction import reduce_first_column, subdivision_block_form
from .frequency import circulant_blocks, frequency_zero_matrix, per_frequency_matrix, per_frequency_matrix_at
from .schemes import Scheme, Stencil, VertexRule, catmull_clark, subdivision_matrix
from .spectrum import Spectrum, closed_form_spectrum, frequency_zero_eigenvalues
from .certify import Certificate, certify
from .closed_forms import ClosedForms, derived_closed_forms
from .crosscheck import CheckStatus, NumericCheck, numeric_check
from .defective import jordan_block_size, jordan_vertex_weights
from .exact import characteristic_polynomial, exact_subdivision_matrix
from .tangent import invariant_ratio, invariant_ratio_at, invariant_ratio_limit, tangent_eigenvalues
from .elliptic import elliptic_defect_table, nice_elliptic_conditions
from .ellipses import ellipse_axes
from .hyperbolic import hyperbolic_equality, hyperbolic_ring, iterate_hyperbolic_ring
from .masks import limit_masks, limit_masks_at
from .tuning import joint_obstruction, tune
from .mesh import QuadMesh, central_rings, mesh_rules, refine, ring_mesh
from .support import Region, classify_support

__version__ = "0.1.0"

__all__ = [
    "symbols",
    # Section 2
    "root_of_unity",
    "fourier_matrix",
    "circ",
    "circ_from_offsets",
    "generating_polynomial",
    "circulant_eigenvalue",
    # schemes and matrices
    "Scheme",
    "Stencil",
    "VertexRule",
    "catmull_clark",
    "subdivision_matrix",
    "circulant_blocks",
    "per_frequency_matrix",
    "per_frequency_matrix_at",
    "frequency_zero_matrix",
    # Section 5.1
    "tangent_eigenvalues",
    "invariant_ratio",
    "invariant_ratio_at",
    "invariant_ratio_limit",
    "Spectrum",
    "closed_form_spectrum",
    "frequency_zero_eigenvalues",
    # Section 5.2-5.3 and limit masks
    "nice_elliptic_conditions",
    "elliptic_defect_table",
    "ellipse_axes",
    "tune",
    "joint_obstruction",
    "hyperbolic_equality",
    "hyperbolic_ring",
    "iterate_hyperbolic_ring",
    "limit_masks",
    "limit_masks_at",
    # Section 6
    "CBMatrix",
    "cb_matrix",
    "cb_matrix_from",
    "frequency_matrix",
    "lifted_vector",
    "block_diagonalization",
    "cb_eigensystem",
    "constant_blocks",
    "perturbed_frequency_zero_matrix",
    "SymbolicCirculant",
    "SymbolicCBMatrix",
    "subdivision_block_form",
    "reduce_first_column",
    "ClosedFormCharpoly",
    "closed_form_characteristic_polynomial",
    "matrix_characteristic_polynomial",
    # Section 3: whole meshes and supports
    "QuadMesh",
    "ring_mesh",
    "mesh_rules",
    "refine",
    "central_rings",
    "Region",
    "classify_support",
    # cross-checks against the full matrix
    "ClosedForms",
    "derived_closed_forms",
    "numeric_check",
    "NumericCheck",
    "certify",
    "Certificate",
    "CheckStatus",
    "exact_subdivision_matrix",
    "characteristic_polynomial",
    "jordan_vertex_weights",
    "jordan_block_size",
    # claims
    "Claim",
    "CheckResult",
    "Status",
    "Step",
    "all_claims",
    "check_claim",
    "get_claim",
    # LaTeX
    "aslatex",
    # errors
    "SymdecompError",
    "InvalidValenceError",
    "FrequencyOutOfRangeError",
    "InvalidPolygonError",
    "NotAffineError",
    "InvalidSchemeError",
]
