# expect_violations.cmake: the layering check's negative control. Runs
# check_layering.cmake on tests/layering/planted, a small tree whose files
# break each rule on purpose, and passes only if the check fails and names
# every planted violation by file, line and rule, and none of the planted
# lines that break no rule. A check that passes anything, or fails for another
# reason (a script error), fails this test.
#
#   cmake -DTESSERA_LAYERING_SCRIPT=<check_layering.cmake> -DTESSERA_LAYERING_ROOT=<planted tree>
#         -P expect_violations.cmake
cmake_minimum_required(VERSION 3.25)

foreach(var TESSERA_LAYERING_SCRIPT TESSERA_LAYERING_ROOT)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "usage: cmake -DTESSERA_LAYERING_SCRIPT=<check_layering.cmake> "
                            "-DTESSERA_LAYERING_ROOT=<planted tree> -P expect_violations.cmake")
    endif()
endforeach()

# Each planted violation, as the check must report it (file:line: [rule]
# #include ...); an edit to a planted file moves these lines with it.
set(expected
    "engine/core/src/terrain/Bad.cpp:5: [vulkan] #include <vulkan/vulkan.h>"
    "engine/core/include/tessera/scene/Bad.h:4: [gpu-layer] #include \"tessera/gpu/Device.h\""
    "engine/core/include/tessera/backend/Bad.h:4: [library-order] #include \"tessera/subdiv/SubdivGpuMesh.h\""
    "engine/gpu/src/Bad.cpp:4: [library-order] #include \"tessera/assets/GltfLoader.h\""
    "engine/subdiv/src/Bad.cpp:4: [library-order] #include \"tessera/runtime/Options.h\""
    "runtime/src/Bad.cpp:8: [library-order] #include \"tessera/cli/CommandLine.h\""
    "tools/heightgen/Bad.cpp:3: [vulkan] #include <volk.h>"
    "game_sample/Bad.cpp:3: [backend-header] #include \"HulldomainTessFactorPass.h\""
    "game_sample/Bad.cpp:4: [backend-header] #include \"../backends/common/GpuTerrain.h\""
    "game_sample/Bad.cpp:5: [backend-header] #include \"CommandHelpers.h\""
    "runtime/src/Bad.cpp:5: [vulkan] #include <vulkan/vulkan.h>"
    "backends/common/CommandHelpers.h:5: [backend-header] #include \"StreamoutBuffers.h\""
    "backends/r2vb/R2vbBad.cpp:6: [backend-header] #include \"HulldomainCharacterPatchPass.h\""
    "backends/null/NullBad.cpp:4: [gpu-layer] #include \"tessera/gpu/Device.h\""
    "backends/null/NullBad.cpp:5: [backend-header] #include \"GpuTerrain.h\""
    "tests/content/Bad.cpp:3: [tool-source] #include \"../../tools/creature/src/Bvh.h\""
    "backends/r2vb/R2vbBad.cpp:10: [barrier] vkCmdPipelineBarrier")
# Planted lines that break no rule: a commented-out include, a library's
# use of the core below it, the runtime's
# use of the GPU layer, a backend's own and the shared headers, the GPU tests,
# a tool's public header.
set(innocent
    "engine/core/src/scene/Good.cpp:"
    "engine/core/include/tessera/backend/Bad.h:5:"
    "engine/gpu/src/Bad.cpp:5:"
    "engine/subdiv/src/Bad.cpp:5:"
    "runtime/src/Bad.cpp:4:"
    "backends/r2vb/R2vbBad.cpp:4:"
    "backends/r2vb/R2vbBad.cpp:5:"
    "backends/common/GpuTerrain.h:"
    "tests/gpu/Good.cpp:"
    "tests/content/Bad.cpp:4:")

execute_process(
    COMMAND "${CMAKE_COMMAND}" -DTESSERA_LAYERING_ROOT=${TESSERA_LAYERING_ROOT} -DTESSERA_LAYERING_EXEMPTIONS=OFF
            -P "${TESSERA_LAYERING_SCRIPT}"
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
message("${output}")

set(failures "")
if(result EQUAL 0)
    list(APPEND failures "the check passed a tree with planted violations")
endif()
foreach(line IN LISTS expected)
    string(FIND "${output}" "${line}" at)
    if(at EQUAL -1)
        list(APPEND failures "not reported: ${line}")
    endif()
endforeach()
foreach(prefix IN LISTS innocent)
    string(FIND "${output}" "${prefix}" at)
    if(NOT at EQUAL -1)
        list(APPEND failures "reported, though it breaks no rule: ${prefix}")
    endif()
endforeach()
list(LENGTH expected expectedCount)
if(NOT output MATCHES "layering: ${expectedCount} violations, 0 stale exemptions")
    list(APPEND failures "the check's summary does not count exactly ${expectedCount} violations")
endif()

if(failures)
    list(JOIN failures "\n  " text)
    message(FATAL_ERROR "layering negative control:\n  ${text}")
endif()
message(STATUS "layering negative control: the check failed and named all ${expectedCount} planted violations")
