# The AprilTag 36h11 reader of the code under the shelf (paper 3.5). Included by
# src/perception/CMakeLists.txt.
target_sources(shelfdock_perception PRIVATE ${CMAKE_CURRENT_LIST_DIR}/marker_detector.cpp)
target_link_libraries(shelfdock_perception PUBLIC apriltag::apriltag)
