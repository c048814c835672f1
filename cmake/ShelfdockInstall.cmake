# `cmake --install`: the libraries, their public headers, the CLI, the default configs and a CMake
# package, so that another project can do
#   find_package(shelfdock REQUIRED)
#   target_link_libraries(app PRIVATE shelfdock::perception)
# Layout under the prefix:
#   lib/libshelfdock_*.a                 the layers (static)
#   include/shelfdock/<layer>/*.hpp      headers, included as "perception/detector.hpp"
#   bin/shelfdock                        the CLI
#   share/shelfdock/config/              models, detector, lidar, robot, camera, docking, scenarios
#   lib/cmake/shelfdock/                 shelfdockConfig.cmake, targets, version
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SHELFDOCK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/shelfdock)
set(SHELFDOCK_INSTALL_CONFIGDIR ${CMAKE_INSTALL_DATADIR}/shelfdock/config)

# The layers' include directory is the source tree's src/ while building; once installed it is
# include/shelfdock. The layers' own CMakeLists name ${PROJECT_SOURCE_DIR}/src plainly, so the
# property is rewritten here rather than in six files.
set(_shelfdock_layers geometry perception sim docking eval io io_rosbag)
foreach(layer ${_shelfdock_layers})
  set(target shelfdock_${layer})
  set_target_properties(${target} PROPERTIES
    EXPORT_NAME ${layer}
    INTERFACE_INCLUDE_DIRECTORIES
      "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>;$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/shelfdock>")
  add_library(shelfdock::${layer} ALIAS ${target})
  install(TARGETS ${target} EXPORT shelfdockTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endforeach()

install(TARGETS shelfdock RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

foreach(layer geometry perception sim docking eval io)
  install(DIRECTORY src/${layer}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shelfdock/${layer}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

install(DIRECTORY config/ DESTINATION ${SHELFDOCK_INSTALL_CONFIGDIR})

install(EXPORT shelfdockTargets NAMESPACE shelfdock:: DESTINATION ${SHELFDOCK_INSTALL_CMAKEDIR})
configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/shelfdockConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shelfdockConfig.cmake
  INSTALL_DESTINATION ${SHELFDOCK_INSTALL_CMAKEDIR}
  PATH_VARS SHELFDOCK_INSTALL_CONFIGDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shelfdockConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shelfdockConfig.cmake
              ${PROJECT_BINARY_DIR}/shelfdockConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindRosbagStorage.cmake
        DESTINATION ${SHELFDOCK_INSTALL_CMAKEDIR})
