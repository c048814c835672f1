# Tests of the camera and robot file readers and the PGM images (camera engineer): their own
# executable, camera_io_tests. Included by tests/io/CMakeLists.txt.
add_executable(camera_io_tests
  ${CMAKE_CURRENT_LIST_DIR}/pgm_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camera_yaml_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_yaml_test.cpp
)
target_link_libraries(camera_io_tests PRIVATE shelfdock_io GTest::gtest_main)
target_compile_definitions(camera_io_tests PRIVATE SHELFDOCK_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
shelfdock_set_warnings(camera_io_tests)
gtest_discover_tests(camera_io_tests)
