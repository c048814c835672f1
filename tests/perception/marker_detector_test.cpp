#include "perception/marker_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"
#include "sim/marker_camera.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kMaxPositionError_m = 0.002;  // issue 3: within 2 mm ...
constexpr double kMaxYawError_rad = 0.005;     // ... and 5 mrad

struct Errors {
  double position_m = 0.0;
  double yaw_rad = 0.0;
};

Errors Compare(const MarkerObservation& obs, const geometry::Pose2& truth) {
  return {std::hypot(obs.T_camera_tag.x - truth.x, obs.T_camera_tag.y - truth.y),
          std::abs(geometry::AngleDiff(obs.T_camera_tag.yaw, truth.yaw))};
}

TEST(MarkerDetector, RecoversTheOffsetOverASweep) {
  // x, y in +-5 cm and yaw in +-0.2 rad (the fine-adjustment range under the shelf), 5 x 5 x 5
  // poses with the default camera (blur, noise): every one within 2 mm and 5 mrad.
  const sim::CameraConfig camera;
  MarkerDetector detector;
  Errors worst;
  double sum_dx = 0.0, sum_dy = 0.0;
  int n = 0;
  for (int ix = -2; ix <= 2; ++ix) {
    for (int iy = -2; iy <= 2; ++iy) {
      for (int iyaw = -2; iyaw <= 2; ++iyaw) {
        const geometry::Pose2 truth(0.025 * ix, 0.025 * iy, 0.1 * iyaw);
        const int id = 7 + n % 5;
        const geometry::GrayImage image = sim::RenderMarker(camera, id, truth, 1000 + n);
        const auto obs = detector.Detect(image, camera.camera);
        ASSERT_TRUE(obs.has_value()) << truth.x << " " << truth.y << " " << truth.yaw;
        EXPECT_EQ(obs->id, id);
        const Errors e = Compare(*obs, truth);
        EXPECT_LT(e.position_m, kMaxPositionError_m)
            << truth.x << " " << truth.y << " " << truth.yaw;
        EXPECT_LT(e.yaw_rad, kMaxYawError_rad) << truth.x << " " << truth.y << " " << truth.yaw;
        EXPECT_NEAR(obs->height_m, camera.camera.code_height_m, 0.01);
        sum_dx += obs->T_camera_tag.x - truth.x;
        sum_dy += obs->T_camera_tag.y - truth.y;
        worst.position_m = std::max(worst.position_m, e.position_m);
        worst.yaw_rad = std::max(worst.yaw_rad, e.yaw_rad);
        ++n;
      }
    }
  }
  // No systematic offset: a half-pixel convention mismatch between renderer, detector and
  // intrinsics would show as a 0.3 mm mean error here.
  EXPECT_LT(std::abs(sum_dx / n), 1e-4);
  EXPECT_LT(std::abs(sum_dy / n), 1e-4);
  RecordProperty("worst_position_error_m", std::to_string(worst.position_m));
  RecordProperty("worst_yaw_error_rad", std::to_string(worst.yaw_rad));
  std::printf("sweep of %d poses: worst position error %.3f mm, worst yaw error %.3f mrad\n", n,
              worst.position_m * 1e3, worst.yaw_rad * 1e3);
}

TEST(MarkerDetector, ReportsTheIdItSeesSoAWrongCodeIsCaught) {
  // The docking check compares the code's id with the shelf's: the detector must report the
  // id that is printed, for any code of the family, and never the one we hoped for.
  const sim::CameraConfig camera;
  MarkerDetector detector;
  for (const int id : {0, 1, 2, 42, 300, 586}) {
    const auto obs =
        detector.Detect(sim::RenderMarker(camera, id, geometry::Pose2(), 5), camera.camera);
    ASSERT_TRUE(obs.has_value()) << id;
    EXPECT_EQ(obs->id, id);
    EXPECT_EQ(obs->hamming, 0);
  }
  const int shelf_id = 12;
  const auto wrong = detector.Detect(
      sim::RenderMarker(camera, 13, geometry::Pose2(0.01, 0.0, 0.0), 6), camera.camera);
  ASSERT_TRUE(wrong.has_value());
  EXPECT_NE(wrong->id, shelf_id);
}

TEST(MarkerDetector, NoCodeNoObservation) {
  const sim::CameraConfig camera;
  MarkerDetector detector;
  // The code far outside the view: only the shelf's underside and sensor noise.
  EXPECT_FALSE(
      detector
          .Detect(sim::RenderMarker(camera, 3, geometry::Pose2(1.0, 0.5, 0.0), 1), camera.camera)
          .has_value());
  EXPECT_FALSE(detector.Detect(geometry::GrayImage(), camera.camera).has_value());
  EXPECT_FALSE(detector.Detect(geometry::GrayImage(64, 48, 128), camera.camera).has_value());
}

TEST(MarkerDetector, PartialViewIsEitherMissedOrRightNeverWrong) {
  // Slide the code out through the top of the image (+x, forward): while its black border is
  // wholly inside, it must be found and accurate; once the border is cut it must not be
  // reported with a wrong pose.
  const sim::CameraConfig camera;
  const auto& k = camera.camera.intrinsics;
  MarkerDetector detector;
  const double half_border_m = 0.5 * camera.camera.code_size_m;
  const double x_edge_m = k.cy_px / k.fy_px * camera.camera.code_height_m;  // image top edge
  int found_inside = 0, cut = 0;
  for (double x = 0.0; x <= x_edge_m + half_border_m; x += 0.005) {
    const geometry::Pose2 truth(x, 0.01, 0.05);
    const auto obs = detector.Detect(sim::RenderMarker(camera, 9, truth, 7), camera.camera);
    // Quiet zone (one cell beyond the border) still inside the image: a full view.
    const bool full_view = x + half_border_m * 10.0 / 8.0 < x_edge_m;
    if (full_view) {
      ASSERT_TRUE(obs.has_value()) << "x = " << x;
      ++found_inside;
    }
    if (x + half_border_m > x_edge_m) ++cut;
    if (obs) {
      const Errors e = Compare(*obs, truth);
      EXPECT_LT(e.position_m, kMaxPositionError_m) << "x = " << x;
      EXPECT_LT(e.yaw_rad, kMaxYawError_rad) << "x = " << x;
    }
    if (x + half_border_m > x_edge_m + 0.005) {
      EXPECT_FALSE(obs.has_value()) << "x = " << x;
    }
  }
  EXPECT_GT(found_inside, 10);
  EXPECT_GT(cut, 3);
}

TEST(MarkerDetector, AnyYawAndLargerOffsets) {
  // Docked back to front the code reads yaw near +-pi; approaching, the offset can reach 10 cm
  // across the image (the 10 cm quiet zone, diagonal 7 cm, must stay within the 0.19 x 0.14 m
  // half-view at 0.30 m).
  const sim::CameraConfig camera;
  MarkerDetector detector;
  for (const double yaw : {-3.1, -std::numbers::pi / 2, 1.0, 3.1, std::numbers::pi - 1e-3}) {
    for (const geometry::Pose2 truth :
         {geometry::Pose2(0.07, -0.10, yaw), geometry::Pose2(-0.07, 0.10, yaw)}) {
      const auto obs = detector.Detect(sim::RenderMarker(camera, 21, truth, 3), camera.camera);
      ASSERT_TRUE(obs.has_value()) << truth.x << " " << truth.y << " " << yaw;
      const Errors e = Compare(*obs, truth);
      EXPECT_LT(e.position_m, kMaxPositionError_m) << truth.x << " " << truth.y << " " << yaw;
      EXPECT_LT(e.yaw_rad, kMaxYawError_rad) << truth.x << " " << truth.y << " " << yaw;
    }
  }
}

TEST(MarkerDetector, HarshImagesStillMeasureWithinTolerance) {
  // Dim exposure, stronger defocus and noise than the default camera.
  sim::CameraConfig camera;
  camera.exposure = 0.45;
  camera.blur_sigma_px = 1.2;
  camera.noise_std = 4.0;
  MarkerDetector detector;
  int n = 0;
  for (const geometry::Pose2 truth :
       {geometry::Pose2(0.03, 0.02, 0.15), geometry::Pose2(-0.04, 0.01, -0.2),
        geometry::Pose2(0.0, -0.05, 0.0)}) {
    const auto obs = detector.Detect(sim::RenderMarker(camera, 30, truth, 40 + n++), camera.camera);
    ASSERT_TRUE(obs.has_value());
    const Errors e = Compare(*obs, truth);
    EXPECT_LT(e.position_m, kMaxPositionError_m);
    EXPECT_LT(e.yaw_rad, kMaxYawError_rad);
  }
}

TEST(MarkerDetector, ACodeOfTheWrongSizeIsRejectedByItsHeight) {
  // The pose's scale comes from the code's known size: a camera config that believes the code
  // is twice as big places it at twice the height, which the height check refuses.
  sim::CameraConfig camera;
  const geometry::GrayImage image =
      sim::RenderMarker(camera, 4, geometry::Pose2(0.02, 0.0, 0.0), 1);
  MarkerDetector detector;
  const auto right = detector.Detect(image, camera.camera);
  ASSERT_TRUE(right.has_value());
  EXPECT_NEAR(right->height_m, camera.camera.code_height_m, 0.005);
  geometry::UpwardCamera wrong = camera.camera;
  wrong.code_size_m *= 2.0;
  EXPECT_FALSE(detector.Detect(image, wrong).has_value());
}

}  // namespace
}  // namespace shelfdock::perception
