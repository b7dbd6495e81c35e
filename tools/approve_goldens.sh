#!/usr/bin/env bash
# Approves the images the last golden-image test run rendered as the new
# goldens. Deliberate by design: look at each image (and its .diff.png, if
# the test wrote one) before running this, and commit the result on its own.
#   tools/approve_goldens.sh [PRESET] [BACKEND...]
# tests/golden/goldens.txt says which file each backend's golden is. Backends
# that share a file are approved together: the file is written only when every
# backend sharing it rendered the same bytes (the PNG encoder is
# deterministic), since it is their golden too.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${1:-release}"
shift || true
backends=("$@")
manifest="$root/tests/golden/goldens.txt"
out="$root/build/$preset/test-output"

declare -A golden
order=()
while read -r name file _; do
  [[ -z "${name:-}" || "$name" == \#* ]] && continue
  golden[$name]="$file"
  order+=("$name")
done <"$manifest"
[ ${#backends[@]} -eq 0 ] && backends=("${order[@]}")

for b in "${backends[@]}"; do
  file="${golden[$b]:-}"
  if [ -z "$file" ]; then
    echo "approve_goldens: $manifest names no golden for backend '$b'" >&2
    exit 1
  fi
  src="$out/golden_$b.png"
  if [ ! -f "$src" ]; then
    echo "approve_goldens: $src does not exist; run ./tessera test first" >&2
    exit 1
  fi
  for other in "${order[@]}"; do
    [ "$other" = "$b" ] || [ "${golden[$other]}" != "$file" ] && continue
    if ! cmp -s "$src" "$out/golden_$other.png"; then
      echo "approve_goldens: $b and $other share tests/golden/$file but rendered different images" \
           "($out/golden_$other.png); give each its own line in $manifest" >&2
      exit 1
    fi
  done
  cp "$src" "$root/tests/golden/$file"
  echo "approved $root/tests/golden/$file ($b)"
done
