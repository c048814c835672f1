# The robot and camera tests: their own executable (sim_robot_tests) so they build and run
# independently of the world/LiDAR tests. Included by tests/sim/CMakeLists.txt.
add_executable(sim_robot_tests
  ${CMAKE_CURRENT_LIST_DIR}/diff_drive_robot_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/odometry_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/localisation_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lift_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marker_camera_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marker_camera_config_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_config_test.cpp
)
target_link_libraries(sim_robot_tests PRIVATE shelfdock_sim GTest::gtest_main)
shelfdock_set_warnings(sim_robot_tests)
gtest_discover_tests(sim_robot_tests)
