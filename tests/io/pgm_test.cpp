#include "io/pgm.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

std::string TempPath(const std::string& name) {
  return (shelfdock::testing::ProcessTempDir().path() / ("shelfdock_pgm_" + name)).string();
}

void WriteBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(Pgm, RoundTripsEveryGreyLevel) {
  geometry::GrayImage image(256, 3);
  for (int v = 0; v < 3; ++v) {
    for (int u = 0; u < 256; ++u) image.at(u, v) = static_cast<uint8_t>((u + 7 * v) % 256);
  }
  const std::string path = TempPath("roundtrip.pgm");
  WritePgm(path, image);
  const geometry::GrayImage back = ReadPgm(path);
  EXPECT_EQ(back.width, 256);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST(Pgm, ReadsCommentsAndRescalesASmallMaxval) {
  const std::string path = TempPath("maxval.pgm");
  WriteBytes(path, std::string("P5\n# a camera dump\n2 1\n# levels\n15\n") + '\x00' + '\x0f');
  const geometry::GrayImage image = ReadPgm(path);
  ASSERT_EQ(image.pixels.size(), 2u);
  EXPECT_EQ(image.at(0, 0), 0);
  EXPECT_EQ(image.at(1, 0), 255);
}

TEST(Pgm, BadFilesNameTheFileAndTheProblem) {
  auto expect_error = [](const std::string& path, const std::string& field) {
    try {
      ReadPgm(path);
      ADD_FAILURE() << path << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  expect_error(TempPath("does_not_exist.pgm"), "");
  const std::string ascii = TempPath("ascii.pgm");
  WriteBytes(ascii, "P2\n2 1\n255\n0 255\n");
  expect_error(ascii, "header");
  const std::string truncated = TempPath("truncated.pgm");
  WriteBytes(truncated, "P5\n4 4\n255\nabc");
  expect_error(truncated, "pixels");
  const std::string deep = TempPath("deep.pgm");
  WriteBytes(deep, "P5\n1 1\n65535\n\x01\x02");
  expect_error(deep, "maxval");
  const std::string no_width = TempPath("nowidth.pgm");
  WriteBytes(no_width, "P5\nx 4\n255\n");
  expect_error(no_width, "width");
}

}  // namespace
}  // namespace shelfdock::io
