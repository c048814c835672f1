// The ROS bag reader on bags written here: a good bag, a bag without LaserScan topics, a
// truncated (corrupt) bag, garbage, and scans the checks refuse.
#include "io/rosbag_scans.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "../common/input_error_of.hpp"
#include "../common/temp_dir.hpp"
#include "bag_writer.hpp"
#include "io/input_error.hpp"
#include "io/input_limits.hpp"

namespace shelfdock::io {
namespace {

using testing::BagLaserScan;
using testing::InputErrorOf;
using testing::TempDir;
using testing::WriteTestBag;

BagLaserScan Scan(double stamp_s, std::vector<float> ranges, const std::string& topic = "/scan") {
  BagLaserScan s;
  s.topic = topic;
  s.stamp_s = stamp_s;
  s.ranges = std::move(ranges);
  return s;
}

TEST(RosbagScansTest, ReadsEveryScanInTimeOrderWithNoReturnsAsNaN) {
  TempDir dir;
  const std::string path = dir.File("good.bag");
  BagLaserScan first = Scan(1.0, {1.0F, 0.0F, 30.0F, 2.5F, 0.01F});  // 0, >= max, < min: none
  first.intensities = {10.0F, 20.0F, 30.0F, 40.0F, 50.0F};
  WriteTestBag(path, {Scan(2.0, {3.0F, 3.0F, 3.0F}, "/rear"), first}, "/chatter");

  const auto topics = ListBagScanTopics(path);
  ASSERT_EQ(topics.size(), 2u);
  EXPECT_EQ(topics[0].topic, "/rear");
  EXPECT_EQ(topics[1].topic, "/scan");
  EXPECT_EQ(topics[1].messages, 1u);

  const auto scans = ReadBagScans(path, "");
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_DOUBLE_EQ(scans[0].stamp, 1.0);  // time order, not write order
  EXPECT_DOUBLE_EQ(scans[1].stamp, 2.0);
  const auto& s = scans[0];
  ASSERT_EQ(s.ranges.size(), 5u);
  EXPECT_DOUBLE_EQ(s.ranges[0], 1.0);
  EXPECT_TRUE(std::isnan(s.ranges[1]));
  EXPECT_TRUE(std::isnan(s.ranges[2]));
  EXPECT_DOUBLE_EQ(s.ranges[3], 2.5);
  EXPECT_TRUE(std::isnan(s.ranges[4]));
  EXPECT_EQ(s.intensities.size(), 5u);
  EXPECT_NEAR(s.angle_increment, 0.1, 1e-7);  // float in the message

  EXPECT_EQ(ReadBagScans(path, "/rear").size(), 1u);
  std::size_t streamed = 0;
  EXPECT_EQ(ForEachBagScan(path, "", [&](const geometry::LaserScan&) { ++streamed; }), 2u);
  EXPECT_EQ(streamed, 2u);
}

TEST(RosbagScansTest, BagWithoutLaserScanTopicsIsAClearError) {
  TempDir dir;
  const std::string path = dir.File("no_scans.bag");
  WriteTestBag(path, {}, "/chatter");
  EXPECT_TRUE(ListBagScanTopics(path).empty());
  const std::string error = InputErrorOf([&] { ReadBagScans(path, ""); });
  EXPECT_NE(error.find("no_scans.bag: topics: no sensor_msgs/LaserScan messages"),
            std::string::npos)
      << error;
  EXPECT_NE(InputErrorOf([&] { ReadBagScans(dir.File("good.bag"), "/none"); }).find("good.bag"),
            std::string::npos);
}

TEST(RosbagScansTest, TruncatedBagIsAClearError) {
  TempDir dir;
  const std::string path = dir.File("cut.bag");
  std::vector<BagLaserScan> scans;
  for (int i = 0; i < 50; ++i) scans.push_back(Scan(1.0 + 0.1 * i, std::vector<float>(200, 2.0F)));
  WriteTestBag(path, scans);
  const auto full = std::filesystem::file_size(path);
  // Cut inside the data, inside the index at the end, and just after the header.
  for (const std::uintmax_t size :
       {full / 2, full - 40, std::uintmax_t{4200}, std::uintmax_t{13}}) {
    std::filesystem::copy_file(path, dir.File("part.bag"),
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(dir.File("part.bag"), size);
    const std::string error = InputErrorOf([&] {
      ListBagScanTopics(dir.File("part.bag"));
      ReadBagScans(dir.File("part.bag"), "");
    });
    EXPECT_NE(error.find("part.bag"), std::string::npos) << size << ": " << error;
  }
}

TEST(RosbagScansTest, GarbageIsAClearError) {
  TempDir dir;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> byte(0, 255);
  std::string text = "#ROSBAG V2.0\n";
  for (int i = 0; i < 20000; ++i) text.push_back(static_cast<char>(byte(rng)));
  std::ofstream(dir.File("garbage.bag"), std::ios::binary) << text;
  std::ofstream(dir.File("empty.bag"), std::ios::binary) << "";
  for (const char* name : {"garbage.bag", "empty.bag", "missing.bag"}) {
    EXPECT_NE(InputErrorOf([&] { ReadBagScans(dir.File(name), ""); }).find(name), std::string::npos)
        << name;
  }
}

TEST(RosbagScansTest, ScansTheChecksRefuseNameTheTopic) {
  TempDir dir;
  BagLaserScan zero = Scan(1.0, {1.0F, 1.0F, 1.0F}, "/zero");
  zero.angle_increment = 0.0F;
  WriteTestBag(dir.File("zero.bag"), {zero});
  EXPECT_NE(InputErrorOf([&] {
              ReadBagScans(dir.File("zero.bag"), "");
            }).find("/zero[0].angle_increment: must be non-zero"),
            std::string::npos);

  BagLaserScan many = Scan(1.0, std::vector<float>(kMaxBeamsPerScan + 1, 1.0F), "/many");
  many.angle_increment = 1e-5F;
  WriteTestBag(dir.File("many.bag"), {many});
  EXPECT_NE(
      InputErrorOf([&] { ReadBagScans(dir.File("many.bag"), ""); }).find("beams exceed the limit"),
      std::string::npos);

  // Over the message size limit: refused before the message is read.
  BagLaserScan huge = Scan(1.0, std::vector<float>(kMaxBagMessageBytes / 4 + 10, 1.0F), "/huge");
  huge.angle_increment = 1e-6F;
  WriteTestBag(dir.File("huge.bag"), {huge});
  EXPECT_NE(InputErrorOf([&] { ReadBagScans(dir.File("huge.bag"), ""); }).find("exceeds the limit"),
            std::string::npos);
}

TEST(RosbagScansTest, NegativeIncrementComesBackAscending) {
  TempDir dir;
  BagLaserScan s = Scan(1.0, {1.0F, 2.0F, 3.0F});
  s.angle_min = 0.2F;
  s.angle_increment = -0.1F;
  WriteTestBag(dir.File("cw.bag"), {s});
  const auto scan = ReadBagScans(dir.File("cw.bag"), "").at(0);
  EXPECT_GT(scan.angle_increment, 0.0);
  EXPECT_NEAR(scan.angle_min, 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(scan.ranges[0], 3.0);  // the beam at angle 0
  EXPECT_DOUBLE_EQ(scan.ranges[2], 1.0);  // the beam at angle 0.2
}

}  // namespace
}  // namespace shelfdock::io
