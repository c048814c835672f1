# The marker detector tests: their own executable (marker_tests), images rendered by the
# simulator's camera. Included by tests/perception/CMakeLists.txt.
add_executable(marker_tests ${CMAKE_CURRENT_LIST_DIR}/marker_detector_test.cpp)
target_link_libraries(marker_tests PRIVATE shelfdock_perception shelfdock_sim GTest::gtest_main)
shelfdock_set_warnings(marker_tests)
gtest_discover_tests(marker_tests)
