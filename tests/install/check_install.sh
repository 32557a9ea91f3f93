#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then builds and runs two consumers against it:
# a CMake project using find_package(contain) and a plain compiler call using pkg-config.
set -euo pipefail
build_dir=$1 source_dir=$2 compiler=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > "$scratch/install.log"
cmake -S "$source_dir/tests/install/consumer" -B "$scratch/consumer" -G Ninja \
  -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_PREFIX_PATH="$scratch/prefix" > /dev/null
cmake --build "$scratch/consumer" > /dev/null
"$scratch/consumer/consumer"
export PKG_CONFIG_PATH="$scratch/prefix/lib/pkgconfig:$scratch/prefix/lib64/pkgconfig"
# shellcheck disable=SC2046
"$compiler" -std=c++20 "$source_dir/tests/install/pkgconfig_main.cpp" -o "$scratch/pc_main" \
  $(pkg-config --cflags --libs --static contain)
"$scratch/pc_main"
test -x "$scratch/prefix/bin/contain"
"$scratch/prefix/bin/contain" --version
echo "install check: find_package, pkg-config and the installed command work"
