#!/usr/bin/env bash
# The long soaks of docs/RELIABILITY.md:
#   tools/soak.sh [NULL_FRAMES] [LAVAPIPE_FRAMES]
# The crowd scene under a meteor shower for NULL_FRAMES frames on the null
# backend (default 100000) and LAVAPIPE_FRAMES on lavapipe (default 10000,
# under the validation layer), checking that memory stays flat after
# warm-up; each run prints one "[soak]" line with its figures. The test
# suite runs the same tests short (FrameSoak.*).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
for n in "${1:-100000}" "${2:-10000}"; do
  [[ "$n" =~ ^[0-9]+$ ]] || { echo "tools/soak.sh: frame counts are whole numbers, got '$n'" >&2; exit 2; }
done
./tessera build >/dev/null
TESSERA_SOAK_FRAMES="${1:-100000}" build/release/bin/tessera_runtime_tests --gtest_filter='FrameSoak.NullBackend*'
TESSERA_SOAK_FRAMES="${2:-10000}" build/release/bin/tessera_runtime_tests --gtest_filter='FrameSoak.Lavapipe*'
