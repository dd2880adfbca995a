#!/usr/bin/env bash
# The package as a user gets it (issue 23, item 4): build the sdist and the wheel (the wheel from
# the sdist, as `python -m build` does), check them with twine, install the wheel (not editable,
# with its dependencies) in a fresh virtual environment and run the program from there, in a
# folder outside the source tree so that nothing is imported from the checkout by accident.
# A few minutes: the claims take about a minute on 2 cores, installing the dependencies the rest.
#
#   bash .ci/package.sh        # from anywhere; exit status 0 when every step passed
set -euo pipefail
cd "$(dirname "$0")/.."
src=$(pwd)
work=$(mktemp -d)
created=()
for artifact in symdecomp.egg-info build; do  # what building in the tree may leave; removed if it was not there
  [ -e "$artifact" ] || created+=("$src/$artifact")
done
cleanup() { rm -rf "$work" "${created[@]+"${created[@]}"}"; }
trap cleanup EXIT

python -c "import build, twine" 2>/dev/null || python -m pip install --quiet build twine
echo "== python -m build"
python -m build --outdir "$work/dist" . >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
ls "$work/dist"
echo "== twine check"
python -m twine check --strict "$work/dist/"*
echo "== the wheel holds the license and the PEP 561 marker"
python - "$work/dist/"*.whl <<'EOF'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
wanted = ["symdecomp/py.typed", next((n for n in names if n.endswith(".dist-info/licenses/LICENSE")), "*.dist-info/licenses/LICENSE")]
missing = [n for n in wanted if n not in names]
assert not missing, f"missing from the wheel: {missing}"
print("\n".join(wanted))
EOF

echo "== fresh virtual environment, the wheel installed from its file"
python -m venv "$work/venv"
"$work/venv/bin/python" -m pip install --quiet "$work/dist/"*.whl
bin="$work/venv/bin"
cd "$work"  # outside the source tree
export XDG_CACHE_HOME="$work/cache"  # where an installed package builds the OpenSubdiv bridge
"$bin/python" - "$src" <<'EOF'
import os, sys
import symdecomp
where = os.path.realpath(symdecomp.__file__)
assert not where.startswith(os.path.realpath(sys.argv[1]) + os.sep), f"imported from the source tree: {where}"
print(f"symdecomp {symdecomp.__version__} from {os.path.dirname(where)}")
EOF

echo "== symdecomp --version"
"$bin/symdecomp" --version
echo "== symdecomp claims"
"$bin/symdecomp" claims --no-progress >claims.txt || { cat claims.txt; exit 1; }
tail -n 2 claims.txt
echo "== symdecomp c1 --n 3:5"
"$bin/symdecomp" c1 --n 3:5
echo "== symdecomp derive --label 'Eq. 34' (the LaTeX preamble is package data)"
"$bin/symdecomp" derive --label "Eq. 34" | head -n 3
echo "== symdecomp oracle --n 3 --levels 8 (the bridge built from the wheel's source, in the cache folder)"
code=0
"$bin/symdecomp" oracle --n 3 --levels 8 >oracle.txt || code=$?
if [ "$code" -eq 3 ] && ! "$bin/python" -c "from symdecomp.verify.opensubdiv.build import headers_present; raise SystemExit(not headers_present())"; then
  echo "OpenSubdiv is not installed here: oracle said so in one line (exit 3); .ci/steps/30-opensubdiv.sh installs it"
elif [ "$code" -ne 0 ]; then
  cat oracle.txt; echo "oracle from the wheel failed (exit $code)"; exit 1
else
  head -n 1 oracle.txt
  ls "$XDG_CACHE_HOME/symdecomp/"
fi
echo "== the installed package passed"
