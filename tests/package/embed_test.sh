#!/usr/bin/env bash
# The consumer example against the installed package, as a game would use it:
# install Tessera into a fresh prefix, build examples/embed with only
# find_package(Tessera), and run it from another directory with no hint of
# the build tree (no TESSERA_* variables, no LD_LIBRARY_PATH), headless,
# under the validation layer.
#   embed_test.sh <tessera build dir> <source dir> <work dir>
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
echo "== install into $work/prefix"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
echo "== configure and build examples/embed against it"
cmake -S "$src/examples/embed" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log"
cmake --build "$work/build"
echo "== run"
cd "$work"
env -u TESSERA_PLUGIN_DIR -u TESSERA_CONTENT_DIR -u LD_LIBRARY_PATH \
  "$work/build/tessera-embed" --validation --frames 8 --agents 200 --screenshot "$work/embed.png"
test -s "$work/embed.png"
echo "== the plugins and content came from the prefix"
grep -q "tessera_backend_" "$work/install.log"
