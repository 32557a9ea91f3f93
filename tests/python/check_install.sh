#!/usr/bin/env bash
# Installs the python component of the build tree into a scratch prefix and imports the module
# from there with Debian's python3, away from the build tree.
set -euo pipefail
build_dir=$1 python=$2 relative=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --component python --prefix "$scratch/prefix" > "$scratch/install.log"
site="$scratch/prefix/$relative"
test -f "$site/contain/__init__.py" && test -f "$site/contain/py.typed"
cd "$scratch"
PYTHONPATH="$site" "$python" -c "
import contain, contain.dask, numpy as np
assert contain.__file__.startswith('$site'), contain.__file__
square = contain.PolygonIndex('POLYGON ((0 0, 1 0, 1 1, 0 1))')
assert square.locate(np.array([[0.5, 0.5], [1, 1], [2, 2]])).tolist() == [1, 0, -1]
print('python install check: contain', contain.__version__, 'imports from', '$site')
"
