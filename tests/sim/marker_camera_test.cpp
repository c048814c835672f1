#include "sim/marker_camera.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "sim/marker_pattern.hpp"

namespace shelfdock::sim {
namespace {

/// An ideal camera: one sample per pixel, no blur, no noise, so pixel values are exact levels.
CameraConfig IdealCamera() {
  CameraConfig c;
  c.supersample = 1;
  c.blur_sigma_px = 0.0;
  c.noise_std = 0.0;
  return c;
}

/// Pixel where a point of the code plane at camera-frame (x, y) projects (UpwardCamera frames).
Eigen::Vector2d Project(const CameraConfig& c, const Eigen::Vector2d& p_camera) {
  const auto& k = c.camera.intrinsics;
  return {k.cx_px + k.fx_px * p_camera.y() / c.camera.code_height_m,
          k.cy_px - k.fy_px * p_camera.x() / c.camera.code_height_m};
}

/// Centre of cell (col, row) of the printed code, in the code's planar frame: printed right is
/// the tag's +y, printed down its -x.
Eigen::Vector2d CellCentreInTag(const CameraConfig& c, const MarkerPattern& p, int col, int row) {
  const double cell = c.camera.code_size_m / p.border_cells;
  const double half = 0.5 * p.total_cells * cell;
  return {half - (row + 0.5) * cell, -half + (col + 0.5) * cell};
}

TEST(MarkerPattern, Tag36h11HasABlackBorderInAWhiteQuietZone) {
  EXPECT_EQ(MarkerFamilySize(), 587);
  const MarkerPattern p = MarkerPatternFor(0);
  ASSERT_EQ(p.total_cells, 10);
  ASSERT_EQ(p.border_cells, 8);
  for (int i = 0; i < 10; ++i) {
    EXPECT_TRUE(p.IsWhite(i, 0) && p.IsWhite(i, 9) && p.IsWhite(0, i) && p.IsWhite(9, i));
    EXPECT_FALSE(i >= 1 && i <= 8 && (p.IsWhite(i, 1) || p.IsWhite(i, 8) || p.IsWhite(1, i)));
  }
  // Different ids differ in at least 11 of the 36 data cells (the family's hamming distance).
  const MarkerPattern q = MarkerPatternFor(1);
  int differing = 0;
  for (int row = 2; row < 8; ++row) {
    for (int col = 2; col < 8; ++col) differing += p.IsWhite(col, row) != q.IsWhite(col, row);
  }
  EXPECT_GE(differing, 11);
}

TEST(RenderMarker, EveryCellLandsWhereThePinholeModelPutsIt) {
  const CameraConfig c = IdealCamera();
  const int id = 17;
  const MarkerPattern pattern = MarkerPatternFor(id);
  for (const geometry::Pose2& T_camera_tag :
       {geometry::Pose2(), geometry::Pose2(0.03, -0.02, 0.4), geometry::Pose2(-0.05, 0.05, -2.9)}) {
    const geometry::GrayImage image = RenderMarker(c, id, T_camera_tag, 1);
    ASSERT_EQ(image.width, c.camera.intrinsics.width_px);
    ASSERT_EQ(image.height, c.camera.intrinsics.height_px);
    for (int row = 0; row < pattern.total_cells; ++row) {
      for (int col = 0; col < pattern.total_cells; ++col) {
        const Eigen::Vector2d uv = Project(c, T_camera_tag * CellCentreInTag(c, pattern, col, row));
        const int u = static_cast<int>(std::lround(uv.x()));
        const int v = static_cast<int>(std::lround(uv.y()));
        const double expected = pattern.IsWhite(col, row) ? c.white_level : c.black_level;
        EXPECT_NEAR(image.at(u, v), expected, 0.5) << "cell " << col << "," << row;
      }
    }
    EXPECT_NEAR(image.at(0, 0), c.background_level, 0.5);
  }
}

TEST(RenderMarker, CodeForwardOfTheRobotAppearsAtTheTopOfTheImage) {
  // 10 cm ahead of the camera at 0.30 m: 500 * 0.1 / 0.3 = 167 px above the image centre.
  const CameraConfig c = IdealCamera();
  const geometry::GrayImage image = RenderMarker(c, 0, geometry::Pose2(0.10, 0.0, 0.0), 1);
  const int v_centre = static_cast<int>(std::lround(
      c.camera.intrinsics.cy_px - c.camera.intrinsics.fy_px * 0.10 / c.camera.code_height_m));
  // On the image row through the code's centre, the black border's left column (cell column
  // 1, 3.5 cells left of the centre) is black; the top of the image shows the shelf.
  const double cell_px =
      c.camera.intrinsics.fx_px * c.camera.code_size_m / 8.0 / c.camera.code_height_m;
  const int u_left_border =
      static_cast<int>(std::lround(c.camera.intrinsics.cx_px - 3.5 * cell_px));
  EXPECT_NEAR(image.at(u_left_border, v_centre), c.black_level, 0.5);
  const int v_below = v_centre + static_cast<int>(std::lround(6.0 * cell_px));  // past the code
  EXPECT_NEAR(image.at(static_cast<int>(c.camera.intrinsics.cx_px), v_below), c.background_level,
              0.5);
}

TEST(RenderMarker, OutOfViewShowsOnlyBackgroundAndPartialViewsAreCut) {
  const CameraConfig c = IdealCamera();
  const geometry::GrayImage away = RenderMarker(c, 3, geometry::Pose2(1.0, 1.0, 0.0), 1);
  for (const uint8_t pixel : away.pixels) ASSERT_NEAR(pixel, c.background_level, 0.5);

  // Looking up mirrors left and right: the robot's left (+y) is the image's right. Half the
  // image width to the left, the code's centre sits on the image's right edge.
  const double y_edge =
      c.camera.intrinsics.cx_px / c.camera.intrinsics.fx_px * c.camera.code_height_m;
  const geometry::GrayImage half = RenderMarker(c, 3, geometry::Pose2(0.0, y_edge, 0.0), 1);
  int dark = 0;
  for (int v = 0; v < half.height; ++v)
    dark += half.at(half.width - 1, v) < c.background_level - 10;
  EXPECT_GT(dark, 20);  // the border crosses the image edge
}

TEST(RenderMarker, NoiseAndBlurBehave) {
  CameraConfig c;
  c.noise_std = 3.0;
  const geometry::Pose2 pose(0.01, 0.02, 0.3);
  const geometry::GrayImage a = RenderMarker(c, 5, pose, 11);
  const geometry::GrayImage b = RenderMarker(c, 5, pose, 11);
  const geometry::GrayImage other_seed = RenderMarker(c, 5, pose, 12);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_NE(a.pixels, other_seed.pixels);

  // Background noise: std of the top-left 50 x 50 block matches noise_std (rounding adds 1/12).
  double sum = 0.0, sum_sq = 0.0;
  for (int v = 0; v < 50; ++v) {
    for (int u = 0; u < 50; ++u) {
      sum += a.at(u, v);
      sum_sq += a.at(u, v) * a.at(u, v);
    }
  }
  const double n = 2500.0, mean = sum / n;
  const double std = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(mean, c.background_level, 0.3);
  EXPECT_NEAR(std, std::sqrt(c.noise_std * c.noise_std + 1.0 / 12.0), 0.15 * c.noise_std);

  // Exposure scales the scene: half exposure, half the background level.
  CameraConfig dim = IdealCamera();
  dim.exposure = 0.5;
  const geometry::GrayImage d = RenderMarker(dim, 5, pose, 1);
  EXPECT_NEAR(d.at(0, 0), 0.5 * dim.background_level, 0.5);
}

TEST(TagInCamera, ComposesRobotAndShelfPoses) {
  const geometry::Pose2 T_world_shelf(4.0, 2.0, std::numbers::pi / 2);
  // Robot exactly under the shelf, aligned: the code is at the identity.
  const geometry::Pose2 aligned = TagInCamera(T_world_shelf, T_world_shelf);
  EXPECT_NEAR(aligned.x, 0.0, 1e-12);
  EXPECT_NEAR(aligned.yaw, 0.0, 1e-12);
  // Robot 3 cm short along the shelf's long side (+y in the world), yawed by 0.1 rad.
  const geometry::Pose2 T_world_base(4.0, 1.97, std::numbers::pi / 2 + 0.1);
  const geometry::Pose2 T_camera_tag = TagInCamera(T_world_base, T_world_shelf);
  EXPECT_NEAR(std::hypot(T_camera_tag.x, T_camera_tag.y), 0.03, 1e-12);
  EXPECT_NEAR(T_camera_tag.yaw, -0.1, 1e-12);
  EXPECT_NEAR(T_camera_tag.x, 0.03 * std::cos(0.1), 1e-12);
}

}  // namespace
}  // namespace shelfdock::sim
