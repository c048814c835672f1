#include "io/rosbag_scans.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include "io/bag_precheck.hpp"
#include "io/input_error.hpp"
#include "io/input_limits.hpp"
#include "io/scan_checks.hpp"

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

/// Checks the array lengths of a serialised LaserScan against its size before ROS deserialises
/// it: roscpp sizes each vector from the length field first, so a corrupt length would cost
/// gigabytes before the read fails. Layout: header (seq, stamp secs, nsecs, frame_id), seven
/// float32 (angle_min .. range_max), ranges and intensities (uint32 count + float32 each).
void CheckLaserScanLengths(const rosbag::MessageInstance& m, const std::string& path,
                           const std::string& where) {
  std::vector<std::uint8_t> bytes(m.size());
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  m.write(stream);
  std::size_t at = 0;
  const auto skip = [&](std::uint64_t n, const char* field) {
    if (n > bytes.size() - at) {
      throw InputError(path, where + "." + field, "length runs past the message's end");
    }
    at += static_cast<std::size_t>(n);
  };
  const auto count = [&](const char* field) {
    skip(4, field);
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + at - 4, 4);
    return std::uint64_t{n};
  };
  skip(12, "header");
  skip(count("header.frame_id"), "header.frame_id");
  skip(7 * 4, "angle_min");
  skip(count("ranges") * 4, "ranges");
  skip(count("intensities") * 4, "intensities");
}

}  // namespace

std::vector<BagScanTopic> ListBagScanTopics(const std::string& path) {
  PrecheckBag(path);
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

std::size_t ForEachBagScan(const std::string& path, const std::string& topic,
                           const std::function<void(const geometry::LaserScan&)>& on_scan) {
  std::size_t count = 0;
  PrecheckBag(path);
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    rosbag::View view(bag, rosbag::TypeQuery(kLaserScanType));
    for (const rosbag::MessageInstance& m : view) {
      if (!topic.empty() && m.getTopic() != topic) continue;
      if (m.size() > kMaxBagMessageBytes) {
        throw InputError(path, m.getTopic(),
                         "message of " + std::to_string(m.size()) + " bytes exceeds the limit of " +
                             std::to_string(kMaxBagMessageBytes) + " (" +
                             std::to_string(kMaxBeamsPerScan) + " beams per scan)");
      }
      const std::string where = m.getTopic() + "[" + std::to_string(count) + "]";
      CheckLaserScanLengths(m, path, where);
      const auto msg = m.instantiate<sensor_msgs::LaserScan>();
      if (!msg) continue;
      geometry::LaserScan scan = FromMessage(*msg);
      CheckScan(scan, path, where);
      MakeBeamsAscending(scan);
      on_scan(scan);
      ++count;
    }
  } catch (const rosbag::BagException& e) {
    throw InputError(path, "", std::string("cannot read ROS bag: ") + e.what());
  } catch (const ros::Exception& e) {
    throw InputError(path, topic, std::string("malformed LaserScan message: ") + e.what());
  }
  return count;
}

std::vector<geometry::LaserScan> ReadBagScans(const std::string& path, const std::string& topic) {
  std::vector<geometry::LaserScan> scans;
  ForEachBagScan(path, topic, [&scans](const geometry::LaserScan& s) { scans.push_back(s); });
  if (scans.empty()) {
    throw InputError(path, topic.empty() ? "topics" : topic, "no sensor_msgs/LaserScan messages");
  }
  return scans;
}

}  // namespace shelfdock::io
