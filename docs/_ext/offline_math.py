"""Sphinx extension: the site's mathematics typeset in the reader's browser without a network.

Sphinx's ``sphinx.ext.mathjax`` loads MathJax from a CDN, so offline (where the people who read
this site, and the machines that build it, often are) every formula stays raw LaTeX (``\\(2n\\)``).
The PyPI package ``sphinx-mathjax-offline`` ships MathJax 3 (its CommonHTML output and fonts) and
copies it into the site's ``_static/mathjax/``, pointing ``mathjax_path`` there; this extension
loads the two in that order, so that the site and the test that opens a built page in a headless
browser (``tests/project/test_docs_math.py``) use one configuration.

Why MathJax, not math rendered at build time (``sphinx.ext.imgmath``): the formulas stay text
(they scale with the page, can be selected and copied as LaTeX, and are read out by screen
readers), and the build needs no LaTeX-to-image tools.
"""

from __future__ import annotations

#: The extensions, in load order: Sphinx's MathJax support, then the package that vendors MathJax.
EXTENSIONS = ("sphinx.ext.mathjax", "sphinx-mathjax-offline")
#: Where MathJax's entry script lies in the built site (relative to ``_static/``).
MATHJAX_PATH = "mathjax/tex-chtml.js"


def setup(app):
    for name in EXTENSIONS:
        app.setup_extension(name)
    app.config.mathjax_path = MATHJAX_PATH  # the vendored copy, whatever the package's default becomes
    return {"parallel_read_safe": True, "parallel_write_safe": True}
