# tessera_add_backend_plugin(<name> SOURCES ... [LIBRARIES ...] [NO_INSTALL]):
# builds backend plugin <name>
# as the shared module tessera_backend_<name>.so in <libdir>/tessera/, the
# folder the plugin loader searches next to libtessera_core.so. Only the entry point is
# exported (hidden visibility), so plugins cannot clash with each other.
function(tessera_add_backend_plugin name)
    cmake_parse_arguments(ARG "NO_INSTALL" "" "SOURCES;LIBRARIES" ${ARGN})
    set(target tessera_backend_${name})
    add_library(${target} MODULE ${ARG_SOURCES})
    set_target_properties(${target} PROPERTIES
        PREFIX ""
        OUTPUT_NAME tessera_backend_${name}
        LIBRARY_OUTPUT_DIRECTORY ${TESSERA_PLUGIN_OUTPUT_DIR}
        CXX_VISIBILITY_PRESET hidden
        VISIBILITY_INLINES_HIDDEN ON
        BUILD_RPATH "$ORIGIN/.."
        INSTALL_RPATH "$ORIGIN/..")
    target_link_libraries(${target} PRIVATE ${ARG_LIBRARIES})
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
    tessera_set_warnings(${target})
    if(NOT ARG_NO_INSTALL)
        install(TARGETS ${target} LIBRARY DESTINATION ${TESSERA_PLUGIN_INSTALL_DIR})
    endif()
    set_property(GLOBAL APPEND PROPERTY TESSERA_BACKEND_PLUGINS ${target})
endfunction()
