# check_layering.cmake: Tessera's layering, checked rather than promised
# (docs/ARCHITECTURE.md, "Layers and libraries"). Scans every C and C++ source file under a
# tree and fails, naming file:line and the rule, where a file includes what
# its layer may not, or records a barrier by hand:
#
#   cmake -DTESSERA_LAYERING_ROOT=<source tree> [-DTESSERA_LAYERING_EXEMPTIONS=OFF]
#         -P check_layering.cmake
#
# It needs nothing but CMake, so it runs before (and without) a build. The
# rules, by where the including file lives:
#
#   [library-order]  the libraries use only the libraries below them. A
#             file belongs to the library of its folder; an include belongs
#             to the library of its include root (tessera/<module>/ of the
#             core's modules, tessera/subdiv/, tessera/assets/,
#             tessera/runtime/, tessera/cli/, tessera/demo/) or of the
#             file it reaches:
#               engine/core      (tessera_core)    nothing but itself
#               engine/subdiv    (tessera_subdiv)  core
#               engine/assets    (tessera_assets)  core
#               engine/gpu       (tessera_gpu)     core
#               backends/common, backends/<name>   core
#               backends/null                      core, subdiv (it
#                                                  refines surfaces on the CPU)
#               runtime          (tessera_runtime) core, subdiv, assets
#               tools/cli        (tessera_cli)     core
#               game_sample/cli  (tessera_demo_cli) core, cli, runtime
#             Uses of the GPU layer and of backends/common have rules of
#             their own ([gpu-layer], [backend-header]) and are not judged
#             twice here.
#   [vulkan]  <vulkan/...>, <volk...> and vulkan*.h only in the GPU layer
#             (engine/gpu), the GPU backends
#             (backends/<name>, not backends/null) and the GPU tests
#             (tests/gpu). Not in runtime/ either: the runtime drives the
#             GPU layer's classes and reaches Vulkan only through its headers,
#             which decide how Vulkan is included and configured.
#   [gpu-layer]  tessera/gpu/... (or a path into the GPU layer) only in the
#             GPU layer, the GPU backends, the GPU tests and runtime/ (the
#             host layer: it creates the device and the frame scheduler).
#             Everything else is the data model and its users (engine's
#             core, scene, profiler, terrain, backend, tessellator, character,
#             crowd, lod, assets and subdiv; tools/, game_sample/, examples/,
#             plugins/, the other tests), which stay Vulkan-free.
#   [backend-header]  a backend's header (a file under backends/<name>/,
#             reached by a path or found by name: any header under
#             backends/, or a name carrying a backend's prefix, Hulldomain*,
#             R2vb*, Streamout*, Null*, hulldomain_*, r2vb_*, streamout_*)
#             only from that backend's own folder. backends/common is
#             shared: the GPU backends and the GPU tests (which link
#             tessera_backend_common) may include it; it includes no single
#             backend. The null backend links no GPU code, so not even
#             backends/common. Backends are plugins loaded by name; the host,
#             the runtime, the demo and the examples never include them.
#   [barrier]  a call of vkCmdPipelineBarrier (or ...2, ...2KHR) anywhere but
#             engine/gpu/src/Barriers.cpp: every barrier goes through the GPU
#             layer's helpers (memoryBarrier, imageBarrier, bufferBarrier,
#             pipelineBarrier in Barriers.h; transitionImage in Image.h).
#   [tool-source]  a file under tools/<tool>/ other than its include/
#             folder (the tool's sources, reached by a path such as
#             ../../tools/creature/src/Bvh.h) from outside that tool: tests
#             and other code link the tool's library and include its public
#             headers by their normal path ("creature/Bvh.h").
#
# A folder that does not exist is simply empty. Build trees (top-level
# build*/ folders, or any top-level folder holding a CMakeCache.txt), hidden
# folders and the negative control's planted tree are not scanned. Lines are
# matched as written: an #include or a call inside a block comment or #if 0
# counts.
cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED TESSERA_LAYERING_ROOT)
    message(FATAL_ERROR "usage: cmake -DTESSERA_LAYERING_ROOT=<source tree> -P check_layering.cmake")
endif()
get_filename_component(root "${TESSERA_LAYERING_ROOT}" ABSOLUTE)
if(NOT IS_DIRECTORY "${root}")
    message(FATAL_ERROR "layering: ${root} is not a directory")
endif()

# Files exempt from one rule, "path|rule", each with its reason. An entry
# that no longer matches a violation (the file is gone or no longer includes
# what it was exempted for) fails the check, so the list cannot outlive its
# reasons.
set(exemptions
    # A test backend plugin, not a loader test: it records a Vulkan command
    # that breaks a valid-usage rule on purpose (a viewport count of zero), so
    # the tests can prove the validation layer is on. Like every backend it
    # records through the frame the GPU layer hands it (FrameContext,
    # RenderTarget). The loader's plugins in tests/plugins stay Vulkan-free.
    "tests/plugins/InvalidUsagePlugin.cpp|gpu-layer"
    # A test backend plugin whose initialize fails after making GPU objects
    # (a buffer, an image, a sampler, a descriptor-set layout) through the
    # GPU layer, as a real backend's would, so the tests can prove the host
    # shuts a half-initialised backend down.
    "tests/plugins/InitFailsPlugin.cpp|gpu-layer")

# The negative control judges its planted tree by the bare rules.
if(DEFINED TESSERA_LAYERING_EXEMPTIONS AND NOT TESSERA_LAYERING_EXEMPTIONS)
    set(exemptions "")
endif()

# Not scanned, relative to the root: the negative control's tree, whose files
# break every rule on purpose (tests/layering/expect_violations.cmake).
set(skippedPrefixes "tests/layering/planted/")

set(sourceSuffixes h hh hpp hxx inc inl ipp c cc cpp cxx)

# --- The files to scan -------------------------------------------------------
file(GLOB topEntries LIST_DIRECTORIES true RELATIVE "${root}" "${root}/*")
set(files "")
foreach(entry IN LISTS topEntries)
    if(entry MATCHES "^\\.")
        continue()
    endif()
    if(IS_DIRECTORY "${root}/${entry}")
        if(entry MATCHES "^build" OR EXISTS "${root}/${entry}/CMakeCache.txt")
            continue()
        endif()
        set(globs "")
        foreach(suffix IN LISTS sourceSuffixes)
            list(APPEND globs "${root}/${entry}/*.${suffix}")
        endforeach()
        file(GLOB_RECURSE found RELATIVE "${root}" ${globs})
        list(APPEND files ${found})
    else()
        foreach(suffix IN LISTS sourceSuffixes)
            if(entry MATCHES "\\.${suffix}$")
                list(APPEND files "${entry}")
            endif()
        endforeach()
    endif()
endforeach()
foreach(prefix IN LISTS skippedPrefixes)
    list(FILTER files EXCLUDE REGEX "^${prefix}")
endforeach()
list(SORT files)

# --- Every header under backends/, by file name ------------------------------
# backendsOf_<name>: the backends (folder names) holding a header of that name.
file(GLOB_RECURSE backendHeaders RELATIVE "${root}/backends"
    "${root}/backends/*.h" "${root}/backends/*.hh" "${root}/backends/*.hpp" "${root}/backends/*.inc")
foreach(header IN LISTS backendHeaders)
    string(REGEX MATCH "^[^/]+" backendName "${header}")
    get_filename_component(headerName "${header}" NAME)
    string(MAKE_C_IDENTIFIER "${headerName}" key)
    list(APPEND backendsOf_${key} "${backendName}")
endforeach()

# Which backend(s) an include names, or "" for none: `resolved` is the file it
# reaches relative to the root (or ""), `include` the text between the quotes.
function(backends_of_include include resolved outVar)
    if(resolved MATCHES "^backends/([^/]+)/")
        set(${outVar} "${CMAKE_MATCH_1}" PARENT_SCOPE)
        return()
    endif()
    if(NOT resolved STREQUAL "")
        # A file that exists outside backends/ is not a backend's, whatever its name.
        set(${outVar} "" PARENT_SCOPE)
        return()
    endif()
    if(include MATCHES "(^|/)backends/([^/]+)/")
        set(${outVar} "${CMAKE_MATCH_2}" PARENT_SCOPE)
        return()
    endif()
    if(include MATCHES "^tessera/")
        set(${outVar} "" PARENT_SCOPE)
        return()
    endif()
    get_filename_component(name "${include}" NAME)
    string(MAKE_C_IDENTIFIER "${name}" key)
    if(DEFINED backendsOf_${key})
        set(${outVar} "${backendsOf_${key}}" PARENT_SCOPE)
        return()
    endif()
    # Two tests, not one with OR: CMake evaluates both, and a failed MATCHES
    # clears CMAKE_MATCH_1.
    if(name MATCHES "^(Hulldomain|R2vb|Streamout|Null)[A-Z0-9_]")
        string(TOLOWER "${CMAKE_MATCH_1}" prefix)
        set(${outVar} "${prefix}" PARENT_SCOPE)
        return()
    endif()
    if(name MATCHES "^(hulldomain|r2vb|streamout|null)_")
        set(${outVar} "${CMAKE_MATCH_1}" PARENT_SCOPE)
        return()
    endif()
    set(${outVar} "" PARENT_SCOPE)
endfunction()

# --- The libraries and their order ([library-order]) -------------------------
set(coreModules backend character core crowd device lod profiler scene shaders terrain tessellator)
list(JOIN coreModules "|" coreModuleRegex)
# mayUse_<library>: the libraries a library's files may include (its own
# included); a file outside every library (tests, tools, the demo) is not
# judged by this rule.
set(mayUse_core core)
set(mayUse_subdiv core subdiv)
set(mayUse_assets core assets)
set(mayUse_gpu core gpu)
set(mayUse_backend core)
set(mayUse_nullbackend core subdiv)
set(mayUse_runtime core subdiv assets runtime)
set(mayUse_cli core cli)
set(mayUse_demo core cli runtime demo)

function(library_of_file file outVar)
    set(library "")
    if(file MATCHES "^engine/(core|subdiv|assets|gpu)/")
        set(library "${CMAKE_MATCH_1}")
    elseif(file MATCHES "^backends/null/")
        set(library nullbackend)
    elseif(file MATCHES "^backends/")
        set(library backend)
    elseif(file MATCHES "^runtime/")
        set(library runtime)
    elseif(file MATCHES "^tools/cli/")
        set(library cli)
    elseif(file MATCHES "^game_sample/cli/")
        set(library demo)
    endif()
    set(${outVar} "${library}" PARENT_SCOPE)
endfunction()

# The library an include reaches, or "" for none of the ordered ones (the
# GPU layer's headers are [gpu-layer]'s to judge).
function(library_of_include include resolved outVar)
    set(library "")
    if(resolved MATCHES "^engine/(core|subdiv|assets)/")
        set(library "${CMAKE_MATCH_1}")
    elseif(resolved MATCHES "^runtime/")
        set(library runtime)
    elseif(resolved MATCHES "^tools/cli/")
        set(library cli)
    elseif(resolved MATCHES "^game_sample/cli/")
        set(library demo)
    elseif(resolved STREQUAL "" AND include MATCHES "^tessera/(${coreModuleRegex})/")
        set(library core)
    elseif(resolved STREQUAL "" AND include MATCHES "^tessera/(subdiv|assets|runtime|cli|demo)/")
        set(library "${CMAKE_MATCH_1}")
    endif()
    set(${outVar} "${library}" PARENT_SCOPE)
endfunction()

# --- Scan ---------------------------------------------------------------------
# Lines are split on newlines; characters CMake's lists treat specially are
# swapped for control characters first so every line stays one element.
string(ASCII 1 kSemicolon)
string(ASCII 2 kOpenBracket)
string(ASCII 3 kCloseBracket)
string(ASCII 4 kBackslash)
set(violations 0)
set(usedExemptions "")
foreach(file IN LISTS files)
    # Where the including file lives decides what it may include.
    set(zone host)
    set(ownBackend "")
    if(file MATCHES "^engine/gpu/")
        set(zone gpu)
    elseif(file MATCHES "^backends/([^/]+)/")
        set(ownBackend "${CMAKE_MATCH_1}")
        if(ownBackend STREQUAL "null")
            set(zone null-backend)
        else()
            set(zone backend)
        endif()
    elseif(file MATCHES "^runtime/")
        set(zone runtime)
    elseif(file MATCHES "^tests/gpu/")
        set(zone gpu-test)
    endif()
    get_filename_component(fileDir "${file}" DIRECTORY)
    library_of_file("${file}" fileLibrary)

    file(READ "${root}/${file}" content)
    if(NOT content MATCHES "#[ \t]*include" AND NOT content MATCHES "vkCmdPipelineBarrier")
        continue()
    endif()
    string(REPLACE "\\" "${kBackslash}" content "${content}")
    string(REPLACE ";" "${kSemicolon}" content "${content}")
    string(REPLACE "[" "${kOpenBracket}" content "${content}")
    string(REPLACE "]" "${kCloseBracket}" content "${content}")
    string(REPLACE "\n" ";" lines "${content}")
    set(lineNumber 0)
    foreach(line IN LISTS lines)
        math(EXPR lineNumber "${lineNumber} + 1")
        # [barrier]
        if(line MATCHES "vkCmdPipelineBarrier(2|2KHR)?[ \t]*\\(" AND NOT file STREQUAL "engine/gpu/src/Barriers.cpp")
            message("${file}:${lineNumber}: [barrier] vkCmdPipelineBarrier: record barriers through the GPU layer's helpers (tessera/gpu/Barriers.h, transitionImage in Image.h)")
            math(EXPR violations "${violations} + 1")
            continue()
        endif()
        if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]+)[>\"]")
            continue()
        endif()
        set(quoted "${CMAKE_MATCH_1}")
        set(include "${CMAKE_MATCH_2}")
        if(quoted STREQUAL "<")
            set(closing ">")
        else()
            set(closing "\"")
        endif()
        string(REPLACE "${kBackslash}" "/" include "${include}")
        string(REPLACE "${kOpenBracket}" "[" include "${include}")
        string(REPLACE "${kCloseBracket}" "]" include "${include}")

        # The file a quoted include reaches relative to the including file
        # (the compiler's first look), relative to the root.
        set(resolved "")
        if(quoted STREQUAL "\"" AND EXISTS "${root}/${fileDir}/${include}"
           AND NOT IS_DIRECTORY "${root}/${fileDir}/${include}")
            cmake_path(SET target NORMALIZE "${root}/${fileDir}/${include}")
            file(RELATIVE_PATH resolved "${root}" "${target}")
            if(resolved MATCHES "^\\.\\./")
                set(resolved "")
            endif()
        endif()

        set(found "")
        # [library-order]
        if(NOT fileLibrary STREQUAL "")
            library_of_include("${include}" "${resolved}" includeLibrary)
            if(NOT includeLibrary STREQUAL "" AND NOT includeLibrary IN_LIST mayUse_${fileLibrary})
                list(JOIN mayUse_${fileLibrary} ", " usable)
                list(APPEND found "library-order|${fileLibrary} is below ${includeLibrary}: it may use ${usable} only (docs/ARCHITECTURE.md, Layers and libraries)")
            endif()
        endif()
        # [vulkan]
        if(include MATCHES "^vulkan/" OR include MATCHES "(^|/)volk[^/]*$" OR include MATCHES "(^|/)vulkan[^/]*\\.h(pp)?$")
            if(zone STREQUAL "runtime")
                list(APPEND found "vulkan|the runtime reaches Vulkan only through the GPU layer's headers (tessera/gpu/...)")
            elseif(zone STREQUAL "null-backend")
                list(APPEND found "vulkan|the null backend runs with no GPU and links no GPU code")
            elseif(NOT zone MATCHES "^(gpu|backend|gpu-test)$")
                list(APPEND found "vulkan|only the GPU layer, the GPU backends and the GPU tests include Vulkan")
            endif()
        endif()
        # [gpu-layer]
        if(include MATCHES "(^|/)tessera/gpu/" OR resolved MATCHES "^engine/gpu/")
            if(zone STREQUAL "null-backend")
                list(APPEND found "gpu-layer|the null backend runs with no GPU and links no GPU code")
            elseif(NOT zone MATCHES "^(gpu|backend|gpu-test|runtime)$")
                list(APPEND found "gpu-layer|only the runtime, the GPU backends and the GPU tests use the GPU layer, the rest stays Vulkan-free")
            endif()
        endif()
        # [backend-header]
        backends_of_include("${include}" "${resolved}" headerBackends)
        if(NOT headerBackends STREQUAL "")
            set(allowed FALSE)
            foreach(headerBackend IN LISTS headerBackends)
                if(headerBackend STREQUAL ownBackend)
                    set(allowed TRUE)
                elseif(headerBackend STREQUAL "common" AND zone MATCHES "^(backend|gpu-test)$")
                    set(allowed TRUE)
                endif()
            endforeach()
            if(NOT allowed)
                string(REPLACE ";" ", " named "${headerBackends}")
                if(ownBackend STREQUAL "common")
                    list(APPEND found "backend-header|backends/common is shared by every backend and includes no single backend's header (${named})")
                elseif(zone STREQUAL "null-backend")
                    list(APPEND found "backend-header|the null backend links no GPU code, not even backends/common (${named})")
                elseif(zone STREQUAL "backend")
                    list(APPEND found "backend-header|a backend includes its own headers and backends/common only, not another backend's (${named})")
                else()
                    list(APPEND found "backend-header|backends are plugins loaded by name: nothing outside backends/ includes their headers, except the GPU tests' use of backends/common (${named})")
                endif()
            endif()
        endif()

        # [tool-source]
        set(tool "")
        if(resolved MATCHES "^tools/([^/]+)/(.*)$")
            set(tool "${CMAKE_MATCH_1}")
            set(toolPath "${CMAKE_MATCH_2}")
        elseif(resolved STREQUAL "" AND include MATCHES "(^|/)tools/([^/]+)/(.*)$")
            set(tool "${CMAKE_MATCH_2}")
            set(toolPath "${CMAKE_MATCH_3}")
        endif()
        if(NOT tool STREQUAL "" AND NOT file MATCHES "^tools/${tool}/" AND NOT toolPath MATCHES "^include/")
            list(APPEND found "tool-source|link the tool's library and include its public headers (tools/${tool}/include), not its sources")
        endif()

        foreach(violation IN LISTS found)
            string(REPLACE "|" ";" parts "${violation}")
            list(GET parts 0 rule)
            list(GET parts 1 why)
            if("${file}|${rule}" IN_LIST exemptions)
                list(APPEND usedExemptions "${file}|${rule}")
                continue()
            endif()
            message("${file}:${lineNumber}: [${rule}] #include ${quoted}${include}${closing}: ${why}")
            math(EXPR violations "${violations} + 1")
        endforeach()
    endforeach()
endforeach()

set(stale 0)
foreach(exemption IN LISTS exemptions)
    if(NOT exemption IN_LIST usedExemptions)
        string(REPLACE "|" ";" parts "${exemption}")
        list(GET parts 0 exemptFile)
        list(GET parts 1 rule)
        if(EXISTS "${root}/${exemptFile}")
            message("${exemptFile}: stale exemption from [${rule}]: the file no longer needs it; remove it from tests/layering/check_layering.cmake")
        else()
            message("${exemptFile}: stale exemption from [${rule}]: no such file; remove it from tests/layering/check_layering.cmake")
        endif()
        math(EXPR stale "${stale} + 1")
    endif()
endforeach()

list(LENGTH files fileCount)
if(violations GREATER 0 OR stale GREATER 0)
    message(FATAL_ERROR "layering: ${violations} violations, ${stale} stale exemptions in ${fileCount} files under ${root} (rules: tests/layering/check_layering.cmake)")
endif()
message(STATUS "layering: ${fileCount} files under ${root}, no violations")
