#!/usr/bin/env bash
# OpenSubdiv from Debian and the symdecomp bridge to it (symdecomp/verify/opensubdiv/osd_bridge.cpp),
# so that the oracle tests (tests/verify/test_opensubdiv.py) run instead of being skipped.
set -euo pipefail
cd "$(dirname "$0")/../.."
export DEBIAN_FRONTEND=noninteractive
apt-get update >/dev/null
apt-get install -y --no-install-recommends g++ libosd-dev libosdcpu3.5.0 >/dev/null
# Stand-alone build script (standard library only; the package is not installed yet).
python symdecomp/verify/opensubdiv/build.py --force
