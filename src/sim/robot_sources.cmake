# The robot (diff drive, odometry, localisation, lift) and the upward camera that renders the
# code under the shelf. Included by src/sim/CMakeLists.txt.
target_sources(shelfdock_sim PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/diff_drive_robot.cpp
  ${CMAKE_CURRENT_LIST_DIR}/odometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/localisation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lift.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marker_camera.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marker_pattern.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sensor_rig.cpp
)
# PRIVATE and for one file only (marker_pattern.cpp): the rendered code's cells come from
# libapriltag's tag36h11 family table, the same table the detector decodes against, instead of
# a second hand-copied table of 587 codes. No apriltag type appears in a sim header.
target_link_libraries(shelfdock_sim PRIVATE apriltag::apriltag)
