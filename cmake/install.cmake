# `cmake --install` puts headers, libraries, the polyplan program and a package config in the
# prefix, so that find_package(polyplan) + target_link_libraries(app polyplan::polyplan) works.
include(CMakePackageConfigHelpers)

install(TARGETS polyplan ${POLYPLAN_FOLDER_LIBRARIES}
  EXPORT polyplanTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS polyplan_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Public headers only: the detail/ folders hold CGAL and nlohmann code that users never include.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/polyplan/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/polyplan
  FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/polyplan)
install(EXPORT polyplanTargets NAMESPACE polyplan:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/polyplanConfig.cmake.in
  ${PROJECT_BINARY_DIR}/polyplanConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/polyplanConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/polyplanConfig.cmake ${PROJECT_BINARY_DIR}/polyplanConfigVersion.cmake
  DESTINATION ${config_dir})
