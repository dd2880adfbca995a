"""The documentation's mathematics is typeset offline (issue 34): a tiny site of two pages, built with the
site's math configuration (``docs/_ext/offline_math.py``), opened in headless Chromium with no network,
shows typeset formulas and no raw LaTeX delimiters.

The full site uses the same extension (``docs/conf.py``); building it takes minutes, so this test builds
two pages (one Markdown with dollar math, one reStructuredText with roles and a display block) instead.
CI installs Chromium (``.ci/steps/40-chromium.sh``); where it is missing the test is skipped, except in CI.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = next(p for p in Path(__file__).resolve().parents if (p / "pyproject.toml").exists())
EXT = ROOT / "docs" / "_ext"

CONF = f"""
import sys
sys.path.insert(0, {str(EXT)!r})
extensions = ["myst_parser", "offline_math"]
myst_enable_extensions = ["dollarmath", "amsmath"]
html_theme = "furo"
"""
MARKDOWN = """# Markdown

The 1-ring is a $2n$-gon, and $A^j$ is its $j$-th component.

$$
\\lambda_1 = \\frac{1}{4}\\left(1 + \\cos\\frac{2\\pi}{n}\\right)
$$

```{toctree}
rst
```
"""
RST = """Restructured
============

The subdominant eigenvalue :math:`\\lambda_1^2` and the matrix :math:`M_j`.

.. math::

   \\det(M_j - \\lambda I) = 0
"""
#: What Chromium is started with: no network, no first-run work, a fresh profile (given per run).
CHROMIUM_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                  "--disable-sync", "--no-first-run", "--virtual-time-budget=20000")


def _chromium() -> str:
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is missing in CI: .ci/steps/40-chromium.sh installs it")
        pytest.skip("needs Chromium (apt-get install chromium)")
    return found


def _build(tmp_path: Path) -> Path:
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    pytest.importorskip("furo")
    source, out = tmp_path / "src", tmp_path / "html"
    source.mkdir()
    (source / "conf.py").write_text(CONF)
    (source / "index.md").write_text(MARKDOWN)
    (source / "rst.rst").write_text(RST)
    built = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", str(source), str(out)],
                           capture_output=True, text=True, timeout=300)
    assert built.returncode == 0, built.stderr[-3000:]
    return out


def _dom(browser: str, page: Path, profile: Path) -> str:
    run = subprocess.run([browser, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--dump-dom", page.as_uri()],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
    return run.stdout


def _visible_text(dom: str) -> str:
    """The page's text without scripts and styles (where a delimiter in code would not be raw math)."""
    dom = re.sub(r"<(script|style)\b.*?</\1>", "", dom, flags=re.S)
    return re.sub(r"<[^>]+>", "", dom)


def test_the_pages_load_mathjax_from_the_site_itself(tmp_path):
    out = _build(tmp_path)
    for name in ("index.html", "rst.html"):
        html = (out / name).read_text()
        scripts = re.findall(r'<script[^>]*src="([^"]+)"', html)
        assert any(s.endswith("_static/mathjax/tex-chtml.js") for s in scripts), scripts
        assert not [s for s in scripts if re.match(r"(https?:)?//", s)], "a script from the network"
    assert (out / "_static" / "mathjax" / "tex-chtml.js").is_file()
    assert list((out / "_static" / "mathjax" / "output" / "chtml" / "fonts").rglob("*.woff"))


def test_a_built_page_shows_typeset_math_offline(tmp_path):
    browser = _chromium()
    out = _build(tmp_path)
    for name in ("index.html", "rst.html"):
        html = (out / name).read_text()
        formulas = html.count('class="math notranslate nohighlight"')
        assert formulas >= 3 and "\\(" in html  # the built page holds the LaTeX that MathJax must typeset ...
        dom = _dom(browser, out / name, tmp_path / f"profile-{name}")
        typeset = re.findall(r'<mjx-container class="MathJax[^"]*" jax="CHTML"', dom)
        assert len(typeset) == formulas, dom[-2000:]  # ... and every formula is typeset in the browser
        text = _visible_text(dom)
        assert "\\(" not in text and "\\[" not in text and "$$" not in text
