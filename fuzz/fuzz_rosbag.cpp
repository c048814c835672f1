// ROS 1 bags: listing the LaserScan topics, then reading every scan (io::ReadBagScans).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/rosbag_scans.hpp"

namespace {
void Run(const std::string& path) {
  (void)shelfdock::io::ListBagScanTopics(path);
  (void)shelfdock::io::ReadBagScans(path, "");
}
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("input.bag", Run)
