#include "io/rosbag_scans.hpp"

#include <cmath>
#include <limits>
#include <map>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

constexpr const char* kLaserScanType = "sensor_msgs/LaserScan";

geometry::LaserScan FromMessage(const sensor_msgs::LaserScan& msg) {
  geometry::LaserScan scan;
  scan.angle_min = msg.angle_min;
  scan.angle_max = msg.angle_max;
  scan.angle_increment = msg.angle_increment;
  scan.range_min = msg.range_min;
  scan.range_max = msg.range_max;
  scan.time_increment = msg.time_increment;
  scan.scan_time = msg.scan_time;
  scan.stamp = msg.header.stamp.toSec();
  scan.frame_id = msg.header.frame_id;
  scan.ranges.reserve(msg.ranges.size());
  for (const float r : msg.ranges) {
    // REP 117: a range outside [range_min, range_max) is not a measurement.
    const bool valid = std::isfinite(r) && r >= msg.range_min && r < msg.range_max;
    scan.ranges.push_back(valid ? static_cast<double>(r)
                                : std::numeric_limits<double>::quiet_NaN());
  }
  scan.intensities.assign(msg.intensities.begin(), msg.intensities.end());
  if (scan.intensities.size() != scan.ranges.size()) scan.intensities.clear();
  return scan;
}

}  // namespace

std::vector<BagScanTopic> ListBagScanTopics(const std::string& path) {
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    rosbag::View view(bag, rosbag::TypeQuery(kLaserScanType));
    std::map<std::string, std::size_t> counts;
    for (const rosbag::MessageInstance& m : view) ++counts[m.getTopic()];
    std::vector<BagScanTopic> topics;
    for (const auto& [topic, n] : counts) topics.push_back({topic, n});
    return topics;
  } catch (const rosbag::BagException& e) {
    throw InputError(path, "", std::string("cannot read ROS bag: ") + e.what());
  }
}

std::vector<geometry::LaserScan> ReadBagScans(const std::string& path, const std::string& topic) {
  std::vector<geometry::LaserScan> scans;
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    rosbag::View view(bag, rosbag::TypeQuery(kLaserScanType));
    for (const rosbag::MessageInstance& m : view) {
      if (!topic.empty() && m.getTopic() != topic) continue;
      const auto msg = m.instantiate<sensor_msgs::LaserScan>();
      if (msg) scans.push_back(FromMessage(*msg));
    }
  } catch (const rosbag::BagException& e) {
    throw InputError(path, "", std::string("cannot read ROS bag: ") + e.what());
  } catch (const ros::Exception& e) {
    throw InputError(path, topic, std::string("malformed LaserScan message: ") + e.what());
  }
  if (scans.empty()) {
    throw InputError(path, topic.empty() ? "topics" : topic, "no sensor_msgs/LaserScan messages");
  }
  return scans;
}

}  // namespace shelfdock::io
