// `shelfdock marker`: reads the code under the shelf from a camera image (paper 3.5) and
// prints its id and offset from the camera as JSON, or renders the image the simulated camera
// would take, so that real and synthetic images go through the same detector.
//
//   shelfdock marker --image FILE.pgm --camera config/camera.yaml
//     -> {"found": true, "id": 7, "x": 0.012, "y": -0.004, "yaw": 0.05, "decision_margin": 80.1,
//         "height": 0.300}; exit 0. No code: {"found": false}; exit 1. Bad input: exit 2.
//   shelfdock marker --render OUT.pgm --camera config/camera.yaml --offset X,Y,YAW --id N
//     -> writes the rendered image; exit 0.
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "io/camera_yaml.hpp"
#include "io/input_error.hpp"
#include "io/pgm.hpp"
#include "perception/marker_detector.hpp"
#include "sim/marker_camera.hpp"
#include "sim/marker_pattern.hpp"

namespace shelfdock::app {
namespace {

struct MarkerOptions {
  std::string image;
  std::string render;
  std::string camera = DefaultConfig("camera.yaml");
  std::string offset = "0,0,0";
  int id = 0;
  std::uint64_t seed = 1;
};

int RunMarker(const MarkerOptions& opt) {
  const io::CameraSetup setup = io::ReadCameraSetup(opt.camera);
  const geometry::UpwardCamera& camera = setup.camera.camera;

  if (!opt.render.empty()) {
    if (opt.id < 0 || opt.id >= sim::MarkerFamilySize()) {
      throw io::InputError(
          kCommandLine, "--id",
          "must be a tag36h11 id, 0.." + std::to_string(sim::MarkerFamilySize() - 1));
    }
    const geometry::GrayImage image =
        sim::RenderMarker(setup.camera, opt.id, ParsePose(opt.offset, "--offset"), opt.seed);
    io::WritePgm(opt.render, image);
    return kExitOk;
  }

  const geometry::GrayImage image = io::ReadPgm(opt.image);
  if (image.width != camera.intrinsics.width_px || image.height != camera.intrinsics.height_px) {
    throw io::InputError(opt.image, "size",
                         std::to_string(image.width) + " x " + std::to_string(image.height) +
                             " does not match the camera's " +
                             std::to_string(camera.intrinsics.width_px) + " x " +
                             std::to_string(camera.intrinsics.height_px) + " (" + opt.camera + ")");
  }
  perception::MarkerDetector detector(setup.detector);
  const auto obs = detector.Detect(image, camera);
  if (!obs) {
    std::cout << nlohmann::json{{"found", false}}.dump() << "\n";
    return kExitFailure;
  }
  const nlohmann::json out = {{"found", true},
                              {"id", obs->id},
                              {"x", obs->T_camera_tag.x},
                              {"y", obs->T_camera_tag.y},
                              {"yaw", obs->T_camera_tag.yaw},
                              {"decision_margin", obs->decision_margin},
                              {"height", obs->height_m}};
  std::cout << out.dump() << "\n";
  return kExitOk;
}

}  // namespace

void AddMarkerCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<MarkerOptions>();
  CLI::App* cmd = app.add_subcommand(
      "marker", "read the code under the shelf from a PGM image (or render one) as JSON");
  auto* image = cmd->add_option("--image", opt->image, "binary PGM (P5) from the upward camera");
  auto* render = cmd->add_option("--render", opt->render, "write the simulated image here instead");
  image->excludes(render);
  cmd->add_option("--camera", opt->camera, "camera file (intrinsics, code, render, detector)")
      ->capture_default_str();
  cmd->add_option("--offset", opt->offset, "with --render: code pose X,Y,YAW from the camera")
      ->capture_default_str();
  cmd->add_option("--id", opt->id, "with --render: tag36h11 id of the code")->capture_default_str();
  cmd->add_option("--seed", opt->seed, "with --render: noise seed")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->callback([opt, exit_code, image, render] {
    if (image->count() == 0 && render->count() == 0) {
      throw io::InputError(kCommandLine, "--image", "give --image FILE or --render FILE");
    }
    *exit_code = RunMarker(*opt);
  });
}

}  // namespace shelfdock::app
