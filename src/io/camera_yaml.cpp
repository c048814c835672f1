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
  f.Require(k.width_px > 0 && k.width_px <= 32768, "width_px", "in 1..32768 pixels");
  f.Require(k.height_px > 0 && k.height_px <= 32768, "height_px", "in 1..32768 pixels");
  f.Require(k.fx_px > 0.0, "fx_px", "> 0 pixels");
  f.Require(k.fy_px > 0.0, "fy_px", "> 0 pixels");
  f.Require(k.cx_px >= 0.0 && k.cx_px <= k.width_px, "cx_px", "inside the image (0..width)");
  f.Require(k.cy_px >= 0.0 && k.cy_px <= k.height_px, "cy_px", "inside the image (0..height)");
}

void ReadCode(YamlFields f, geometry::UpwardCamera& cam) {
  f.Read("code_size_m", cam.code_size_m);
  f.Read("code_height_m", cam.code_height_m);
  f.RejectUnknown();
  f.Require(cam.code_size_m > 0.0, "code_size_m", "> 0 (outer black border side, metres)");
  f.Require(cam.code_height_m > 0.0, "code_height_m", "> 0 (code above the lens, metres)");
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
  f.Require(c.supersample >= 1 && c.supersample <= 16, "supersample", "in 1..16");
  f.Require(c.blur_sigma_px >= 0.0 && c.blur_sigma_px <= 20.0, "blur_sigma_px", "in 0..20 pixels");
  f.Require(c.noise_std >= 0.0, "noise_std", ">= 0 grey levels");
  f.Require(c.exposure > 0.0, "exposure", "> 0");
  for (const auto& [key, level] :
       {std::pair{"white_level", c.white_level}, std::pair{"black_level", c.black_level},
        std::pair{"background_level", c.background_level}}) {
    f.Require(level >= 0.0 && level <= 255.0, key, "in 0..255 grey levels");
  }
  f.Require(c.white_level > c.black_level, "white_level", "> black_level");
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
  f.Require(d.quad_decimate >= 1.0, "quad_decimate", ">= 1");
  f.Require(d.quad_sigma_px >= 0.0, "quad_sigma_px", ">= 0 pixels");
  f.Require(d.decode_sharpening >= 0.0, "decode_sharpening", ">= 0");
  f.Require(d.max_hamming >= 0 && d.max_hamming <= 2, "max_hamming", "0, 1 or 2 bits");
  f.Require(d.min_decision_margin >= 0.0, "min_decision_margin", ">= 0");
  f.Require(d.max_height_error_m > 0.0, "max_height_error_m", "> 0 metres");
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
  ReadDetector(YamlFields(top.Child("detector"), path, "detector"), setup.detector);
  top.RejectUnknown();
  return setup;
}

}  // namespace shelfdock::io
