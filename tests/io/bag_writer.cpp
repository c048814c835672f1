#include "bag_writer.hpp"

#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>

namespace shelfdock::testing {

void WriteTestBag(const std::string& path, const std::vector<BagLaserScan>& scans,
                  const std::string& string_topic) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (const BagLaserScan& s : scans) {
    sensor_msgs::LaserScan msg;
    msg.header.stamp = ros::Time(s.stamp_s);
    msg.header.frame_id = "lidar";
    msg.angle_min = s.angle_min;
    msg.angle_increment = s.angle_increment;
    msg.angle_max =
        s.angle_min +
        s.angle_increment * static_cast<float>(s.ranges.empty() ? 0 : s.ranges.size() - 1);
    msg.range_min = s.range_min;
    msg.range_max = s.range_max;
    msg.ranges = s.ranges;
    msg.intensities = s.intensities;
    bag.write(s.topic, msg.header.stamp, msg);
  }
  if (!string_topic.empty()) {
    std_msgs::String text;
    text.data = "not a scan";
    bag.write(string_topic, ros::Time(2.0), text);
  }
  bag.close();
}

}  // namespace shelfdock::testing
