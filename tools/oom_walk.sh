#!/usr/bin/env bash
# The full out-of-device-memory walk (docs/RELIABILITY.md, "Exhaustion"): on
# every GPU backend, the crowd scene and the characters scene with a
# Catmull-Clark surface are run once per device allocation they make, that
# allocation failing (gpu::Device::failAllocation), plus the caps; every run
# must end in OutOfDeviceMemory with 0 validation messages (object tracking
# clean). About 40 minutes on lavapipe on two cores; the suite runs a sample.
#
#   tools/oom_walk.sh [BUILD_DIR]     (default build/release, built already)
set -euo pipefail
build=${1:-build/release}
tests="$build/bin/tessera_runtime_tests"
[[ -x $tests ]] || { echo "oom_walk.sh: $tests not built (./tessera build)" >&2; exit 2; }
TESSERA_OOM_WALK=full "$tests" --gtest_filter='DeviceMemoryExhaustion.*' 2>&1 |
    grep -E '^\[oom\]|^\[ *(OK|FAILED|PASSED) *\]|Failure|validation:'
