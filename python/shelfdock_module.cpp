// The Python module `shelfdock`: the shelf detector on a numpy array of ranges, results as the
// same fields as `shelfdock detect` prints (both go through io::DetectionResultToJson).
//   import shelfdock, numpy as np
//   det = shelfdock.Detector(models="config/models.yaml")
//   result = det.detect(ranges, angle_min=-2.356, angle_increment=0.00582, preset=(2.0, 0, 0))
//   result["detections"][0]["x"], result["stats"]["clusters"]
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "io/detection_json.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"
#include "perception/detector.hpp"

namespace py = pybind11;

namespace {

using Ranges = py::array_t<double, py::array::c_style | py::array::forcecast>;
using PresetTuple = std::tuple<double, double, double>;

// The scan the detector sees; errors name the Python argument, as the CLI's name the JSON field.
shelfdock::geometry::LaserScan MakeScan(const Ranges& ranges, double angle_min,
                                        double angle_increment, double range_min,
                                        double range_max) {
  if (ranges.ndim() != 1) throw py::value_error("ranges: expected a 1-D array");
  if (!std::isfinite(angle_min)) throw py::value_error("angle_min: must be finite");
  if (!std::isfinite(angle_increment) || angle_increment <= 0.0) {
    throw py::value_error("angle_increment: must be finite and > 0");
  }
  if (!(range_min >= 0.0) || !(range_max > range_min)) {
    throw py::value_error("range_max: must exceed range_min >= 0");
  }
  shelfdock::geometry::LaserScan scan;
  const auto r = ranges.unchecked<1>();
  scan.ranges.assign(r.data(0), r.data(0) + r.shape(0));
  scan.angle_min = angle_min;
  scan.angle_increment = angle_increment;
  scan.angle_max =
      angle_min + angle_increment * static_cast<double>(std::max<py::ssize_t>(r.shape(0) - 1, 0));
  scan.range_min = range_min;
  scan.range_max = range_max;
  return scan;
}

class PyDetector {
 public:
  PyDetector(const std::filesystem::path& models,
             const std::optional<std::filesystem::path>& params,
             const std::vector<std::string>& only)
      : detector_(shelfdock::io::SelectModels(shelfdock::io::ReadShelfModels(models.string()), only,
                                              models.string(), "only"),
                  params ? shelfdock::io::ReadDetectorConfig(params->string())
                         : shelfdock::perception::DetectorConfig{}) {}

  py::object Detect(const Ranges& ranges, double angle_min, double angle_increment,
                    const std::optional<PresetTuple>& preset, double range_min, double range_max,
                    bool explain) const {
    const auto scan = MakeScan(ranges, angle_min, angle_increment, range_min, range_max);
    std::optional<shelfdock::geometry::Pose2> T_lidar_preset;
    if (preset) {
      const auto [x, y, yaw] = *preset;
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw)) {
        throw py::value_error("preset: expected (x, y, yaw) as three finite numbers");
      }
      T_lidar_preset = shelfdock::geometry::Pose2(x, y, yaw);
    }
    shelfdock::perception::DetectionResult result;
    {
      py::gil_scoped_release release;  // Detect is const and thread-safe
      result = detector_.Detect(scan, T_lidar_preset, explain);
    }
    const std::string text = shelfdock::io::DetectionResultToJson(result, explain).dump();
    return py::module_::import("json").attr("loads")(text);
  }

  std::vector<std::string> ModelNames() const {
    std::vector<std::string> names;
    for (const auto& m : detector_.models()) names.push_back(m.name);
    return names;
  }

 private:
  shelfdock::perception::Detector detector_;
};

}  // namespace

PYBIND11_MODULE(shelfdock, m) {
  m.doc() = "shelfdock: find shelves in 2D LiDAR scans (Zhao et al.); see README 'Python'";
  py::register_exception<shelfdock::io::InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PyDetector>(m, "Detector", R"doc(
The shelf detector, configured once.

models: shelf models YAML (e.g. config/models.yaml; installed under share/shelfdock/config).
params: detector parameters YAML, or None for the built-in defaults.
only: names of the models to look for (the map names the shelf's model), or [] for all of them.
Raises shelfdock.InputError (a ValueError) naming the file and key on bad input.)doc")
      .def(py::init<const std::filesystem::path&, const std::optional<std::filesystem::path>&,
                    const std::vector<std::string>&>(),
           py::arg("models"), py::arg("params") = py::none(),
           py::arg("only") = std::vector<std::string>{})
      .def("detect", &PyDetector::Detect, py::arg("ranges"), py::arg("angle_min"),
           py::arg("angle_increment"), py::arg("preset") = py::none(), py::arg("range_min") = 0.0,
           py::arg("range_max") = std::numeric_limits<double>::infinity(),
           py::arg("explain") = false, R"doc(
Detects shelves in one scan.

ranges: 1-D array of ranges [m], beam i at angle_min + i * angle_increment [rad] in the lidar
frame; NaN (or outside [range_min, range_max]) = no return.
preset: expected shelf pose (x, y, yaw) in the lidar frame [m, m, rad], or None.
Returns a dict with the fields of one `shelfdock detect` line: "detections" (best first; model,
x, y, yaw, length, width, legs, confidence, covariance, ...) and "stats" (and "hypotheses" when
explain=True).)doc")
      .def_property_readonly("models", &PyDetector::ModelNames, "names of the shelf models");
}
