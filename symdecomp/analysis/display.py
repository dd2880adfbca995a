"""How Jupyter shows a result: a short table (``_repr_html_``) or LaTeX (``_repr_latex_``).

The results users meet first (a spectrum, the masks at a valence, a C1 test, the artifact
indicators, a claim's check, a mesh inspection) inherit :class:`NotebookDisplay`. Its methods only
delegate to the package's entry points, :func:`symdecomp.ashtml` and :func:`symdecomp.notebook_latex`
(whose LaTeX comes from :func:`symdecomp.aslatex`), which live with the rest of the output in
:mod:`symdecomp.output.display`; a result knows nothing of how it is drawn.
"""

from __future__ import annotations

__all__ = ["NotebookDisplay"]


class NotebookDisplay:
    """Jupyter's display hooks for a result (module docstring); no state, no fields."""

    __slots__ = ()

    def _repr_html_(self) -> str:
        import symdecomp

        return symdecomp.ashtml(self)

    def _repr_latex_(self) -> str:
        import symdecomp

        return symdecomp.notebook_latex(self)
