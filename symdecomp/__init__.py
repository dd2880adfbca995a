"""symdecomp: exact, symbolic eigenanalysis of subdivision surfaces through polygonal decompositions.

Implements and checks I.P. Ivrissimtzis, R. Zayer, H.-P. Seidel, *Polygonal decompositions of
quadrilateral subdivision meshes*. The package is layered; each folder imports only from the
ones above it in this list (``tests/project/test_layers.py`` checks it). This table is the one map of the
package: it names every module (a folder's modules relative to the folder; the subpackages'
docstrings point here), and ``tests/project/test_layers.py`` checks that it names every module and
nothing else.

=================  ===========================================================================
``errors``         the package's error types, all of them
``symbols``        the paper's symbols n, omega, alpha, beta, c = cos(j pi/n) and sin(j pi/n)
``expressions``    exact weights and expressions from user input, parsed and never evaluated
``validate``       one validation layer for every input from outside (valences, frequencies, ...)
``parallel/``      the one pool of worker processes (local, or a Dask cluster), valences in order; the Dask
                   side: scheduler addresses checked, the peer asked first, every wait bounded (``cluster``)
``algebra/``       no scheme knowledge: circulants and the Fourier matrix and its rows (Section 2,
                   ``circulant``), CB-matrices (Section 6, ``cbmatrix``), cyclotomic fields
                   (``cyclotomic``), polygon decompositions (Eq. 5-6, ``polygons``), fast
                   exact/interval evaluation of expressions (``compile``), the conversions
                   between sympy, Fraction, FLINT and Arb numbers (``numbers``), small exact
                   eigen-decompositions (``small_eigen``), the certified null vector of a ball matrix
                   (``null_vector``), correct rounding of balls (``rounding``),
                   clusters of enclosures that may overlap (``clusters``),
                   polynomials over a triangle in Bezier form (``triangle_bezier``), products of
                   tensor and triangular Bernstein polynomials in Arb (``bernstein``), signs of
                   rational functions of n for every n (``valence_signs``), of a rational polynomial on an
                   interval by Sturm sequences in FLINT (``interval_signs``), every root of a polynomial with
                   parameters in a disc as polynomial inequalities (Schur-Cohn, ``schur_cohn``), exact signs of real
                   algebraic numbers (``algebraic_sign``), identities in sines and cosines decided as exponential
                   polynomials (``trig_identity``),
                   exact left eigenspaces over Q(lambda) by rational linear algebra (``number_field``), a
                   rational expression in one symbol and one square root as the polynomial it equals
                   (``quadratic_extension``),
                   exact linear algebra over one real field Q(cos(pi/k)) (``cos_field``), the
                   eigen-decomposition of a rational matrix by the irreducible factors of its
                   characteristic polynomial (``primary_decomposition``)
``schemes/``       the lattice a scheme lives on, one object per kind of mesh (``lattice``: quad,
                   triangle; regular valence, rings and labels, refinement, regular patch: every
                   fact that depends on the kind of mesh, asked of the lattice, never compared), a
                   scheme as data (edge, face, vertex rules on a lattice, for the whole mesh) and
                   the one assembly of its subdivision matrix (Eq. 13-16, ``scheme``), the checks a scheme passes
                   once, when built (``scheme_checks``), the full
                   matrix in FLINT rationals and its characteristic polynomial (``full_matrix``),
                   rules as polynomials in the index shift (Eq. 17-23, ``shift_stencil``), a scheme of the zoo as
                   stencils of any support on halfedge walks (``stencils``), the zoo's scheme files and the
                   families shipped as TOML files in its folder zoo, a new family one more file there
                   (``stencil_files``), each rule's weights summing to 1
                   (``stencil_affinity``), today's schemes as stencils (``stencil_convert``), what the
                   literature says of each family, sources, eigenvalues, smoothness (``zoo_literature``), the zoo's
                   engine: halfedge local meshes (``halfedge``), the neighbourhood of an extraordinary vertex or face
                   with the orbit labelling of its points (``neighbourhood``), a stencil rule read as an exact row on a
                   mesh (``stencil_rows``), one step per topology, primal, dual and sqrt(3) (``topology``), local
                   quad and triangle meshes and ring meshes (``mesh``), whole meshes refined by
                   the rules (Section 3, ``refinement``), K-ring matrices by exact refinement
                   (``rings``), the 1-ring and its 2n-gon (Eq. 10-13, ``ring``), the rules at
                   boundaries, creases and corners and OpenSubdiv's sharpness arithmetic (``sharp``),
                   refinement of meshes with tagged sharp edges and vertices (``tagged_refinement``),
                   a boundary, crease, corner or dart vertex and its exact subdivision matrix
                   (``sector``), the regular patches next to a sharp ray with phantom points
                   (``sector_patch``), schemes from TOML
                   files and by name (``files``), Loop's scheme (``loop``), Stam's patch
                   matrices, (2N+8)-point and Loop's (N+6)-point (``patch``), the regular Loop
                   patch (quartic box spline) in Bezier form (``box_spline``), a dual quad scheme's regular
                   patch derived from its corner rule as a piecewise quadratic on the four-direction mesh
                   (Midedge: the Zwart-Powell box spline, ``four_direction``), a modeller's polygon
                   mesh validated with its 1-rings and extraordinary vertices (``meshfile``), the
                   checks of its faces in linear time, strict or lenient (``mesh_topology``), read
                   and written as OBJ, OFF and PLY (``meshformats``; OBJ with OpenSubdiv's tags,
                   ``mesh_obj``; PLY, ``mesh_ply``), its sharpness tags and the elements left out
                   of it (``mesh_tags``); one exact Catmull-Clark step on a mesh
                   of any polygons (``polygon_step``; with OpenSubdiv's tags, ``polygon_sharp``),
                   whole meshes refined exactly with their tags (``mesh_refine``)
``analysis/``      per-frequency matrices M_j, the recursion matrix of Eq. 43 and, for any scheme and K-ring,
                   the block form and E_k (``frequency``),
                   spectra (Eq. 34, of any scheme and K-ring from its factored blocks, and of boundary, crease, corner and dart
                   vertices named by their mirror's blocks, ``spectrum``; the roots of the
                   blocks' factors, their clusters and Jordan blocks, ``factor_roots``;
                   ``closed_forms``; a distinct eigenvalue with its multiplicity, the
                   one type of every spectrum, ``eigenvalue``), the tangent plane (Section
                   5.1, ``tangent``) and the tail bound of Proposition 5.1 (``dominance``),
                   elliptic and hyperbolic properties (Sections 5.2-5.3, ``elliptic``,
                   ``ellipses``, ``hyperbolic``), limit masks (``masks``, of any scheme and K-ring, and at sharp vertices), tuning (``tuning``; the
                   regions of free vertex weights by curvature regime, ``tuning_region``),
                   the characteristic polynomial (Section 6, and its factors and product form for any K-ring, ``charpoly``;
                   ``reduction``; its certified roots with multiplicities, ``polynomial_roots``), Jordan
                   blocks (``defective``), supports (Section 3, ``support``; for every n from one
                   window of sectors, ``support_window``), rings iterated step by step
                   (``evolution``), the 2-ring matrix by frequency and the characteristic map's
                   nets (``characteristic``; exact in t = cos(2 pi/n) for every n,
                   ``characteristic_uniform``), where a 1-ring component starts on one eigenvector of M_j
                   (Eq. 35-38, ``components``); any StencilScheme of the zoo: its matrix on its
                   neighbourhood by refinement and closure (``zoo_matrix``), frequency blocks from the orbit
                   labelling (``zoo_blocks``), factored spectra (``zoo_spectrum``; repeated roots split exactly,
                   ``zoo_roots``; Jordan blocks, ``zoo_jordan``), limit and tangent masks (``zoo_masks``), a face
                   or ring family's symbol for every size (``zoo_symbols``), the blocks for every valence read
                   once (``zoo_structure``), their factors for every n (``zoo_large``) and spectra at large n
                   (``zoo_large_spectrum``);
                   what the curvature regimes at the vertex mean (``curvature_regime``: mu against lambda_1^2); the patch's certified eigen-data
                   (``eigendata``; the 1-ring block's eigenvector columns by frequency on every lattice,
                   ``eigendata_columns``; the trig table and the Fourier patterns they are made of, ``fourier_patterns``;
                   the file's valences rounded straight from those columns,
                   ``eigendata_direct``; the tables' zeros a mirror symmetry makes exact,
                   ``eigendata_zeros``; every entry correctly rounded, those that do not round at the working precision
                   sharpened alone, ``eigendata_sharpen``) and exact evaluation on either lattice (``evaluation``), at an interior and at a
                   boundary or corner vertex (the latter's sub-patch data by exact refinement, ``subpatch_data``; the regular
                   patch's basis on each lattice, ``regular_basis``); the
                   extraordinary vertices of a modeller's mesh, limit frames and 1-ring components
                   (``inspection``); every vertex of a mesh classified by its neighbourhood kind
                   (``mesh_kinds``; a vertex of no kind, its computed outcome: off the surface, the kind it becomes
                   once its semi-sharp tags have decayed, or its fan's spectrum, ``mesh_outcomes``) and its limit
                   position and normal from exact masks per kind applied with numpy (``mesh_limits``; a transient
                   vertex's by exact refinement of its 2-ring, ``mesh_transient``); second-order characteristic maps, the elliptic and hyperbolic
                   height fields on the ring (``second_order``); control nets designed for prescribed
                   limit properties (``design``; its inputs checked against their bounds, ``design_input``),
                   and the least change of a 1-ring for a normal or no hyperbolic part (``redesign``); boundary, crease, corner and dart vertices
                   by the mirror symmetry of their sectors: crease block and sine blocks (``mirror``), the
                   spectrum for every k and the comparison with the boundary curve (``mirror_threshold``);
                   evaluation data at crease, boundary and corner vertices, standard and BLZ rules: the eigen-decomposition over Q and
                   the picking matrices of the spline cells past the modified points (``sector_evaldata``),
                   the patches evaluated from them (``sector_evaluation``); at an extraordinary face of a dual quad
                   scheme whose regular part is the biquadratic B-spline (Doo-Sabin): the matrix, the ring cells' picking
                   matrices and the decomposition over Q (``dual_evaldata``), the sectors evaluated from them
                   (``dual_evaluation``);
                   exact eigenvalues of a block-triangular matrix by its parts, the crease block and the sectors, over Q
                   or, for rules with cos(theta_k) weights, Q(cos(pi/k)) (``triangular_eigen``); the mirror blocks'
                   eigenvalues joined exactly, O(k), the spectrum's structural route at boundary, crease and corner vertices
                   (``block_values``), the leading ones and a bound of the rest in O(log k) (``leading_values``), the blocks that
                   have each exact eigenvalue of the matrix, matched by value (``block_names``); the limit and tangent
                   masks of a block-triangular matrix part by part, exact left eigenvectors (``triangular_masks``); how Jupyter
                   shows a result, delegating to the output layer (``display``)
``verify/``        cross-checks against the full matrices: numeric, at an interior vertex (1-ring or K-ring) or a
                   boundary, crease or corner sector (``numeric``; past the faces solved densely, the refined matrix on
                   every sine polyline, ``sector_numeric``; certified Arb enclosures ``arb_numeric``), certified
                   at an interior vertex (1-ring closed forms or K-ring frequency factors), a boundary, crease, corner
                   or dart vertex (mirror blocks) or the neighbourhood of a StencilScheme of the zoo (``certify``; the
                   closed forms' symmetric functions, ``symmetric_functions``; the distinct values and multiplicities
                   proved, ``multiplicities``; the O(n) route ``structural``, and O(k) at a boundary, crease or corner vertex,
                   ``sector_structural``; beyond n = 19 for the zoo from the
                   structural blocks, ``zoo_structural``), their results and
                   the C1 verdicts (``result``); OpenSubdiv at an interior vertex (Catmull-Clark or Loop by the lattice) or
                   a boundary, crease, corner or dart vertex (``oracle``; what it reports, ``comparisons``; the
                   toolkit's Catmull-Clark numbers, ``predictions``; single steps chained and split by frequency,
                   ``step_chains``; a level's matrices measured against each other, ``matrix_measures``),
                   through the bridge ``opensubdiv``, its build script ``opensubdiv.build`` and
                   Loop side ``opensubdiv.loop``, boundaries, creases and corners
                   ``opensubdiv.sharp``); certified C1 by Reif's test (``c1``,
                   ``c1_spectrum``, Bernstein-Bezier nets ``bezier``; for every valence, its spectral conditions proved
                   in n and the map per valence, ``c1_every_n``; a dual scheme's with the biquadratic regular part, from its n-gon's
                   weights' symbol, ``c1_dual_every_n``, its ring of biquadratic patches for every n >= N0 by exact signs in t,
                   ``c1_dual_uniform``; a primal one's (the modified butterfly) from its structural blocks, the
                   Schur-Cohn test in t = cos(2 pi k/n), with the map per valence by Zorin's test,
                   ``c1_zorin_every_n``, each Schur-Cohn polynomial's sign for every valence or the valence that
                   shows it fails, ``every_n_signs``; where lambda_1 depends on n (sqrt(3)), lambda_1 = lambda(t) rational in
                   t = cos(2 pi/n) and every other frequency's roots below it by exact signs, ``zorin_lambda_in_t``;
                   where it is a constant algebraic number (the largest root of a factor of p_1 with rational
                   coefficients), the Schur-Cohn steps in Q(lambda_1) by its minimal polynomial, norms and an
                   isolating ball, ``zorin_lambda_algebraic``;
                   the frequency-1 eigenvector on the neighbourhood Zorin's test reads, in closed form for every n
                   (Laurent polynomials in omega, stretched nets in t), ``zorin_eigenvector_every_n``; its stretched
                   net in the limit n -> oo, refined, and that limit map's Jacobian certified, ``zorin_limit_net``;
                   the characteristic map for every n >= N0 by exact signs in t = cos(2 pi/n), ``c1_uniform``; the curvature regime for every
                   valence, ``regime_every_n``, its hyperbolic cause on quads, ``regime_cause``; the part that dominates on fine
                   rings for every valence, ``dominance_every_n``); at a sector between sharp rays (boundary, crease
                   and corner vertices) by Zorin's conditions, at a dart's closed fan cut by one sharp ray by Reif's,
                   each route named by the symmetry it reads: the sector's exact matrix, its mirror's parts read
                   through characteristic polynomials (``c1_sector_matrix``), the mirror blocks with many faces
                   (``c1_mirror_blocks``), the closed fan (``c1_closed_fan``); what they share: the sector matrix's
                   certified spectrum and eigenvectors by the mirror's parts and the part of each eigenvector the
                   blocks name (``mirror_parts``), the boundary curves' tangents in the tangent plane
                   (``boundary_tangent``), the ring of the characteristic map (its nets, at O or past BLZ's modified
                   edges, its Jacobian and arcs, ``sector_ring``), its injectivity, open or closed, and what a sector
                   test found (``sector_injectivity``); BLZ's subdominant eigenvectors as Fourier modes for every k
                   (``fourier_modes``) and the map from them on a few faces per k (``fourier_map``); the
                   eigenvalue 1/2 at BLZ's corners, a triple root with a Jordan block (``corner_jordan``; its chain
                   from the 1-ring block and rational lifts for any k, ``corner_jordan_blocks``), and C1 there
                   from the map of the chain's eigenvector and the other one (``c1_corner_jordan``); for
                   the zoo's schemes, Reif's test on a dual neighbourhood whose regular
                   part is the biquadratic B-spline (``c1_dual``) or a piecewise quadratic on the four-direction
                   mesh (Midedge, ``c1_four_direction``; where the matrix fails Reif's conditions, the spectrum on
                   the functions that patch makes, its translates being dependent, ``c1_four_direction_quotient``; where
                   its subdominant eigenvalue has one pair of Jordan chains, C1 from the map of the chains'
                   eigenvectors, ``c1_four_direction_jordan``)
                   and the route read from the scheme's model, or
                   undecided with the reason (``c1_zoo``; the engine's mesh, spectral conditions and characteristic
                   map at one valence, ``zoo_characteristic``), Zorin's test where no spline patch exists (a vertex
                   of the triangle lattice, over the steps that refine it by 1/a: the modified butterfly, a = 2;
                   sqrt(3), two steps, a = 3: ``c1_zorin``; the regular rules' difference bounds,
                   ``zorin_bounds``; the characteristic net grown and refined by them, ``zorin_net``); dyadic limit positions for
                   the patch evaluator at an interior vertex or a boundary or corner sector and for the crease,
                   boundary and corner data (``patch_eval``), a dual scheme's face data (``dual_evaldata``); the tuning region with Reif's
                   weight-independent conditions certified (``tuning_c1``); the certified
                   second-order eigenstructure and curvature regime (``second_order_spectrum``) and
                   the artifact indicators (``artifacts``; a StencilScheme of the zoo's density and curvature regime from its
                   engine's spectrum, ``zoo_artifacts``); certified shape at the vertex: the sign
                   of the Gaussian curvature of a central surface (``curvature``), elliptic,
                   hyperbolic or hybrid, and the shape chart (``shape``); a mesh's
                   kinds' C1 verdicts and curvature regimes (``mesh_verdicts``) and its limits against
                   OpenSubdiv's (``oracle_mesh``)
``claims/``        the paper's claims, one module per section (``s2_background``,
                   ``s2_circulants``, ``s3_support``, ``s4_one_ring``, ``s4_components``,
                   ``s5_1_staged``, ``s5_1_tangent``, ``s5_1_tangent_c1``, ``s5_2_ellipses``, ``s5_2_elliptic``,
                   ``s5_3_hyperbolic``,
                   ``s6_cb_matrices``, ``s6_cb_perturbation``, ``s6_cb_subdivision``, ``s6_closing``,
                   ``s6_full_spectrum``), the toolkit's own claims beyond the paper (curvature and
                   shape, ``b1_curvature``; boundary and crease vertices, ``b2_mirror``) and their registry
                   (``registry``; their order, from the sources, ``order``; the findings' prose with mathematics, ``text``;
                   the derivations' displayed steps, ``steps``); every claim is checked
                   for a scheme, within a time budget, and no verdict rests on a free parameter or an
                   undefined value (``guards``),
                   many claims at once on the shared pool (``batch``); what several checks share: the requirements a claim declares
                   (``applicability``), computed evidence (``evidence``), comparisons valence by valence for rules in n
                   (``per_valence``), the paper's notation
                   (``notation``), example CB-matrices (``cb_examples``); which claims apply to a scheme of
                   the zoo, and why the others do not (``zoo_claims``)
``output/``        LaTeX (``latex``, one entry point aslatex; formulas that fit the page,
                   ``texlayout``), results in a notebook: short HTML tables and LaTeX (``display``),
                   the artifact table's columns (``artifact_table``), the zoo's families derived
                   by the engine, the file zoo.tex (``zoo_derivations``), C1 and the curvature regime
                   for every valence as propositions, the file c1-every-n.tex (``every_n_derivations``;
                   Doo-Sabin's, an n-sided face, ``dual_every_n_derivations``),
                   the report of a zoo scheme (``report_zoo``), Stam's data file (``evaldata``), the
                   crease, boundary and corner data file (``sector_evaldata``), the data file of a dual scheme's faces
                   (``dual_evaldata``), meshes
                   with per-vertex colours as PLY and OBJ (``colored_mesh``), figures (``plotting``):
                   Sections 2 and 4 (``plotting.polygons``), 5.1 (``plotting.tangent``), 5.2-5.3
                   (``plotting.elliptic``), 6 (``plotting.cbmatrix``), a mesh's extraordinary
                   vertices (``plotting.meshes``), Reif's test
                   (``plotting.characteristic``), the tuning region (``plotting.tuning``), boundary, crease and
                   corner vertices: the mirror decomposition's polylines, a sector's characteristic map, the
                   subdominant eigenvalues over k (``plotting.boundary``),
                   Stam's evaluation (``plotting.evaldata``), the second-order height fields and the
                   shape chart (``plotting.shape``), the figures the commands draw with --plot: the characteristic
                   map and its certified bounds (``plotting.c1_figures``; a zoo scheme's map, its spline patches or
                   its control net refined by its rules, ``plotting.zoo_maps``), eigenvalues by frequency or block
                   (``plotting.spectrum_chart``), the curvature regime over n (``plotting.regime_chart``), C1 for every
                   valence, the proof's lambda_1(n) beside the certified valences (``plotting.every_n_chart``), the
                   cross-check's agreement by valence (``plotting.check_chart``), the limit masks' weights on the
                   neighbourhood (``plotting.mask_weights``), the characteristic polynomial's roots
                   (``plotting.charpoly_roots``), a refined mesh over its control mesh (``plotting.refine_figure``),
                   a designed net with its limit point, normal and tangents (``plotting.design_figure``), the
                   oracle's disagreements level by level against the predicted rates (``plotting.oracle_chart``), the
                   eigenvalues of written evaluation data, one line per rank (``plotting.evaldata_chart``),
                   matplotlib loaded only when a figure is drawn (``plotting._mpl``); everything about
                   one scheme in one document (``report``: its sections; C1 and the regime for every valence,
                   ``report_every_n``; as LaTeX and PDF,
                   ``report_tex``; as one HTML file, ``report_html``)
``cli/``           the symdecomp command, one module per subcommand (``claims_cmd``,
                   ``derive_cmd``, ``spectrum_cmd``, ``charpoly_cmd``, ``oracle_cmd``,
                   ``tune_cmd``, ``masks_cmd``, ``check_cmd``, ``c1_cmd``, ``artifacts_cmd``,
                   ``evaldata_cmd`` (the files of a sector's and a dual scheme's faces' data, ``evaldata_formats``; the
                   eigenvalues --plot draws, gathered as they are written, ``evaldata_plot``),
                   ``inspect_cmd`` (its outputs ``inspect_outputs``, its per-vertex table ``inspect_vertices``), ``refine_cmd``,
                   ``design_cmd``, ``report_cmd``; check's rows against the mirror decomposition, ``check_mirror``),
                   the extraordinary element the user named, read and validated once, its kinds and each command's
                   table from kind to route (``element``), shared argument types and output (``common``), output files
                   written whole (``files``),
                   the one shape of every command's JSON output and its JSON Schema
                   (``json_envelope``), the one progress display of long commands (``progress``), the
                   option --plot FILE of the commands that draw (``plot_file``)
``__main__``       python -m symdecomp: the command line
=================  ===========================================================================

The names below are the public API (re-exported from the modules above).

Importing the package is cheap: the public names are imported from their modules on first use
(PEP 562 ``__getattr__``), so ``import symdecomp`` and the command line's ``--help`` and
``--version`` load none of the analysis, verify or claims layers. ``from symdecomp import X`` and
``symdecomp.X`` work for every name in ``__all__``.
"""

from __future__ import annotations

import importlib

from symdecomp import errors
from symdecomp.errors import *  # noqa: F403 - every error type is public (a small module: imported at once)

#: The package's version, its one source (``pyproject.toml`` reads it; ``symdecomp --version`` prints it).
__version__ = "0.1.0"

#: Each module and the public names it provides, imported on first use.
_EXPORTS: dict[str, tuple[str, ...]] = {
    "symdecomp.algebra.cbmatrix": ("CBMatrix", "cb_matrix", "cb_matrix_from", "block_eigenvalue_matrix", "lifted_vector",
        "BlockDiagonalization", "block_diagonalization", "cb_eigensystem", "constant_blocks", "perturbed_block_eigenvalue_matrix",
        "SymbolicCirculant", "SymbolicCBMatrix"),
    "symdecomp.algebra.circulant": ("circ", "circ_from_offsets", "circulant_eigenvalue", "fourier_matrix", "generating_polynomial", "root_of_unity"),
    "symdecomp.analysis.charpoly": ("ClosedFormCharpoly", "closed_form_characteristic_polynomial"),
    "symdecomp.analysis.closed_forms": ("ClosedForms", "derived_closed_forms"),
    "symdecomp.analysis.curvature_regime": ("CurvatureRegime", "curvature_regime", "frequency_kind"),
    "symdecomp.analysis.defective": ("jordan_block_size", "jordan_vertex_weights"),
    "symdecomp.analysis.design": ("LimitFrame", "RingDesign", "design_ring", "limit_frame"),
    "symdecomp.analysis.eigendata": ("certified_eigendata",),
    "symdecomp.analysis.eigenvalue": ("ClosedFormLabel", "Eigenvalue", "MirrorBlock"),
    "symdecomp.analysis.ellipses": ("ellipse_axes",),
    "symdecomp.analysis.elliptic": ("elliptic_defect_table", "nice_elliptic_conditions"),
    "symdecomp.analysis.evaluation": ("PatchEvaluator",),
    "symdecomp.analysis.frequency": ("circulant_blocks", "per_frequency_matrix", "per_frequency_matrix_at", "recursion_matrix",
        "RingBlocks", "ring_blocks"),
    "symdecomp.analysis.hyperbolic": ("hyperbolic_equality", "hyperbolic_ring", "iterate_hyperbolic_ring"),
    "symdecomp.analysis.inspection": ("MeshInspection", "VertexInspection", "inspect_mesh", "inspect_vertex"),
    "symdecomp.analysis.masks": ("limit_masks", "limit_masks_at", "ring_masks", "SharpMasks", "sharp_masks"),
    "symdecomp.analysis.mirror": ("SectorDecomposition", "SineBlock", "sector_decomposition", "sector_spectrum"),
    "symdecomp.analysis.redesign": ("redesign_vertex",),
    "symdecomp.analysis.reduction": ("reduce_first_column", "subdivision_block_form"),
    "symdecomp.analysis.triangular_masks": ("SharpMask",),
    "symdecomp.analysis.spectrum": ("Spectrum", "closed_form_spectrum", "recursion_eigenvalues", "RingSpectrum", "ring_spectrum",
        "SharpSpectrum", "sharp_spectrum"),
    "symdecomp.analysis.subpatch_data": ("SharpPatchData", "sharp_patch_data"),
    "symdecomp.analysis.support": ("Region", "classify_support"),
    "symdecomp.analysis.tangent": ("invariant_ratio", "invariant_ratio_at", "invariant_ratio_limit", "tangent_eigenvalues"),
    "symdecomp.analysis.tuning": ("joint_obstruction", "tune"),
    "symdecomp.analysis.zoo_masks": ("zoo_masks",),
    "symdecomp.analysis.zoo_matrix": ("ZooMatrix", "zoo_matrix"),
    "symdecomp.analysis.zoo_spectrum": ("zoo_spectrum",),
    "symdecomp.claims": ("CheckResult", "Claim", "Status", "Step", "all_claims", "check_claim", "get_claim"),
    "symdecomp.output.display": ("aslatex", "ashtml", "notebook_latex"),
    "symdecomp.schemes.full_matrix": ("characteristic_polynomial", "exact_subdivision_matrix"),
    "symdecomp.schemes.lattice": ("QUAD", "TRIANGLE", "Lattice", "lattice"),
    "symdecomp.schemes.loop": ("loop", "loop_warren", "triangle_scheme"),
    "symdecomp.schemes.mesh": ("QuadMesh", "ring_mesh"),
    "symdecomp.schemes.meshfile": ("PolygonMesh", "scheme_for_mesh"),
    "symdecomp.schemes.meshformats": ("decode_mesh", "encode_mesh", "read_mesh"),
    "symdecomp.schemes.mesh_tags": ("MeshDefects", "MeshTags"),
    "symdecomp.schemes.neighbourhood": ("Neighbourhood", "neighbourhood"),
    "symdecomp.schemes.patch": ("patch_matrices",),
    "symdecomp.schemes.refinement": ("central_rings", "mesh_rules", "refine"),
    "symdecomp.schemes.rings": ("RingMatrix", "ring_subdivision_matrix"),
    "symdecomp.schemes.sector": ("SharpVertex", "exact_sharp_matrix", "sharp_subdivision_matrix"),
    "symdecomp.schemes.sharp": ("SharpOptions", "SharpRules", "standard_sharp_rules"),
    "symdecomp.schemes.scheme": ("Scheme", "Stencil", "VertexRule", "catmull_clark", "subdivision_matrix"),
    "symdecomp.verify.artifacts": ("ArtifactIndicators", "artifact_indicators"),
    "symdecomp.verify.c1": ("C1Result", "c1_test"),
    "symdecomp.verify.c1_sector_matrix": ("SharpC1Result", "c1_sharp_test"),
    "symdecomp.verify.certify": ("Certificate", "certify", "certify_ring", "SharpCertificate", "certify_sharp", "certify_zoo"),
    "symdecomp.verify.numeric": ("NumericCheck", "numeric_check"),
    "symdecomp.verify.result": ("C1Verdict", "CrossCheckResult", "CrossCheckStatus"),
    "symdecomp.verify.second_order_spectrum": ("CurvatureResult", "second_order_eigenstructure"),
    "symdecomp.verify.zoo_artifacts": ("ZooArtifacts", "zoo_artifacts"),
    "symdecomp.verify.shape": ("ShapeChart", "ShapeResult", "classify_shape", "shape_chart"),
}

#: Modules the package root names (``symdecomp.symbols``; ``symdecomp.cbmatrix``, the Section 6 API).
_MODULES = {"symbols": "symdecomp.symbols", "cbmatrix": "symdecomp.algebra.cbmatrix"}

_WHERE = {name: module for module, names in _EXPORTS.items() for name in names}

__all__ = ["symbols", *_WHERE, *errors.__all__]  # noqa: F405 - symbols and the rest are imported on first use


def __getattr__(name: str):
    """A public name's value, imported from its module on first use and kept (PEP 562)."""
    if name in _MODULES:
        value = importlib.import_module(_MODULES[name])
    elif name in _WHERE:
        value = getattr(importlib.import_module(_WHERE[name]), name)
    else:
        raise AttributeError(f"module 'symdecomp' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__, *_MODULES})
