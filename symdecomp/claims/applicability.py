"""What the claims' derivations need of a scheme: the requirements a claim declares (``requires=``).

Each is a :class:`~symdecomp.claims.registry.Requirement`; the registry tests a claim's requirements
before its check runs and reports ``not applicable``, with the reason, for a scheme that does not
meet one (instead of failing inside sympy, or repeating the same guard in every check).

* :data:`MIRROR_SYMMETRIC`: mirror-symmetric rules (the weight on ``a_{i+k}`` equal to that on ``a_{i-k}`` and so
  on), on either lattice: the reflection ``i -> -i`` of the 1-ring is ``j -> n - j`` on the frequencies, ``omega ->
  1/omega`` in the frequency block ``M(omega)`` (:func:`~symdecomp.analysis.frequency.one_ring_matrices`), ``s -> -s``
  in ``c = cos(j pi/n)``, ``s = sin(j pi/n)``. Two kinds of check need it, and it is one requirement for both:
  Section 5's closed forms in ``c`` alone (``M_j``'s trace and determinant free of ``s``), and the checks that compare
  ``lambda_1`` with real numbers (``lambda_1^2`` in the curvature regimes: the frequencies ``j`` and ``n - j`` must
  carry the same eigenvalues, ``M(omega)``'s characteristic polynomial real). Both are the same computation: the
  trace and the determinant of ``M(omega)`` written in ``c`` and ``s`` (:func:`~symdecomp.analysis.frequency.laurent_to_cos`)
  have no odd part in ``s``, which is their invariance under ``omega -> 1/omega``; the reason names the term that
  has one.
* :data:`COSINE_ONLY`: some checks order the eigenvalues of ``M_j`` or evaluate them in intervals from
  their closed forms in ``c`` alone, which needs edge and face rules that do not depend on the valence
  ``n`` (otherwise ``n`` enters ``M_j`` beside ``c``); the reason names the term.
* :data:`REAL_TANGENT_SPECTRUM`: checks that order the two eigenvalues of ``M_j`` (the dominant one, the
  other one) need them real at every frequency: the discriminant of ``M_j`` nonnegative for every ``c`` in
  ``[-1, 1]`` (exactly: no root of odd multiplicity inside, and positive somewhere).
* :data:`FACE_NEIGHBOURS`: statements about the ``(2n+1)``-point 1-ring of a quad mesh (the matrix of
  Eq. 43, ``M_j`` of order 2) need a face rule.
* :data:`NO_FREE_PARAMETERS`: checks that compute with the scheme's numbers (exact matrices at a
  valence, certified balls) need every weight to be a number at each valence.
* :data:`WHOLE_MESH`: the supports of Section 3 live on whole quad meshes, so the 1-ring rules must
  be rules of the mesh (:func:`symdecomp.schemes.mesh.mesh_rules`).

The claims' checks compute with the 1-ring of a vertex refined by a primal step: the paper's with the
``(2n+1)``-point 1-ring of a quad mesh, others (Loop's) with the ``(n+1)``-point 1-ring of a triangle mesh, and the
sector claims (B.2, whose parameter is ``k``) with the 1-ring of a sector of ``k`` faces between two sharp edges. A
scheme of the zoo (:class:`~symdecomp.schemes.stencils.StencilScheme`) is tested against that model, from its
data: first its lattice against the claim's (:attr:`~symdecomp.claims.registry.Claim.lattices`), then by
:data:`ZOO_REQUIREMENTS` (a 1-ring primal :class:`Scheme` meets each of them); each reason says what the scheme
has, and :func:`one_ring_needed` what the claim needs:

* :data:`PRIMAL_VERTEX`: the step is primal and the extraordinary element is a vertex (for the sector claims,
  :data:`PRIMAL_SECTOR`: the step is primal, so that it keeps the sector's vertex);
* :data:`ONE_RING_SUPPORT`: every rule's walks cross at most one edge from the anchor's faces.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.valence_signs import sign_on_interval
from symdecomp.analysis.frequency import laurent_to_cos, one_ring_matrices
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.claims.registry import Requirement, Text, Verbatim
from symdecomp.errors import InvalidSchemeError
from symdecomp.expressions import identically_zero
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.refinement import mesh_rules
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.schemes.topology import topology_of
from symdecomp.symbols import cos_jtheta as C
from symdecomp.symbols import n as N
from symdecomp.symbols import sin_jtheta as SIN

__all__ = ["MIRROR_SYMMETRIC", "COSINE_ONLY", "REAL_TANGENT_SPECTRUM", "FACE_NEIGHBOURS", "NO_FREE_PARAMETERS", "WHOLE_MESH", "closed_form_obstacle",
           "PRIMAL_VERTEX", "PRIMAL_SECTOR", "ONE_RING_SUPPORT", "ZOO_REQUIREMENTS", "one_ring_needed"]


def _block_term(scheme: Scheme, symbol) -> tuple[str, sp.Expr] | None:
    """``(name, expr)``: the trace or determinant of ``M_j`` when it holds ``symbol``, else ``None``."""
    ev = tangent_eigenvalues(scheme)
    return next(((name, e) for name, e in (("trace", ev.trace), ("determinant", ev.determinant)) if e.has(symbol)), None)


def _mirror_asymmetry(scheme: Scheme) -> Text | None:
    """The trace or determinant of the frequency block ``M_j``, in ``c`` and ``s``, when it has a part odd in
    ``s = sin(j pi/n)`` (not the same at ``omega`` and ``1/omega``), else ``None``; either lattice."""
    M, _ = one_ring_matrices(scheme)
    for name, term in (("trace", M.trace()), ("determinant", M.det())):
        in_c = laurent_to_cos(sp.expand(term))
        if not identically_zero(sp.Poly(in_c, SIN).coeff_monomial(SIN)):
            return Text("the rules are not mirror symmetric: for the scheme ", Verbatim(repr(scheme.name)), " the ", name,
                        " of the frequency block M_j is ", in_c, " (s = sin(j pi/n)), not the same at the frequencies j and "
                        "n - j: Section 5's closed forms need M_j in c = cos(j pi/n) alone, and a comparison of lambda_1 "
                        "with real numbers needs M_j and M_(n-j) to have the same eigenvalues (they are conjugate: the "
                        "characteristic map rotates)")
    return None


def _valence_in_blocks(scheme: Scheme) -> Text | None:
    """The trace or determinant of ``M_j`` when it depends on ``n`` besides ``c``, else ``None``."""
    if (term := _block_term(scheme, N)) is None:
        return None
    return Text("the check evaluates the eigenvalues of M_j from closed forms in c = cos(j pi/n) alone, and this "
                "scheme's edge or face rule depends on the valence: the ", term[0], " of M_j is ", term[1])


def _complex_tangent_spectrum(scheme: Scheme) -> Text | None:
    """The discriminant of ``M_j`` when it is negative somewhere in ``c`` in ``[-1, 1]`` (complex eigenvalues), else ``None``.

    Not a polynomial in ``c`` alone: :data:`MIRROR_SYMMETRIC` or :data:`COSINE_ONLY` says why."""
    d = tangent_eigenvalues(scheme).discriminant
    if d.has(N):  # an edge rule in n: the claims that allow it compare the eigenvalues valence by valence, by modulus
        return None
    if sign_on_interval(d, C, -1, 1, strict=False) is not False:
        return None
    return Text("the check orders the two eigenvalues of M_j, and for this scheme they are complex at some frequencies: the "
                "discriminant of M_j is ", d, ", negative for some c = cos(j pi/n) in [-1, 1]")


def _no_face_rule(scheme: Scheme) -> str | None:
    """Why a scheme without face neighbours is outside a statement about the quad 1-ring, or ``None``."""
    if scheme.face_rule is None:
        return Text("the statement is about the (2n+1)-point 1-ring of a quad mesh, and the scheme ", Verbatim(repr(scheme.name)),
                    " has no face neighbours b_i (a triangle mesh)")
    return None


def _free_parameters(scheme: Scheme) -> str | None:
    """The scheme's free parameters, when it has any."""
    if scheme.parameters:
        return Text("the scheme ", Verbatim(repr(scheme.name)), f" has free parameters {', '.join(map(str, scheme.parameters))}; "
                    "give them values first")
    return None


def _not_mesh_rules(scheme: Scheme) -> str | None:
    """Why the scheme's 1-ring rules are not rules of a whole quad mesh, or ``None`` when they are."""
    try:
        mesh_rules(scheme)
    except InvalidSchemeError as exc:
        return Text("the supports of Section 3 live on whole meshes, and ", Verbatim(exc))
    return None


#: Mirror-symmetric rules: ``M_j`` depends on ``c = cos(j pi/n)`` alone (Section 5's closed forms; a real ``lambda_1``).
MIRROR_SYMMETRIC = Requirement("mirror-symmetric rules", _mirror_asymmetry)
#: Edge and face rules free of ``n``: ``M_j`` depends on ``c`` alone (checks that order or bound its eigenvalues).
COSINE_ONLY = Requirement("edge and face rules that do not depend on n", _valence_in_blocks)
#: Real eigenvalues of ``M_j`` at every frequency (checks that order them).
REAL_TANGENT_SPECTRUM = Requirement("real eigenvalues of M_j", _complex_tangent_spectrum)
#: A face rule: the quad 1-ring ``(O, a_i, b_i)`` of the paper.
FACE_NEIGHBOURS = Requirement("a quad mesh (face neighbours b_i)", _no_face_rule)
#: No free parameters: every weight is a number at each valence.
NO_FREE_PARAMETERS = Requirement("no free parameters", _free_parameters)
#: Rules of a whole quad mesh (Section 3's supports).
WHOLE_MESH = Requirement("rules of a whole quad mesh", _not_mesh_rules)


def one_ring_needed(lattices: tuple, scheme: Scheme | StencilScheme, parameter: str = "n") -> Text:
    """What a claim on ``lattices`` needs, in words computed from the lattices, naming the lattice ``scheme`` subdivides
    when it is not one of them. ``parameter`` is the claim's (:attr:`~symdecomp.claims.registry.Claim.parameter`):
    ``"n"``, the 1-ring of a vertex of valence ``n`` (``2n+1`` points on quads, ``n+1`` on triangles, from each
    lattice's kinds of neighbours); ``"k"``, a sector of ``k`` faces between two sharp edges (``2k+2`` points on quads,
    ``k+2`` on triangles, from the sector's own 1-ring, :class:`~symdecomp.schemes.sector.SharpVertex`)."""
    if parameter == "k":
        what = " or of ".join(f"a {x} mesh (its ({_sector_points(x)})-point 1-ring)" for x in lattices)
        needed = f"a sector of k faces between two sharp edges of {what},"
    else:
        needed = " or ".join(f"the ({_ring_points(x)})-point 1-ring of a vertex of a {x} mesh" for x in lattices)
    own = lattice(scheme.lattice)
    other = () if own in lattices else (", and ", Verbatim(repr(scheme.name)), f" subdivides {own} meshes")
    return Text("the claim is about ", needed, " refined by a primal step", *other)


def _ring_points(x) -> str:
    """``2n+1``, ``n+1``: the centre and one point per kind of 1-ring neighbour per sector."""
    kinds = len(x.one_ring_classes)
    return f"{kinds if kinds > 1 else ''}n+1"


def _sector_points(x) -> str:
    """``2k+2``, ``k+2``: the points of the 1-ring of a boundary sector of ``k`` faces on lattice ``x``, read from the
    sector's model at ``k = 1, 2`` (its size is affine in ``k``: one more edge neighbour, and face neighbour, per face)."""
    from symdecomp.schemes.sector import SharpVertex

    one, two = (len(SharpVertex.boundary(k, x).vertex_order()) for k in (1, 2))
    slope = two - one
    return f"{slope if slope > 1 else ''}k+{one - slope}"


def _not_primal_vertex(scheme: Scheme | StencilScheme) -> Text | None:
    """Why the scheme's extraordinary element is not a vertex of a primal step, or ``None``."""
    if not isinstance(scheme, StencilScheme) or (topology := topology_of(scheme)).name == "primal":
        return None  # a Scheme is the 1-ring primal model itself
    if topology.centre == "face":
        return Text("the extraordinary element is an n-sided face of a dual scheme (", Verbatim(repr(scheme.name)),
                    " makes a new point per face corner)")
    return _not_primal_step(scheme)


def _not_primal_sector(scheme: Scheme | StencilScheme) -> Text | None:
    """Why a sector of the scheme between two sharp edges is not the sector model's (a sector of ``k`` faces around a
    vertex that each primal step keeps, :class:`~symdecomp.schemes.sector.SharpVertex`), or ``None``."""
    from symdecomp.schemes.sector import SharpVertex

    if not isinstance(scheme, StencilScheme) or (topology := topology_of(scheme)).name == "primal":
        return None
    if topology.centre == "face":
        centre = SharpVertex.boundary(1, lattice(scheme.lattice)).vertex_order()[0]
        return Text(f"a sector of k faces is centred on its vertex {centre}, which a step of a dual scheme does not keep (",
                    Verbatim(repr(scheme.name)), f" makes a new point per face corner, one in each face at {centre})")
    return _not_primal_step(scheme)


def _not_primal_step(scheme: StencilScheme) -> Text:
    return Text("the scheme ", Verbatim(repr(scheme.name)), f" has the {topology_of(scheme).name.replace('sqrt', '√')} "
                f"topology (analysed over {scheme.steps} steps), not a primal step")


def _walk_beyond_one_ring(scheme: Scheme | StencilScheme) -> Text | None:
    """The first walk of a rule that crosses two or more edges (its stencil leaves the 1-ring), or ``None``."""
    if not isinstance(scheme, StencilScheme):
        return None
    for kind in scheme.kinds:
        for rule in kind.rules:
            for term in rule.terms:
                if term.walk.count("twin") >= 2:
                    return Text(f"the {kind.kind} rule reaches two rings out (its walk ", Verbatim(repr(" ".join(term.walk))),
                                " crosses two edges)")
    return None


#: A primal step, centred on an extraordinary vertex.
PRIMAL_VERTEX = Requirement("a primal step at an extraordinary vertex", _not_primal_vertex)
#: A primal step, at a sector of faces between two sharp edges around a vertex it keeps.
PRIMAL_SECTOR = Requirement("a primal step at a sector of a sharp vertex", _not_primal_sector)
#: Rules whose stencils stay in the 1-ring (walks crossing at most one edge).
ONE_RING_SUPPORT = Requirement("rules on the 1-ring", _walk_beyond_one_ring)
#: What a scheme of the zoo on one of a claim's lattices (:attr:`~symdecomp.claims.registry.Claim.lattices`, tested
#: first) is tested against, in order, by the claim's parameter (:attr:`~symdecomp.claims.registry.Claim.parameter`):
#: ``"n"``, the 1-ring of a vertex; ``"k"``, a sector of ``k`` faces.
ZOO_REQUIREMENTS = {"n": (PRIMAL_VERTEX, ONE_RING_SUPPORT), "k": (PRIMAL_SECTOR, ONE_RING_SUPPORT)}


def closed_form_obstacle(scheme: Scheme) -> str | None:
    """Why the paper's closed forms in ``c = cos(j pi/n)`` (Section 5) do not apply to ``scheme`` (``None`` when they do).

    They need a quad scheme with mirror-symmetric rules, so that ``M_j`` depends on ``c`` alone.
    """
    if not scheme.lattice.paper_claims:
        return f"they are derived for quad meshes, not {scheme.lattice} meshes"
    if MIRROR_SYMMETRIC.unmet(scheme) is not None:
        return "its rules are not mirror-symmetric (M_j depends on sin(j pi/n), not on c = cos(j pi/n) alone)"
    return None
