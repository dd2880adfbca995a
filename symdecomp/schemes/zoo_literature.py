"""What the literature says about the zoo's families: sources, eigenvalues and smoothness, for the tests to reproduce.

Each family of :data:`symdecomp.schemes.stencil_files.ZOO_FILES` has one :class:`FamilyFacts`: the publication its
weights come from, what was read to check them (the source itself is not always at hand: then the secondary text
that restates it is named), the leading eigenvalues of its subdivision matrix at an extraordinary element as exact
expressions in the valence ``n`` (the subdominant one, its multiplicity, and a bound on the rest), and the
smoothness the literature states. Where the eigenvalues are not quoted from a text but follow from the weights by
the discrete Fourier transform (the rules are circulant around the element), :attr:`FamilyFacts.derived` says so
and the docstring of the field gives the derivation; the tests compare all of them with matrices refined
independently on explicit meshes (``tests/schemes/zoo_reference.py``).

A family the issue names whose rules could not be read in full is not shipped: :data:`NOT_SHIPPED` says what was
read, what is missing, why nothing is written under its name (no weight is written that was not read), and which
texts would settle it (looked for, not at hand).

>>> facts = FAMILIES["doo-sabin"]
>>> facts.subdominant.subs(N, 7), facts.multiplicity
(1/2, 2)
>>> sorted(NOT_SHIPPED)
['kobbelt-quad']
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.schemes.stencils import N

__all__ = ["FamilyFacts", "FAMILIES", "NOT_SHIPPED", "UnshippedFamily"]


@dataclass(frozen=True)
class FamilyFacts:
    """The literature's facts on one family of the zoo."""

    #: The family's name (a key of :data:`~symdecomp.schemes.stencil_files.ZOO_FILES`).
    name: str
    #: Where the weights come from (author, year, title), as the shipped file's ``source`` says.
    source: str
    #: What was read to check the weights and the statements below.
    read: str
    #: The subdominant eigenvalue of the analysed step(s) at an element of valence (or size) ``n``, in ``n``.
    subdominant: sp.Expr
    #: Its multiplicity (2: the frequencies 1 and n - 1).
    multiplicity: int
    #: Every other eigenvalue but 1 is at most this in modulus (in ``n``).
    rest_at_most: sp.Expr
    #: The valences at which these hold (3 and up unless said).
    valences: str
    #: Smoothness at the extraordinary element, as the literature states it (with the source).
    smoothness: str
    #: Whether the eigenvalues are derived here from the weights (the derivation in one line) rather than quoted.
    derived: str = ""


_SQRT3_LAMBDA = (2 + 2 * sp.cos(2 * sp.pi / N)) / 9
#: sqrt(3)'s eigenvalue at frequency 2 (at n = 3 frequency 2 is frequency -1, the subdominant one: not the rest).
_SQRT3_SECOND = sp.Piecewise((0, sp.Eq(N, 3)), ((2 + 2 * sp.cos(4 * sp.pi / N)) / 9, True))

FAMILIES: dict[str, FamilyFacts] = {f.name: f for f in (
    FamilyFacts(
        "doo-sabin", "D. Doo and M. Sabin, 1978, Behaviour of recursive division surfaces near extraordinary points",
        "I. Guskov, 2002, Eigenanalysis for Doo-Sabin subdivision (EECS 598 notes): the weights alpha_0 = 1/4 + 5/(4N), "
        "alpha_k = (3 + 2 cos(2 pi k/N))/(4N) and the circulant one-ring matrix S_lk = alpha_(k-l) diagonalized by the "
        "discrete Fourier transform",
        sp.Rational(1, 2), 2, sp.Rational(1, 4), "3 and up (n-gons)",
        "C1 at the centre of an extraordinary face, every n (the issue cites J. Peters and U. Reif, 1998, Analysis of "
        "algorithms generalizing B-spline subdivision; not read here: c1 --every-n proves C1 for every n from the weights: "
        "the spectral conditions by the symbol, the characteristic map by exact signs in cos(2 pi/n) from n = 16)",
        "the Fourier transform of the weights: 1 at frequency 0, 1/4 + 1/4 = 1/2 at frequencies 1 and n - 1, 1/4 at the "
        "others; the regular quads around the n-gon add eigenvalues of at most 1/4"),
    FamilyFacts(
        "midedge", "J. Peters and U. Reif, 1997, The simplest subdivision scheme for smoothing polyhedra",
        "the paper's abstract: a step connects every edge midpoint to its four neighbouring edge midpoints; the surface "
        "is C1 with a piecewise quadratic parametrization except at isolated points; the paper analyses and improves "
        "the construction (the improved weights are not shipped)",
        (1 + sp.cos(2 * sp.pi / N)) / 2, 2, sp.Max(sp.Rational(1, 4), (1 + sp.cos(4 * sp.pi / N)) / 2),
        "4 and up (at 3 the subdominant 1/4 is not simple: the "
        "n-gon's own 1/4 meets the regular part's)",
        "C1 (Peters and Reif 1997, abstract), for the improved construction",
        "two mid-edge steps put 1/2 on a corner and 1/4 on its two neighbours: the Fourier transform gives "
        "1/2 + cos(2 pi k/n)/2 at frequency k; the regular part adds eigenvalues of at most 1/4"),
    FamilyFacts(
        "sqrt3", "L. Kobbelt, 2000, sqrt(3)-subdivision (SIGGRAPH 2000)",
        "the paper's abstract (C2 away from extraordinary points, C1 there) and its rules as restated with the paper's "
        "equation numbers by implementations: centroids (1/3 each), S(p) = (1 - alpha_n) p + alpha_n/n sum p_i with "
        "alpha_n = (4 - 2 cos(2 pi/n))/9 (Eq. 6)",
        _SQRT3_LAMBDA, 2, sp.Max(_SQRT3_LAMBDA**2, _SQRT3_SECOND), "3 and up, over two steps, on the 1-ring",
        "C1 at extraordinary points (Kobbelt 2000, abstract)",
        "over two steps the ring's frequency k block is (1 + omega^k)(1 + omega^-k)/9 = (2 + 2 cos(2 pi k/n))/9; "
        "frequency 0 gives 1 and (2/3 - alpha_n)^2, the square of the subdominant: the choice of alpha_n"),
    FamilyFacts(
        "modified-butterfly",
        "D. Zorin, P. Schroeder and W. Sweldens, 1996, Interpolating subdivision for meshes with arbitrary topology (SIGGRAPH 96)",
        "the weights as an implementation's documentation restates the paper (SubVis, sd_modbutterfly.h): valence 3: "
        "5/12, -1/12, -1/12; valence 4: 3/8, 0, -1/8, 0; valence 5 and up: (1/4 + cos(2 pi j/K) + cos(4 pi j/K)/2)/K; "
        "3/4 on the extraordinary vertex; two extraordinary ends averaged",
        sp.Rational(1, 2), 2, sp.Rational(1, 4), "3 and up",
        "C1 at every valence: D. Zorin, 2000, A method for analysis of C1-continuity of subdivision surfaces (SIAM J. "
        "Numer. Anal. 37(5)); what was read is its abstract, which says the method proves C1 for all valences and is "
        "applied to the butterfly and modified butterfly schemes (the per-scheme verdicts are in the paper's body, not "
        "read here); the toolkit's certificate by that method is per valence (c1 --scheme modified-butterfly)",
        "the Fourier transform of s_j: 1/4 at frequency 0, 1/2 at frequencies 1 and n - 1, 1/4 at 2 and n - 2, 0 at "
        "the others, at n = 3, 4 and 5 and up alike; the 2-ring's outer points add at most 1/4"),
)}


@dataclass(frozen=True)
class UnshippedFamily:
    """A family that is not shipped because its rules could not be read in full, and what was read."""

    #: The name it would have (not a key of :data:`~symdecomp.schemes.stencil_files.ZOO_FILES`).
    name: str
    #: The publication its rules are in (author, year, title).
    source: str
    #: What was read, and what it says.
    read: str
    #: What could not be read, so that the family is not shipped.
    missing: str
    #: The texts that would state the missing rule, looked for and not at hand (named for the next reader, not cited).
    looked_for: tuple[str, ...] = ()
    #: What is missing in one line, for the error a user gets who asks for the family by name.
    summary: str = ""


NOT_SHIPPED: dict[str, UnshippedFamily] = {f.name: f for f in (
    UnshippedFamily(
        "kobbelt-quad",
        "L. Kobbelt, 1996, Interpolatory subdivision on open quadrilateral nets with arbitrary topology "
        "(Computer Graphics Forum 15, Eurographics 96, 409-420)",
        "the paper's abstract (its publisher's page, and the publication page of Kobbelt's group at RWTH Aachen): an "
        "interpolatory scheme for quadrilateral nets of arbitrary topology, C1 in the limit, with boundary curves on "
        "open nets; the opening of Kobbelt's own text under the title A subdivision scheme for smooth interpolation "
        "of quad-mesh data (University of Erlangen; its abstract is the paper's, word for word), up to the first "
        "paragraph of its introduction only: a net N = (V, F) of data points and faces is mapped to a refined net "
        "close to a smooth surface, and the rules come after what was at hand; G. Li, W. Ma and H. Bao, 2005, A new "
        "interpolatory subdivision for quadrilateral meshes (Computer Graphics Forum 24, 3-16), its abstract: its "
        "surfaces coincide with Kobbelt's on regular meshes and it designs a new group of rules for the points "
        "inserted around extraordinary vertices, so its rules there are its own, not Kobbelt's; "
        "and one public implementation (the repository "
        "Instyx/kobbelt_subdivision, which cites no source): edge points by the four-point rule, (8 + w)/16 on the "
        "edge's ends and -w/16 on the next points out, face points by the same rule on the new edge points; at an end "
        "of valence n the point missing behind it on the edge towards its neighbour q_i is a virtual point, "
        "(4/n) sum_j q_j - (q_(i-1) + q_i + q_(i+1)) + w/(4 + w) (r_(i-2) + r_(i-1) + r_i + r_(i+1)) "
        "- 4 w/((4 + w) n) sum_j r_j, with q the neighbours and r the faces' opposite corners (at n = 4 it is "
        "the opposite neighbour); a second implementation (a Blender add-on, Interpolating Subdivision for Quads, "
        "which cites nothing either) has no virtual point, takes any neighbour off the edge's faces at an "
        "extraordinary end, and averages a face point over its two pairs of opposite edge points; a third (the "
        "repository daergoth/SubdivisionSandbox, a geometry mask for CGAL's primal quad refinement, citing nothing) "
        "has the regular rules only: 9/16 and -1/16 on an edge, 81/256, -9/256 and 1/256 on the 16 points around a "
        "face, the four-point rule in each direction (the first implementation's face point at valence 4 is this "
        "stencil: tests/schemes/test_zoo_reference.py), and no rule at an extraordinary vertex; the other public "
        "code under Kobbelt's name read is his sqrt(3) scheme or Li, Ma and Bao's",
        "Kobbelt's own statement of the rule at an extraordinary vertex: his text was at hand only to its "
        "introduction's first paragraph, the one later paper read (Li, Ma and Bao, its abstract) keeps his surfaces "
        "on regular meshes and designs new rules around extraordinary vertices, and the only text read that "
        "gives the virtual point cites nothing; it takes a face point next to an extraordinary vertex along the "
        "first pair of opposite new edge points in the face's storage order, and the other pair "
        "gives another point there (at valences 3, 5, 6 and 7; the same at 4: "
        "tests/schemes/test_zoo_reference.py), so its rules make no matrix that commutes with the rotation; the "
        "two implementations disagree on both rules, which the paper would settle. Nothing is "
        "shipped under the name: writing the weights from that text would attribute to the paper what was not read "
        "in it",
        (
            "the paper's full text, past its introduction's first paragraph",
            "D. Zorin and P. Schroeder, 2000, Subdivision for modeling and animation (SIGGRAPH 2000 course notes), "
            "the chapter on interpolatory schemes",
            "Kobbelt's dissertation and habilitation",
            "Li, Ma and Bao 2005 past its abstract",
            "W. Ma, 2005, Subdivision surfaces for CAD - an overview (Computer-Aided Design 37), past its abstract "
            "and the opening of its introduction, which say nothing of the rule: a survey of schemes that may restate it",
        ),
        "its rule at an extraordinary vertex was not read in a text that states it as Kobbelt's (its regular rules, "
        "the tensor product of the four-point scheme, are; symdecomp.schemes.zoo_literature.NOT_SHIPPED says what was "
        "read)"),
)}
