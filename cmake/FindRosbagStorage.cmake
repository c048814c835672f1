# Finds Debian's ROS 1 rosbag_storage (package librosbag-storage-dev) and the sensor_msgs headers
# without catkin or ament: their own CMake configs need ROS's Python tooling at configure time.
# Defines the imported target Rosbag::storage.
find_path(RosbagStorage_INCLUDE_DIR rosbag/bag.h)
find_path(RosbagStorage_PLUGINLIB_DIR pluginlib/class_loader.hpp PATH_SUFFIXES pluginlib)
find_path(RosbagStorage_CLASS_LOADER_DIR class_loader/class_loader.hpp PATH_SUFFIXES class_loader)
find_path(RosbagStorage_RCUTILS_DIR rcutils/types.h PATH_SUFFIXES rcutils)
find_path(RosbagStorage_RCPPUTILS_DIR rcpputils/shared_library.hpp PATH_SUFFIXES rcpputils)
find_path(RosbagStorage_AMENT_INDEX_DIR ament_index_cpp/get_package_prefix.hpp
          PATH_SUFFIXES ament_index_cpp)
find_path(RosbagStorage_SENSOR_MSGS_DIR sensor_msgs/LaserScan.h)
find_library(RosbagStorage_LIBRARY rosbag_storage)
set(_rosbag_deps console_bridge boost_filesystem roslz4 rostime roscpp_serialization cpp_common)
set(_rosbag_dep_libs)
foreach(dep ${_rosbag_deps})
  find_library(RosbagStorage_${dep}_LIBRARY ${dep})
  list(APPEND _rosbag_dep_libs ${RosbagStorage_${dep}_LIBRARY})
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(RosbagStorage
  REQUIRED_VARS RosbagStorage_LIBRARY RosbagStorage_INCLUDE_DIR RosbagStorage_PLUGINLIB_DIR
                RosbagStorage_CLASS_LOADER_DIR RosbagStorage_RCUTILS_DIR
                RosbagStorage_RCPPUTILS_DIR RosbagStorage_AMENT_INDEX_DIR
                RosbagStorage_SENSOR_MSGS_DIR RosbagStorage_console_bridge_LIBRARY
                RosbagStorage_roscpp_serialization_LIBRARY)

if(RosbagStorage_FOUND AND NOT TARGET Rosbag::storage)
  add_library(Rosbag::storage UNKNOWN IMPORTED)
  set_target_properties(Rosbag::storage PROPERTIES
    IMPORTED_LOCATION ${RosbagStorage_LIBRARY}
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
      "${RosbagStorage_INCLUDE_DIR};${RosbagStorage_PLUGINLIB_DIR};${RosbagStorage_CLASS_LOADER_DIR};${RosbagStorage_RCUTILS_DIR};${RosbagStorage_RCPPUTILS_DIR};${RosbagStorage_AMENT_INDEX_DIR};${RosbagStorage_SENSOR_MSGS_DIR}"
    INTERFACE_INCLUDE_DIRECTORIES
      "${RosbagStorage_INCLUDE_DIR};${RosbagStorage_PLUGINLIB_DIR};${RosbagStorage_CLASS_LOADER_DIR};${RosbagStorage_RCUTILS_DIR};${RosbagStorage_RCPPUTILS_DIR};${RosbagStorage_AMENT_INDEX_DIR};${RosbagStorage_SENSOR_MSGS_DIR}"
    INTERFACE_LINK_LIBRARIES "${_rosbag_dep_libs}")
endif()
mark_as_advanced(RosbagStorage_INCLUDE_DIR RosbagStorage_LIBRARY)
