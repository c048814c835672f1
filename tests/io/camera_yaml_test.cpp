#include "io/camera_yaml.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

std::string WriteYaml(const std::string& name, const std::string& text) {
  const auto path = shelfdock::testing::ProcessTempDir().path() / ("shelfdock_camera_" + name);
  std::ofstream(path) << text;
  return path.string();
}

TEST(CameraYaml, TheShippedFileWritesOutTheDefaults) {
  const CameraSetup setup = ReadCameraSetup(SHELFDOCK_SOURCE_DIR "/config/camera.yaml");
  const sim::CameraConfig c;
  const perception::MarkerDetectorConfig d;
  EXPECT_EQ(setup.camera.camera.intrinsics.width_px, c.camera.intrinsics.width_px);
  EXPECT_EQ(setup.camera.camera.intrinsics.fx_px, c.camera.intrinsics.fx_px);
  EXPECT_EQ(setup.camera.camera.intrinsics.cy_px, c.camera.intrinsics.cy_px);
  EXPECT_EQ(setup.camera.camera.code_size_m, c.camera.code_size_m);
  EXPECT_EQ(setup.camera.camera.code_height_m, c.camera.code_height_m);
  EXPECT_EQ(setup.camera.blur_sigma_px, c.blur_sigma_px);
  EXPECT_EQ(setup.camera.background_level, c.background_level);
  EXPECT_EQ(setup.detector.quad_decimate, d.quad_decimate);
  EXPECT_EQ(setup.detector.max_hamming, d.max_hamming);
  EXPECT_EQ(setup.detector.max_height_error_m, d.max_height_error_m);
}

TEST(CameraYaml, ReadsKeysAndKeepsDefaultsForTheRest) {
  const CameraSetup setup = ReadCameraSetup(
      WriteYaml("partial.yaml", "code: {code_size_m: 0.12}\nrender: {noise_std: 0}\n"));
  EXPECT_EQ(setup.camera.camera.code_size_m, 0.12);
  EXPECT_EQ(setup.camera.noise_std, 0.0);
  EXPECT_EQ(setup.camera.camera.code_height_m, sim::CameraConfig{}.camera.code_height_m);
}

TEST(CameraYaml, ErrorsNameTheKey) {
  auto field_of = [](const std::string& text) -> std::string {
    try {
      ReadCameraSetup(WriteYaml("bad.yaml", text));
    } catch (const InputError& e) {
      return e.field();
    }
    return "(accepted)";
  };
  EXPECT_EQ(field_of("intrinsics: {fx_px: 0}\n"), "intrinsics.fx_px");
  EXPECT_EQ(field_of("code: {code_size_m: -0.08}\n"), "code.code_size_m");
  EXPECT_EQ(field_of("render: {blurr: 1}\n"), "render.blurr");
  EXPECT_EQ(field_of("render: {white_level: 20, black_level: 30}\n"), "render.white_level");
  EXPECT_EQ(field_of("detector: {max_hamming: 3}\n"), "detector.max_hamming");
  EXPECT_EQ(field_of("lens: {}\n"), "lens");
  EXPECT_EQ(field_of("code: {code_height_m: tall}\n"), "code.code_height_m");
}

}  // namespace
}  // namespace shelfdock::io
