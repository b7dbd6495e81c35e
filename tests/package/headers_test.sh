#!/usr/bin/env bash
# The runtime's public headers compile without the Vulkan headers, as a game
# includes them: install Tessera into a fresh prefix, compile one
# translation unit of every installed tessera/runtime, tessera/cli and
# tessera/demo header against it (tests/package/headers), and fail if any
# header it reaches, directly or through others, is Vulkan's, volk's,
# GLFW's or the GPU layer's (tessera/gpu). Debian keeps the Vulkan headers in
# /usr/include, where every compiler finds them, so the check reads the
# compiler's list of the headers it opened (-H) instead of hiding them.
#   headers_test.sh <tessera build dir> <source dir> <work dir>
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
echo "== install into $work/prefix"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
# Compiles the translation unit in $work/$1 (with cmake options $2...) and
# lists the headers it reached in $work/$1/reached.txt.
reach() {
  local dir=$work/$1
  shift
  cmake -S "$src/tests/package/headers" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$work/prefix" "$@" >"$dir.configure.log"
  cmake --build "$dir" -v >"$dir.build.log" 2>&1 || { cat "$dir.build.log"; exit 1; }
  # -H prints one line per header opened: dots for the depth, then the path.
  grep -E '^\.+ ' "$dir.build.log" | sed -E 's/^\.+ //' | sort -u >"$dir/reached.txt"
  grep -q 'tessera/runtime/RenderSession.h$' "$dir/reached.txt" ||
    { echo "$1 reached no tessera/runtime/RenderSession.h: the check did not run"; exit 1; }
}
forbidden='(/vulkan/|/vk_video/|/volk|vulkan\.h|/GLFW/|/tessera/gpu/)'
echo "== the negative control: a tessera/gpu header planted among them must be named"
reach planted -DTESSERA_HEADER_CHECK_PLANTED=ON
grep -qE "$forbidden" "$work/planted/reached.txt" ||
  { echo "FAIL: the check missed the planted tessera/gpu/Device.h"; exit 1; }
echo "== compile every installed runtime, cli and demo header with -H"
reach every
echo "$(wc -l <"$work/every/reached.txt") headers reached"
if grep -E "$forbidden" "$work/every/reached.txt"; then
  echo "FAIL: the installed headers above reach Vulkan, GLFW or the GPU layer"
  exit 1
fi
echo "== no Vulkan, GLFW or tessera/gpu header reached"
