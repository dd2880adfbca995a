#!/usr/bin/env bash
# A TeX engine from Debian, so that tests/output/test_latex.py compiles the derivations
# (a LaTeX error or a formula running past the margin fails the tests).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends texlive-latex-base texlive-latex-recommended latexmk
