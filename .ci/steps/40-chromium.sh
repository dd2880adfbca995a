#!/usr/bin/env bash
# A headless browser from Debian, so that tests/project/test_docs_math.py opens a built page and
# checks that its mathematics is typeset offline (MathJax from the site, not a CDN).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update >/dev/null
apt-get install -y --no-install-recommends chromium >/dev/null
chromium --version
