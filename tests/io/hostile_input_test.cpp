// Hostile scan inputs (issue 10): each is a clear InputError naming the file and what is wrong,
// or a clean empty result, and the work done before the answer is bounded by the documented
// limits (io/input_limits.hpp), not by the size of the input. Work is bounded structurally:
// streams count the bytes the reader took, files are far larger than what may be read.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <streambuf>
#include <string>

#include <gtest/gtest.h>

#include "../common/input_error_of.hpp"
#include "../common/paper_models.hpp"
#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"
#include "io/input_limits.hpp"
#include "io/scan_json.hpp"
#include "io/scan_line_reader.hpp"
#include "perception/detector.hpp"

namespace shelfdock::io {
namespace {

using testing::InputErrorOf;
using testing::TempDir;

const std::string kData = std::string(SHELFDOCK_SOURCE_DIR) + "/tests/data/";

/// A stream of `size` bytes made up on demand: `head`, then `filler` repeated. Counts what the
/// reader took, so a test can show that a reader stopped early without holding gigabytes.
class GeneratedStreamBuf : public std::streambuf {
 public:
  GeneratedStreamBuf(std::string head, std::string filler, std::uint64_t size)
      : head_(std::move(head)), filler_(std::move(filler)), size_(size) {
    chunk_.resize(1 << 16);
  }
  std::uint64_t served() const { return served_; }

 protected:
  int_type underflow() override {
    if (served_ >= size_) return traits_type::eof();
    const auto n =
        static_cast<std::size_t>(std::min<std::uint64_t>(chunk_.size(), size_ - served_));
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t at = served_ + i;
      chunk_[i] = at < head_.size() ? head_[at] : filler_[(at - head_.size()) % filler_.size()];
    }
    served_ += n;
    setg(chunk_.data(), chunk_.data(), chunk_.data() + n);
    return traits_type::to_int_type(chunk_[0]);
  }

 private:
  std::string head_, filler_;
  std::uint64_t size_;
  std::uint64_t served_ = 0;
  std::string chunk_;
};

std::string ScanLineJson(std::size_t beams, const std::string& range = "1.5",
                         double increment = 0.01) {
  std::ostringstream out;
  out.precision(17);
  out << R"({"angle_min":-1.0,"angle_max":)" << -1.0 + increment * static_cast<double>(beams - 1)
      << R"(,"angle_increment":)" << increment
      << R"(,"range_min":0.05,"range_max":25.0,"ranges":[)";
  for (std::size_t i = 0; i < beams; ++i) out << (i ? "," : "") << range;
  out << "]}";
  return out.str();
}

std::string WriteFile(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.File(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(HostileInputTest, TenMillionBeamLineStopsAtTheLineLimit) {
  // 10 M beams of "1.5," would be 40 MB: the reader gives up after one line limit.
  GeneratedStreamBuf buf(R"({"angle_min":-1,"angle_max":1,"angle_increment":2e-7,"ranges":[)",
                         "1.5,", 40'000'000);
  std::istream in(&buf);
  ScanLineReader reader(in, "(stdin)");
  const auto line = reader.Next();
  ASSERT_TRUE(line.has_value());
  EXPECT_FALSE(line->scan.has_value());
  ASSERT_TRUE(line->error.has_value());
  EXPECT_NE(std::string(line->error->what()).find("(stdin): line 1: longer than"),
            std::string::npos)
      << line->error->what();
  EXPECT_LE(buf.served(), kMaxScanLineBytes + (1 << 16));
}

TEST(HostileInputTest, TenMillionBeamDocumentStopsAtTheArrayLimit) {
  // The same scan as one pretty-printed document: parsing stops at the array limit.
  TempDir dir;
  constexpr std::size_t kBeams = 10'000'000;
  std::string text = "{\n\"angle_min\": -1, \"angle_max\": 1, \"angle_increment\": 2e-7,\n" +
                     std::string("\"range_min\": 0.05, \"range_max\": 25, \"ranges\": [");
  text.reserve(text.size() + 2 * kBeams + 2);
  for (std::size_t i = 0; i < kBeams; ++i) text += "1,";
  text.back() = ']';
  text += "}";
  const std::string path = WriteFile(dir, "ten_million.json", text);
  const std::string error = InputErrorOf([&] { ReadScans(path); });
  EXPECT_NE(error.find("ten_million.json"), std::string::npos) << error;
  EXPECT_NE(error.find("more than " + std::to_string(kMaxJsonArrayElements)), std::string::npos)
      << error;
}

TEST(HostileInputTest, BeamsOverTheLimitAreRejectedAndAtTheLimitAccepted) {
  TempDir dir;
  const std::string over = WriteFile(dir, "over.jsonl", ScanLineJson(kMaxBeamsPerScan + 1, "1"));
  EXPECT_NE(InputErrorOf([&] { ReadScans(over); }).find("more than"), std::string::npos);
  const std::string at = WriteFile(dir, "at.jsonl", ScanLineJson(kMaxBeamsPerScan, "1", 1e-5));
  const auto scans = ReadScans(at);
  ASSERT_EQ(scans.size(), 1u);
  EXPECT_EQ(scans[0].ranges.size(), kMaxBeamsPerScan);
}

TEST(HostileInputTest, AllNaNScanIsACleanEmptyResult) {
  TempDir dir;
  const std::string path = WriteFile(dir, "nan.jsonl", ScanLineJson(811, "null"));
  const auto scans = ReadScans(path);
  ASSERT_EQ(scans.size(), 1u);
  for (double r : scans[0].ranges) EXPECT_TRUE(std::isnan(r));
  const perception::Detector detector(testing::PaperModels(), perception::DetectorConfig{});
  const perception::DetectionResult result = detector.Detect(scans[0], std::nullopt, false);
  EXPECT_TRUE(result.detections.empty());
  EXPECT_EQ(result.stats.valid_points, 0);
}

TEST(HostileInputTest, WrongLengthsNameTheField) {
  TempDir dir;
  // 11 ranges where the angles say 21.
  std::string few = ScanLineJson(21);
  few = few.substr(0, few.find("\"ranges\"")) + R"("ranges":[1,1,1,1,1,1,1,1,1,1,1]})";
  EXPECT_NE(InputErrorOf([&] { ReadScans(WriteFile(dir, "few.jsonl", few)); })
                .find("line 1.ranges: holds 11 beams but angle_min/angle_max/angle_increment "
                      "imply 21"),
            std::string::npos);
  std::string intensities = ScanLineJson(5);
  intensities.insert(intensities.size() - 1, R"(,"intensities":[1,2,3])");
  EXPECT_NE(InputErrorOf([&] {
              ReadScans(WriteFile(dir, "int.jsonl", intensities));
            }).find("line 1.intensities: length differs from ranges"),
            std::string::npos);
}

TEST(HostileInputTest, ZeroIncrementIsAnError) {
  TempDir dir;
  const std::string path = WriteFile(
      dir, "zero.jsonl",
      R"({"angle_min":0,"angle_max":0,"angle_increment":0,"range_min":0.05,"range_max":25,"ranges":[1,2,3]})");
  EXPECT_NE(InputErrorOf([&] { ReadScans(path); }).find("line 1.angle_increment: must be non-zero"),
            std::string::npos);
}

TEST(HostileInputTest, NegativeIncrementAgainstTheAnglesIsAnError) {
  TempDir dir;
  // angle_max > angle_min but a negative increment: the angles imply a negative beam count.
  const std::string path = WriteFile(
      dir, "neg.jsonl",
      R"({"angle_min":-1,"angle_max":-0.98,"angle_increment":-0.01,"range_min":0.05,"range_max":25,"ranges":[1,2,3]})");
  EXPECT_NE(InputErrorOf([&] { ReadScans(path); }).find("line 1.ranges: holds 3 beams"),
            std::string::npos);
}

TEST(HostileInputTest, ReversedScanWithNegativeIncrementGivesTheSameDetections) {
  // A LiDAR mounted upside down sweeps clockwise: the example scan written from its last beam
  // to its first must find the same shelf at the same pose.
  auto forward = ReadScans(kData + "example_scan.json").at(0);
  geometry::LaserScan reversed = forward;
  const double n_minus_1 = static_cast<double>(forward.ranges.size() - 1);
  reversed.angle_min = forward.angle_min + n_minus_1 * forward.angle_increment;
  reversed.angle_max = forward.angle_min;
  reversed.angle_increment = -forward.angle_increment;
  std::reverse(reversed.ranges.begin(), reversed.ranges.end());
  std::reverse(reversed.intensities.begin(), reversed.intensities.end());
  TempDir dir;
  const std::string path = WriteFile(dir, "reversed.jsonl", ScanToJson(reversed).dump());
  const auto read = ReadScans(path).at(0);
  EXPECT_GT(read.angle_increment, 0.0);
  EXPECT_NEAR(read.angle_min, forward.angle_min, 1e-12);
  ASSERT_EQ(read.ranges.size(), forward.ranges.size());
  for (std::size_t i = 0; i < read.ranges.size(); ++i) {
    if (std::isnan(forward.ranges[i])) {
      EXPECT_TRUE(std::isnan(read.ranges[i]));
    } else {
      EXPECT_DOUBLE_EQ(read.ranges[i], forward.ranges[i]) << i;
    }
  }
  const perception::Detector detector(testing::PaperModels(), perception::DetectorConfig{});
  const auto a = detector.Detect(forward, std::nullopt, false).detections;
  const auto b = detector.Detect(read, std::nullopt, false).detections;
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a[0].model, b[0].model);
  // Beam angles are recomputed from the other end: equal to rounding, far below a millimetre.
  EXPECT_NEAR(a[0].T_lidar_shelf.x, b[0].T_lidar_shelf.x, 1e-6);
  EXPECT_NEAR(a[0].T_lidar_shelf.y, b[0].T_lidar_shelf.y, 1e-6);
  EXPECT_NEAR(a[0].T_lidar_shelf.yaw, b[0].T_lidar_shelf.yaw, 1e-6);
}

/// A sparse file of `size` bytes starting with `head` (the rest reads as zero bytes).
std::string SparseFile(const TempDir& dir, const std::string& name, const std::string& head,
                       std::uintmax_t size) {
  const std::string path = WriteFile(dir, name, head);
  std::filesystem::resize_file(path, size);
  return path;
}

TEST(HostileInputTest, OneGigabyteFilesAreRejectedBeforeTheyAreRead) {
  constexpr std::uintmax_t kGigabyte = std::uintmax_t{1} << 30;
  TempDir dir;
  // Zero bytes: not JSON at all, known from the first byte.
  const std::string zeros = SparseFile(dir, "zeros.json", "", kGigabyte);
  EXPECT_NE(InputErrorOf([&] { ReadScans(zeros); }).find("line 1: expected a scan object"),
            std::string::npos);
  // An array document: refused from its size alone.
  const std::string array = SparseFile(dir, "array.json", "[", kGigabyte);
  EXPECT_NE(InputErrorOf([&] { ReadScans(array); }).find("a JSON document over"),
            std::string::npos);
  // One endless line: refused at the line limit.
  const std::string line = SparseFile(dir, "line.jsonl", R"({"angle_min":0,"ranges":[)", kGigabyte);
  EXPECT_NE(InputErrorOf([&] { ReadScans(line); }).find("line 1: longer than"), std::string::npos);
}

TEST(HostileInputTest, BinaryGarbageIsAnError) {
  TempDir dir;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const char* head : {"", "{", "["}) {
    std::string text = head;
    for (int i = 0; i < 100000; ++i) text.push_back(static_cast<char>(byte(rng)));
    const std::string path = WriteFile(dir, "garbage.bin", text);
    EXPECT_NE(InputErrorOf([&] { ReadScans(path); }).find("garbage.bin"), std::string::npos)
        << head;
  }
}

TEST(HostileInputTest, StreamReportsABadLineAndGoesOn) {
  std::istringstream in(ScanLineJson(5) + "\n\x01\x02garbage\n\n" + ScanLineJson(5) + "\n" +
                        ScanLineJson(5).substr(0, 40));
  ScanLineReader reader(in, "(stdin)");
  std::vector<int> good, bad;
  while (const auto line = reader.Next()) (line->scan ? good : bad).push_back(line->line);
  EXPECT_EQ(good, (std::vector<int>{1, 4}));
  EXPECT_EQ(bad, (std::vector<int>{2, 5}));  // line 3 is blank; 5 is cut short
}

TEST(HostileInputTest, StreamGoesOnAfterALineOverTheLimit) {
  std::string text = ScanLineJson(3) + "\n[" + std::string(kMaxScanLineBytes + 100000, '1') +
                     "]\n" + ScanLineJson(4) + "\n";
  std::istringstream in(text);
  ScanLineReader reader(in, "(stdin)");
  const auto first = reader.Next();
  const auto second = reader.Next();
  const auto third = reader.Next();
  ASSERT_TRUE(first && second && third);
  EXPECT_TRUE(first->scan.has_value());
  EXPECT_FALSE(second->scan.has_value());
  EXPECT_EQ(second->line, 2);
  ASSERT_TRUE(third->scan.has_value());
  EXPECT_EQ(third->line, 3);
  EXPECT_EQ(third->scan->ranges.size(), 4u);
  EXPECT_FALSE(reader.Next().has_value());
}

}  // namespace
}  // namespace shelfdock::io
