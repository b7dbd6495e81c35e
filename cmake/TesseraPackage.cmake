# Installs Tessera as a CMake package so a game can
#   find_package(Tessera REQUIRED)
#   target_link_libraries(game PRIVATE Tessera::core Tessera::gpu Tessera::assets Tessera::subdiv)
# (Tessera::assets, the glTF/Draco character loader, is optional: link it only
# to load .gltf/.glb files; Tessera::subdiv, the Catmull-Clark base surfaces,
# likewise. Both link their dependencies privately.)
include(CMakePackageConfigHelpers)

install(TARGETS tessera_core tessera_gpu tessera_assets tessera_subdiv EXPORT TesseraTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/tessera DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Host/shader layouts and shared GLSL, for games that write their own passes.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/shaders/shared/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/shaders/include/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tessera/glsl)
install(DIRECTORY ${PROJECT_BINARY_DIR}/content/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tessera/content OPTIONAL)
install(EXPORT TesseraTargets NAMESPACE Tessera:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/TesseraConfig.cmake.in
    ${PROJECT_BINARY_DIR}/TesseraConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TesseraConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TesseraConfig.cmake ${PROJECT_BINARY_DIR}/TesseraConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tessera)
