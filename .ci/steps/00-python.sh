#!/usr/bin/env bash
# The Python build tooling the editable install needs.
set -euo pipefail
python -m pip install --upgrade pip setuptools wheel >/dev/null
