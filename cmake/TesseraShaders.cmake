# Shader compilation at build time, so a shader error fails the build with
# glslang's "ERROR: <file>:<line>: ..." instead of failing the running demo.
#
#   tessera_add_shaders(<target>
#       SOURCES a.vert b.frag ...       # one stage per file suffix
#       [VARIANT <suffix> DEFINES A=1 B ...])  # optional #define variant
#
# Each source becomes <binary dir>/spirv/<name>[_<suffix>].spv.h holding
# `const uint32_t <ident>_spv[]`, where <ident> is the file name with '.' as
# '_' (terrain.vert -> terrain_vert_spv). The headers are embedded in the
# module that uses them: no shader files to find at run time.
# Includes generated at build time (tools/osdglsl: OpenSubdiv's patch basis).
set(TESSERA_GENERATED_GLSL_DIR ${PROJECT_BINARY_DIR}/generated/glsl)
set(TESSERA_SHADER_INCLUDE_DIRS
    ${PROJECT_SOURCE_DIR}/engine/shaders
    ${PROJECT_SOURCE_DIR}/engine/core/include
    ${TESSERA_GENERATED_GLSL_DIR}
    CACHE INTERNAL "Shared GLSL include directories")

function(tessera_add_shaders target)
    cmake_parse_arguments(ARG "" "VARIANT" "SOURCES;DEFINES" ${ARGN})
    set(outdir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
    file(MAKE_DIRECTORY ${outdir})
    set(flags -V --target-env vulkan1.3 -g)
    foreach(dir ${TESSERA_SHADER_INCLUDE_DIRS})
        list(APPEND flags -I${dir})
    endforeach()
    foreach(def ${ARG_DEFINES})
        list(APPEND flags -D${def})
    endforeach()
    set(outputs)
    foreach(src ${ARG_SOURCES})
        get_filename_component(abs ${src} ABSOLUTE)
        get_filename_component(name ${src} NAME)
        if(ARG_VARIANT)
            set(name ${name}_${ARG_VARIANT})
        endif()
        string(MAKE_C_IDENTIFIER ${name} ident)
        set(out ${outdir}/${name}.spv.h)
        add_custom_command(
            OUTPUT ${out}
            COMMAND Vulkan::glslangValidator ${flags} --vn ${ident}_spv --depfile ${out}.d -o ${out} ${abs}
            DEPENDS ${abs} Vulkan::glslangValidator
            DEPFILE ${out}.d
            COMMENT "glslang ${name}"
            VERBATIM)
        list(APPEND outputs ${out})
    endforeach()
    set(shaderTarget ${target}_shaders)
    if(ARG_VARIANT)
        set(shaderTarget ${target}_shaders_${ARG_VARIANT})
    endif()
    add_custom_target(${shaderTarget} DEPENDS ${outputs})
    # Any shader may include the generated OpenSubdiv basis; its depfile
    # tracks the include once it exists, this makes it exist first.
    add_dependencies(${shaderTarget} tessera_osd_glsl)
    add_dependencies(${target} ${shaderTarget})
    target_include_directories(${target} PRIVATE ${outdir})
endfunction()
