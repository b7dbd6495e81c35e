#!/usr/bin/env bash
# Approves the images the last golden-image test run rendered as the new
# goldens. Deliberate by design: look at each image (and its .diff.png, if
# the test wrote one) before running this, and commit the result on its own.
#   tools/approve_goldens.sh [PRESET] [BACKEND...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${1:-release}"
shift || true
backends=("$@")
[ ${#backends[@]} -eq 0 ] && backends=(r2vb streamout hulldomain)
out="$root/build/$preset/test-output"
for b in "${backends[@]}"; do
  src="$out/golden_$b.png"
  if [ ! -f "$src" ]; then
    echo "approve_goldens: $src does not exist; run ./tessera test first" >&2
    exit 1
  fi
  cp "$src" "$root/tests/golden/$b.png"
  echo "approved $root/tests/golden/$b.png"
done
