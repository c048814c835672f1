#include "io/camera_yaml.hpp"

#include "io/yaml_fields.hpp"

namespace shelfdock::io {
namespace {

void ReadIntrinsics(YamlFields f, geometry::CameraIntrinsics& k) {
  f.Read("width_px", k.width_px);
  f.Read("height_px", k.height_px);
  f.Read("fx_px", k.fx_px);
  f.Read("fy_px", k.fy_px);
  f.Read("cx_px", k.cx_px);
  f.Read("cy_px", k.cy_px);
  f.RejectUnknown();
}

void ReadCode(YamlFields f, geometry::UpwardCamera& cam) {
  f.Read("code_size_m", cam.code_size_m);
  f.Read("code_height_m", cam.code_height_m);
  f.RejectUnknown();
}

void ReadRender(YamlFields f, sim::CameraConfig& c) {
  f.Read("supersample", c.supersample);
  f.Read("blur_sigma_px", c.blur_sigma_px);
  f.Read("noise_std", c.noise_std);
  f.Read("exposure", c.exposure);
  f.Read("white_level", c.white_level);
  f.Read("black_level", c.black_level);
  f.Read("background_level", c.background_level);
  f.RejectUnknown();
}

void ReadDetector(YamlFields f, perception::MarkerDetectorConfig& d) {
  f.Read("quad_decimate", d.quad_decimate);
  f.Read("quad_sigma_px", d.quad_sigma_px);
  f.Read("refine_edges", d.refine_edges);
  f.Read("decode_sharpening", d.decode_sharpening);
  f.Read("max_hamming", d.max_hamming);
  f.Read("min_decision_margin", d.min_decision_margin);
  f.Read("max_height_error_m", d.max_height_error_m);
  f.RejectUnknown();
}

}  // namespace

CameraSetup ReadCameraSetup(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  YamlFields top(root, path, "");
  CameraSetup setup;
  ReadIntrinsics(YamlFields(top.Child("intrinsics"), path, "intrinsics"),
                 setup.camera.camera.intrinsics);
  ReadCode(YamlFields(top.Child("code"), path, "code"), setup.camera.camera);
  ReadRender(YamlFields(top.Child("render"), path, "render"), setup.camera);
  const YamlFields detector(top.Child("detector"), path, "detector");
  ReadDetector(detector, setup.detector);
  top.RejectUnknown();
  // The rules live with the structs: the camera's keys already name their maps.
  top.Reject(sim::FindConfigViolation(setup.camera));
  detector.Reject(perception::FindConfigViolation(setup.detector));
  return setup;
}

}  // namespace shelfdock::io
