"""symdecomp: exact, symbolic eigenanalysis of subdivision surfaces through polygonal decompositions.

Implements and checks I.P. Ivrissimtzis, R. Zayer, H.-P. Seidel, *Polygonal decompositions of
quadrilateral subdivision meshes*. The package is layered; each folder imports only from the
ones above it in this list (``tests/test_layers.py`` checks it):

=================  ===========================================================================
``errors``,        the package's error types; the symbols ``n``, ``omega``, ``alpha``, ``beta``
``symbols``
``algebra/``       no scheme knowledge: circulants and the Fourier matrix (Section 2,
                   ``circulant``), CB-matrices (Section 6, ``cbmatrix``), cyclotomic fields
                   (``cyclotomic``), polygon decompositions (Eq. 5-6, ``polygons``), fast
                   exact/interval evaluation of expressions (``compile``), small exact
                   eigen-decompositions (``small_eigen``), correct rounding of balls (``rounding``)
``schemes/``       a scheme as data (edge, face, vertex rules, ``scheme``), its subdivision
                   matrix (Eq. 13-16, ``scheme``; exact FLINT matrices, ``matrices``), whole quad
                   meshes refined by its rules (Section 3, ``mesh``), the 1-ring as a pair of
                   polygons (Section 4, ``ring``), Stam's (2N+8)-point patch matrix (``patch``)
``analysis/``      per-frequency matrices M_j and the Eq. 43 matrix (``frequency``), spectra
                   (Eq. 34, ``spectrum``, ``closed_forms``), the tangent plane (Section 5.1,
                   ``tangent``), elliptic and hyperbolic properties (Sections 5.2-5.3,
                   ``elliptic``, ``ellipses``, ``hyperbolic``), limit masks (``masks``), tuning
                   (``tuning``), the characteristic polynomial (Section 6, ``charpoly``,
                   ``reduction``), Jordan blocks (``defective``), supports (Section 3,
                   ``support``), rings iterated step by step (``evolution``), the patch's
                   certified eigen-data (``eigendata``) and exact evaluation (``evaluation``)
``verify/``        cross-checks against the full matrices: numeric (``numeric``), certified
                   (``certify``), OpenSubdiv (``oracle``, ``opensubdiv``), dyadic limit
                   positions for the evaluator (``patch_eval``)
``claims/``        the paper's claims, one module per section, and their registry
``output/``        LaTeX (``latex``, one entry point ``aslatex``), figures (``plotting``), Stam's
                   data file (``evaldata``)
``cli/``           the ``symdecomp`` command, one module per subcommand
=================  ===========================================================================

The names below are the public API (re-exported from the modules above).
"""

from symdecomp import symbols
from symdecomp.algebra.cbmatrix import (
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
from symdecomp.analysis.charpoly import ClosedFormCharpoly, closed_form_characteristic_polynomial, matrix_characteristic_polynomial
from symdecomp.algebra.circulant import circ, circ_from_offsets, circulant_eigenvalue, fourier_matrix, generating_polynomial, root_of_unity
from symdecomp.claims import CheckResult, Claim, Status, Step, all_claims, check_claim, get_claim
from symdecomp.errors import (
    FrequencyOutOfRangeError,
    InvalidPolygonError,
    InvalidSchemeError,
    InvalidValenceError,
    NotAffineError,
    SymdecompError,
)
from symdecomp.output.latex import aslatex
from symdecomp.analysis.reduction import reduce_first_column, subdivision_block_form
from symdecomp.analysis.frequency import circulant_blocks, frequency_zero_matrix, per_frequency_matrix, per_frequency_matrix_at
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark, subdivision_matrix
from symdecomp.analysis.spectrum import Spectrum, closed_form_spectrum, frequency_zero_eigenvalues
from symdecomp.verify.certify import Certificate, certify
from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.verify.numeric import CheckStatus, NumericCheck, numeric_check
from symdecomp.analysis.defective import jordan_block_size, jordan_vertex_weights
from symdecomp.schemes.matrices import characteristic_polynomial, exact_subdivision_matrix
from symdecomp.analysis.tangent import invariant_ratio, invariant_ratio_at, invariant_ratio_limit, tangent_eigenvalues
from symdecomp.analysis.elliptic import elliptic_defect_table, nice_elliptic_conditions
from symdecomp.analysis.ellipses import ellipse_axes
from symdecomp.analysis.hyperbolic import hyperbolic_equality, hyperbolic_ring, iterate_hyperbolic_ring
from symdecomp.analysis.masks import limit_masks, limit_masks_at
from symdecomp.analysis.tuning import joint_obstruction, tune
from symdecomp.schemes.mesh import QuadMesh, central_rings, mesh_rules, refine, ring_mesh
from symdecomp.analysis.support import Region, classify_support
from symdecomp.schemes.patch import patch_matrices
from symdecomp.analysis.eigendata import NotDiagonalizableError, certified_eigendata
from symdecomp.analysis.evaluation import PatchEvaluator

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
    # exact evaluation near an extraordinary vertex (Stam)
    "patch_matrices",
    "certified_eigendata",
    "NotDiagonalizableError",
    "PatchEvaluator",
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
