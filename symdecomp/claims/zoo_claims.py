"""The paper's claims for a scheme of the zoo: which apply, and why the others do not.

The checks of the registry compute with the 1-ring primal model (:class:`~symdecomp.schemes.scheme.Scheme`);
a scheme of the zoo (:class:`~symdecomp.schemes.stencils.StencilScheme`) is tested against that model: first its
lattice against the lattices whose 1-ring the claim is about (:attr:`~symdecomp.claims.registry.Claim.lattices`, from its
``reads_on`` and requirements), the most basic mismatch, then by
:data:`~symdecomp.claims.applicability.ZOO_REQUIREMENTS`, and the first mismatch is the ``not applicable`` reason:
what the scheme has, and what the claim needs. A claim whose
statement is not tied to the 1-ring (C1 at the extraordinary element, the closed forms being the spectrum of the
full matrix) is named with the command of the zoo engine
that answers it for this scheme (:data:`ENGINE_COMMANDS`), since its check is written for 1-ring primal
schemes only. A claim that involves no scheme (:attr:`~symdecomp.claims.registry.Claim.involves_no_scheme`: its check
reads none and it requires nothing, as Section 2's n-gons, Fourier matrix and circulants and Section 6's CB-matrices)
is checked as for any scheme, and says so: the same property decides it on the 1-ring route (a triangle scheme such
as Loop), so the two routes agree on which claims involve no scheme. A claim whose check reads the scheme only on
some lattices (:attr:`~symdecomp.claims.registry.Claim.reads_on`: "Curvature regime: Catmull-Clark" on quad meshes)
reads a scheme of the zoo on another lattice as the 1-ring route reads Loop: through the lattice's reference scheme
(:meth:`~symdecomp.claims.registry.Claim.reads_instead`, the one test of both routes), and has its verdict.
"""

from __future__ import annotations

import dataclasses

from symdecomp.claims.applicability import ZOO_REQUIREMENTS, one_ring_needed
from symdecomp.claims.registry import CheckResult, Claim, Status, Text, Verbatim, check_claim, get_claim
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.stencils import StencilScheme

__all__ = ["ENGINE_COMMANDS", "zoo_claim_result"]

#: The claim modules whose statements hold beyond the 1-ring: what they state, and the command that answers it.
ENGINE_COMMANDS = {
    "symdecomp.claims.s5_1_tangent_c1": ("C1 at the extraordinary element", "c1"),
    "symdecomp.claims.s6_full_spectrum": ("the spectrum of the full subdivision matrix", "check --certify"),
}


def _first_unmet(scheme: StencilScheme, claim: Claim) -> Text | None:
    """Why ``scheme`` is outside the claim's 1-ring model, or ``None`` when it fits: first a lattice that is not the
    claim's (what the claim needs, naming the scheme's lattice: :func:`one_ring_needed`), the most basic reason, which
    no topology or support on that lattice could change; else the first zoo requirement it does not meet, with what the
    claim needs."""
    needed = one_ring_needed(claim.lattices, scheme, claim.parameter)
    if lattice(scheme.lattice) not in claim.lattices:
        return needed
    for requirement in ZOO_REQUIREMENTS[claim.parameter]:  # the zoo's requirements take either model of a scheme (applicability)
        if (reason := requirement.unmet(scheme)) is not None:  # type: ignore[arg-type]
            return Text(reason, "; ", needed)
    return None


def zoo_claim_result(label: str, scheme: StencilScheme, *, budget: float | None = None) -> CheckResult:
    """The result of the claim ``label`` for a zoo scheme: checked when it involves no scheme, else ``not applicable``
    with the reason computed from the scheme."""
    claim = get_claim(label)
    reason: str | Text
    if claim.involves_no_scheme:
        result = check_claim(label, budget=budget)  # the check reads no scheme: its verdict is the same for every one
        return dataclasses.replace(result, evidence=Text("the statement involves no scheme: ", result.evidence))
    if (instead := claim.reads_instead(scheme)) is not None:  # as on the 1-ring route: the scheme it reads is not this one
        result = check_claim(label, instead, budget=budget)
        return dataclasses.replace(result, evidence=Text(
            "the statement is about a scheme on ", " and ".join(f"{x.name} meshes" for x in claim.reads_on), " and ",
            Verbatim(repr(scheme.name)), f" is on {scheme.lattice} meshes, so the check reads ", Verbatim(instead.name),
            f", as for every scheme on {scheme.lattice} meshes: ", result.evidence))
    if claim.module in ENGINE_COMMANDS:
        what, command = ENGINE_COMMANDS[claim.module]
        reason = Text("the question the claim answers (", what, ") applies to the zoo scheme ", Verbatim(repr(scheme.name)),
                      ", but its check is written for 1-ring primal schemes only; the zoo engine's result is in ",
                      Verbatim(f"{command} --scheme {scheme.name} --n N"))
    else:
        unmet = _first_unmet(scheme, claim)
        reason = unmet if unmet is not None else Text(
            "the zoo scheme ", Verbatim(repr(scheme.name)), " meets the 1-ring primal model, but the check computes with "
            "rules given in the 1-ring format (edge, face and vertex weights); give the scheme in that format")
    result = CheckResult(Status.NOT_APPLICABLE, Text(str(reason)))
    return dataclasses.replace(result, parameter=claim.parameter)
