# The marker detector tests: their own executable (marker_tests), images rendered by the
# simulator's camera. Included by tests/perception/CMakeLists.txt.
add_executable(marker_tests
  ${CMAKE_CURRENT_LIST_DIR}/marker_detector_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marker_detector_config_test.cpp
)
target_link_libraries(marker_tests PRIVATE shelfdock_perception shelfdock_sim GTest::gtest_main)
shelfdock_set_warnings(marker_tests)
gtest_discover_tests(marker_tests)

# The `marker` CLI: render -> PGM -> detect, and bad inputs (exit codes 0 / 1 / 2).
if(TARGET shelfdock)
  add_test(NAME perception_marker_cli
           COMMAND ${CMAKE_COMMAND} -DSHELFDOCK=$<TARGET_FILE:shelfdock>
                   -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}
                   -P ${CMAKE_CURRENT_LIST_DIR}/marker_cli_test.cmake)
endif()
