# Installs Tessera as a CMake package so a game can
#   find_package(Tessera REQUIRED)
#   target_link_libraries(game PRIVATE Tessera::runtime)
# Tessera::runtime (backend and device selection, the frame loop, the world,
# captures, benchmarks) brings Tessera::subdiv and Tessera::core; its headers
# need no Vulkan headers (the GPU layer, Tessera::gpu, and the asset loaders,
# Tessera::assets, are its private dependencies). A game that writes its own
# host links Tessera::gpu and the others alone. Tessera::assets (glTF/Draco)
# and Tessera::subdiv (OpenSubdiv) link their dependencies privately.
# For a game's command line: Tessera::cli, the parser every Tessera program
# uses (CLI11), and Tessera::demo_cli, tessera-demo's own flags into
# runtime::Options (tessera/demo/CommandLine.h) with its names for the
# runtime's settings (tessera/demo/SettingFlags.h). examples/embed is such a
# game; the README's "Using Tessera in your game"
# describes it.
include(CMakePackageConfigHelpers)

install(TARGETS tessera_core tessera_gpu tessera_assets tessera_subdiv tessera_runtime tessera_cli tessera_demo_cli
    EXPORT TesseraTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Public headers, the host/shader layouts among them (tessera/shaders/), all
# under include/tessera so none can collide with a game's own.
foreach(library core subdiv assets gpu)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/${library}/include/tessera DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/include/tessera ${PROJECT_SOURCE_DIR}/tools/cli/include/tessera
    ${PROJECT_SOURCE_DIR}/game_sample/cli/include/tessera DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Shared GLSL for games that write their own passes (compile with
# -I<prefix>/share/tessera/glsl -I<prefix>/include).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tessera/glsl FILES_MATCHING PATTERN "*.glsl")
# ... with the one they include that the build generates (OpenSubdiv's patch basis, tools/osdglsl).
install(FILES ${TESSERA_GENERATED_GLSL_DIR}/osd_patch_basis.glsl DESTINATION ${CMAKE_INSTALL_DATADIR}/tessera/glsl)
install(DIRECTORY ${PROJECT_BINARY_DIR}/content/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tessera/content OPTIONAL
    PATTERN CMakeFiles EXCLUDE PATTERN "*.cmake" EXCLUDE)
install(EXPORT TesseraTargets NAMESPACE Tessera:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera)

set(TESSERA_PACKAGE_PLUGIN_DIR ${CMAKE_INSTALL_LIBDIR}/tessera)
set(TESSERA_PACKAGE_CONTENT_DIR ${CMAKE_INSTALL_DATADIR}/tessera/content)
set(TESSERA_PACKAGE_GLSL_DIR ${CMAKE_INSTALL_DATADIR}/tessera/glsl)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/TesseraConfig.cmake.in
    ${PROJECT_BINARY_DIR}/TesseraConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera
    PATH_VARS TESSERA_PACKAGE_PLUGIN_DIR TESSERA_PACKAGE_CONTENT_DIR TESSERA_PACKAGE_GLSL_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TesseraConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TesseraConfig.cmake ${PROJECT_BINARY_DIR}/TesseraConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera)
