"""Sphinx configuration of the symdecomp documentation (``python -m sphinx -W -b html docs docs/_build/html``).

The command reference, the API reference, the module map and the tables of limits and exit codes
are generated from the code by ``_ext/symdecomp_docs.py``; the guide's pictures are drawn by the
commands themselves (``_ext/guide_figures.py``); the math is typeset by a MathJax copied into the site,
so it reads offline (``_ext/offline_math.py``); the notebooks are executed during the build (see
``nb_execution_mode`` below).
"""

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "_ext"))
sys.path.insert(0, str(ROOT))  # this checkout's symdecomp, also for the notebooks' kernels (below)
os.environ["PYTHONPATH"] = os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
os.environ["MPLBACKEND"] = "Agg"

from symdecomp import __version__  # noqa: E402 - after the path is set

project = "symdecomp"
author = "the symdecomp authors"
copyright = "the symdecomp authors"  # no year: the pages are the same whenever they are built
release = version = __version__

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "offline_math",  # MathJax from the site itself, not a CDN: the math reads offline (_ext/offline_math.py)
    "symdecomp_docs",
    "guide_figures",  # the guide pages' pictures, drawn by the commands during the build (_ext/guide_figures.py)
]
exclude_patterns = ["_build", "_ext", "_generated", "**.ipynb_checkpoints"]
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3

# The API reference documents what each module defines (not what it re-exports, which has its own
# home), in the order of the source.
autodoc_default_options = {"members": True, "ignore-module-all": True, "member-order": "bysource"}
autodoc_typehints = "description"

# The committed notebooks carry no outputs (tests/project/test_notebooks.py), so the site runs them: the
# figures are those of the current code. Together they take about a minute and a half on two shared
# cores; the cache (under _build) reruns only the notebooks that changed.
nb_execution_mode = "cache"
nb_execution_cache_path = str(ROOT / "docs" / "_build" / ".jupyter_cache")
nb_execution_timeout = 600
nb_execution_raise_on_error = True
nb_execution_show_tb = True

html_theme = "furo"
html_title = f"symdecomp {release}"
html_last_updated_fmt = None
