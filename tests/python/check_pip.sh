#!/usr/bin/env bash
# pip as a Python user runs it, offline: `python3 -m pip install --no-build-isolation .` and
# `pip wheel --no-build-isolation .` on a copy of the project, into a scratch virtual environment
# made with --system-site-packages (Debian's numpy, setuptools, wheel, shapely), then the module
# imported from the environment with the version of CMakeLists.txt.
#
# Speed (2 cores): where ccache is on PATH the copy is configured and built afresh by setup.py
# (the copy's build tree sits at the depth of build/release, so ccache's base_dir finds the
# suite's objects); without ccache setup.py reuses the suite's own build tree
# (CONTAIN_CMAKE_BUILD_DIR), which is configured for the same interpreter and sources.
set -euo pipefail
project=$1 build_dir=$2 python=$3
scratch="$build_dir/tests/python/pip"
rm -rf "$scratch"
mkdir -p "$scratch"
trap 'rm -rf "$scratch/venv" "$scratch/wheel-venv"' EXIT

# The project as a user's checkout would hold it: no build trees, no caches.
"$python" - "$project" "$scratch/src" <<'PY'
import shutil, sys
shutil.copytree(sys.argv[1], sys.argv[2],
                ignore=shutil.ignore_patterns("build", ".git", "__pycache__", "*.egg-info", "out"))
PY

if [ -z "${CONTAIN_PIP_REUSE_BUILD:-}" ] && command -v ccache > /dev/null; then
  how="configured by setup.py, compiled through ccache"
else
  export CONTAIN_CMAKE_BUILD_DIR="$build_dir"
  how="the suite's build tree reused"
fi
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2} PIP_NO_INDEX=1
export PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1

"$python" -m venv --system-site-packages "$scratch/venv"
venv_python="$scratch/venv/bin/python"
(cd "$scratch/src" && "$venv_python" -m pip install --no-build-isolation -q . > "$scratch/install.log" 2>&1) ||
  { tail -40 "$scratch/install.log"; exit 1; }

version=$(sed -n 's/^project(contain VERSION \([0-9.]*\).*/\1/p' "$project/CMakeLists.txt")
cd "$scratch"
"$venv_python" - "$scratch/venv" "$version" <<'PY'
import sys, pathlib
import contain, contain.dask
import numpy as np
venv, version = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2]
where = pathlib.Path(contain.__file__).resolve()
assert venv in where.parents, f"contain imported from {where}, not from the environment {venv}"
assert contain.__version__ == version, (contain.__version__, version)
import importlib.metadata as metadata
assert metadata.version("contain") == version, metadata.version("contain")
for name in ("_contain.pyi", "py.typed", "dask.py"):
    assert (where.parent / name).exists(), name
square = contain.PolygonIndex("POLYGON ((0 0, 1 0, 1 1, 0 1))")
assert square.locate(np.array([[0.5, 0.5], [1, 1], [2, 2]])).tolist() == [1, 0, -1]
try:
    import shapely.geometry
    assert contain.as_region(shapely.geometry.box(0, 0, 1, 1)).area == 1.0
except ImportError:
    pass
print("pip install:", "contain", contain.__version__, "imports from", where.parent)
PY

# pip wheel: the same build (the copy's tree is reused), a wheel holding the module, the
# stubs and the marker, installable offline into another environment.
(cd "$scratch/src" && "$venv_python" -m pip wheel --no-build-isolation --no-deps -q -w "$scratch/dist" . \
   > "$scratch/wheel.log" 2>&1) || { tail -40 "$scratch/wheel.log"; exit 1; }
wheel=$(ls "$scratch"/dist/contain-"$version"-*.whl)
"$python" - "$wheel" <<'PY'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
for needed in ("contain/__init__.py", "contain/dask.py", "contain/_contain.pyi", "contain/py.typed"):
    assert needed in names, (needed, names)
assert any(n.startswith("contain/_contain") and n.endswith(".so") for n in names), names
PY
"$python" -m venv --system-site-packages "$scratch/wheel-venv"
"$scratch/wheel-venv/bin/python" -m pip install -q --no-deps "$wheel"
"$scratch/wheel-venv/bin/python" -c "import contain; assert contain.__version__ == '$version'; print('pip wheel:', '$(basename "$wheel")', 'installs and imports')"
echo "pip check: passed ($how)"
