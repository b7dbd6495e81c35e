#!/usr/bin/env bash
# Runs one libFuzzer harness (docs/RELIABILITY.md):
#   tools/fuzz/run.sh NAME SECONDS [libFuzzer flags...]
# NAME is gltf, heightmap, obj or cli. Builds the fuzz preset (clang, ASan,
# UBSan) first, seeds the corpus from ../shared/testdata (and
# tools/fuzz/seeds), keeps the grown corpus in build/fuzz/corpus/NAME and
# writes any crash, leak or hang to build/fuzz/artifacts/NAME/. Exits
# non-zero when the harness found one. Needs clang and libfuzzer-14-dev.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
name="${1:-}"
seconds="${2:-}"
case "$name" in gltf | heightmap | obj | cli) ;; *)
  echo "usage: tools/fuzz/run.sh gltf|heightmap|obj|cli SECONDS [libFuzzer flags]" >&2
  exit 2 ;;
esac
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "tools/fuzz/run.sh: SECONDS must be a whole number of seconds, got '$seconds'" >&2
  exit 2
fi
shift 2
# 77: skipped (ctest's SKIP_RETURN_CODE for the smoke runs) where clang is missing.
if ! command -v clang++ >/dev/null || ! compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null; then
  echo "tools/fuzz/run.sh: clang++ or libFuzzer not found (apt-get install clang libfuzzer-14-dev); not fuzzing" >&2
  exit 77
fi

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc 2>/dev/null || echo 2)" >/dev/null

testdata="$root/../shared/testdata"
seeds="build/fuzz/seeds/$name"
corpus="build/fuzz/corpus/$name"
artifacts="build/fuzz/artifacts/$name"
rm -rf "$seeds"
mkdir -p "$seeds" "$corpus" "$artifacts"
# Seeds: the real inputs of that kind, small enough to mutate quickly.
seed_files() {
  case "$name" in
    gltf) find "$testdata" -type f \( -name '*.glb' -o -name '*.gltf' \) -size -256k ;;
    heightmap) find "$testdata" "$root/tests" -type f -name '*.png' -size -256k ;;
    obj) find "$testdata" -type f -name '*.obj' -size -256k ;;
    cli) find "$root/tools/fuzz/seeds/cli" -type f ;;
  esac
}
i=0
while IFS= read -r f; do
  cp "$f" "$seeds/$(printf '%04d' "$i")_$(basename "$f")"
  i=$((i + 1))
done < <(seed_files | sort)
[ -d "$testdata" ] || echo "tools/fuzz/run.sh: $testdata not found; seeding from tools/fuzz only" >&2

# Leaks count as failures; a hang is an input that takes over 10 s.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec "build/fuzz/bin/tessera_fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -max_len=262144 -print_final_stats=1 -artifact_prefix="$artifacts/" "$@" "$corpus" "$seeds"
