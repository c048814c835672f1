#include "perception/marker_detector.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <apriltag/apriltag.h>
#include <apriltag/apriltag_pose.h>
#include <apriltag/tag36h11.h>

#include "geometry/angle.hpp"

namespace shelfdock::perception {

struct MarkerDetector::Impl {
  apriltag_family_t* family = nullptr;
  apriltag_detector_t* detector = nullptr;

  ~Impl() {
    if (detector != nullptr) apriltag_detector_destroy(detector);
    if (family != nullptr) tag36h11_destroy(family);
  }
};

namespace {

/// libapriltag's pose is 3D in the optical frame (x right, y down, z along the axis, up here)
/// with the code's frame x right, y down as printed, z into the code. geometry::UpwardCamera
/// ties the planar frames to it: camera (x, y) = (-y_c, x_c), and the code's planar x axis is
/// its printed "up" (-y of the code), so for a code parallel to the image plane the planar yaw
/// is the rotation about the optical axis, atan2(R10, R00).
geometry::Pose2 PlanarPose(const matd_t* R, const matd_t* t) {
  const double tx = MATD_EL(t, 0, 0);
  const double ty = MATD_EL(t, 1, 0);
  const double yaw = std::atan2(MATD_EL(R, 1, 0), MATD_EL(R, 0, 0));
  return geometry::Pose2(-ty, tx, geometry::WrapAngle(yaw));
}

/// Debian's libapriltag exports none of the matd_* helpers, matd_destroy included. A matd_t is
/// a single calloc'd block (header plus flexible array, common/matd.h), so free() releases it.
void FreeMatrix(matd_t* m) { std::free(m); }

}  // namespace

MarkerDetector::MarkerDetector(const MarkerDetectorConfig& config)
    : config_(config), impl_(std::make_unique<Impl>()) {
  impl_->family = tag36h11_create();
  impl_->detector = apriltag_detector_create();
  apriltag_detector_add_family_bits(impl_->detector, impl_->family,
                                    std::clamp(config_.max_hamming, 0, 2));
  impl_->detector->quad_decimate = static_cast<float>(config_.quad_decimate);
  impl_->detector->quad_sigma = static_cast<float>(config_.quad_sigma_px);
  impl_->detector->refine_edges = config_.refine_edges;
  impl_->detector->decode_sharpening = config_.decode_sharpening;
  impl_->detector->nthreads = 1;
}

MarkerDetector::~MarkerDetector() = default;
MarkerDetector::MarkerDetector(MarkerDetector&&) noexcept = default;
MarkerDetector& MarkerDetector::operator=(MarkerDetector&&) noexcept = default;

std::vector<MarkerObservation> MarkerDetector::DetectAll(const geometry::GrayImage& image,
                                                         const geometry::UpwardCamera& camera) {
  std::vector<MarkerObservation> observations;
  if (image.empty()) return observations;
  // libapriltag reads the buffer without writing to it; its API just is not const-correct.
  image_u8_t view{image.width, image.height, image.width,
                  const_cast<uint8_t*>(image.pixels.data())};
  zarray_t* detections = apriltag_detector_detect(impl_->detector, &view);

  for (int i = 0; i < zarray_size(detections); ++i) {
    apriltag_detection_t* det = nullptr;
    zarray_get(detections, i, &det);
    if (det->hamming > config_.max_hamming) continue;
    if (det->decision_margin < config_.min_decision_margin) continue;

    // libapriltag's pixel (i, j) spans [i, i + 1), its centre at i + 0.5; our intrinsics put
    // pixel centres at integers (the OpenCV calibration convention). Shifting the principal
    // point by half a pixel reconciles the two (a 0.3 mm bias at 0.30 m otherwise).
    const auto& k = camera.intrinsics;
    apriltag_detection_info_t info{det,     camera.code_size_m, k.fx_px,
                                   k.fy_px, k.cx_px + 0.5,      k.cy_px + 0.5};
    apriltag_pose_t pose{nullptr, nullptr};
    estimate_tag_pose(&info, &pose);
    MarkerObservation obs;
    obs.id = det->id;
    obs.T_camera_tag = PlanarPose(pose.R, pose.t);
    obs.height_m = MATD_EL(pose.t, 2, 0);
    obs.decision_margin = det->decision_margin;
    obs.hamming = det->hamming;
    FreeMatrix(pose.R);
    FreeMatrix(pose.t);

    // A code at the wrong height is not the one under this shelf (or a misread size).
    if (std::abs(obs.height_m - camera.code_height_m) > config_.max_height_error_m) continue;
    observations.push_back(obs);
  }
  apriltag_detections_destroy(detections);

  std::sort(observations.begin(), observations.end(),
            [](const MarkerObservation& a, const MarkerObservation& b) {
              return a.decision_margin > b.decision_margin;
            });
  return observations;
}

std::optional<MarkerObservation> MarkerDetector::Detect(const geometry::GrayImage& image,
                                                        const geometry::UpwardCamera& camera) {
  std::vector<MarkerObservation> all = DetectAll(image, camera);
  if (all.empty()) return std::nullopt;
  return all.front();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const MarkerDetectorConfig& c) {
  geometry::ConfigChecker k;  // refine_edges: either value
  k.Check(c.quad_decimate >= 1.0, "quad_decimate", ">= 1");
  k.Check(c.quad_sigma_px >= 0.0, "quad_sigma_px", ">= 0 pixels");
  k.Check(c.decode_sharpening >= 0.0, "decode_sharpening", ">= 0");
  k.Check(c.max_hamming >= 0 && c.max_hamming <= 2, "max_hamming", "0, 1 or 2 bits");
  k.Check(c.min_decision_margin >= 0.0, "min_decision_margin", ">= 0");
  k.Check(c.max_height_error_m > 0.0, "max_height_error_m", "> 0 metres");
  return k.Result();
}

}  // namespace shelfdock::perception
