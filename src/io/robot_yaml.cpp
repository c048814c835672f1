#include "io/robot_yaml.hpp"

#include "io/yaml_fields.hpp"

namespace shelfdock::io {
namespace {

void ReadOdometry(YamlFields f, sim::OdometryNoiseConfig& o) {
  f.Read("wheel_scale_std", o.wheel_scale_std);
  f.Read("wheel_base_scale_std", o.wheel_base_scale_std);
  f.Read("slip_std_m_per_sqrt_m", o.slip_std_m_per_sqrt_m);
  f.RejectUnknown();
}

void ReadLocalisation(YamlFields f, sim::LocalisationNoiseConfig& l) {
  f.Read("noise_std_m", l.noise_std_m);
  f.Read("noise_std_rad", l.noise_std_rad);
  f.Read("bias_std_m", l.bias_std_m);
  f.Read("bias_std_rad", l.bias_std_rad);
  f.Read("bias_time_constant_s", l.bias_time_constant_s);
  f.Read("update_rate_hz", l.update_rate_hz);
  f.RejectUnknown();
}

}  // namespace

sim::DiffDriveConfig ReadRobotConfig(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  YamlFields f(root, path, "");
  sim::DiffDriveConfig c;
  f.Read("max_v_mps", c.max_v_mps);
  f.Read("max_w_radps", c.max_w_radps);
  f.Read("max_accel_mps2", c.max_accel_mps2);
  f.Read("max_alpha_radps2", c.max_alpha_radps2);
  f.Read("wheel_base_m", c.wheel_base_m);
  f.Read("footprint_length_m", c.footprint_length_m);
  f.Read("footprint_width_m", c.footprint_width_m);
  f.Read("control_rate_hz", c.control_rate_hz);
  f.Read("lift_duration_s", c.lift_duration_s);
  f.Read("history_s", c.history_s);
  ReadOdometry(YamlFields(f.Child("odometry"), path, "odometry"), c.odometry);
  ReadLocalisation(YamlFields(f.Child("localisation"), path, "localisation"), c.localisation);
  std::string name;  // a label for the reader of the file only
  f.Read("name", name);
  f.RejectUnknown();
  f.Reject(sim::FindConfigViolation(c));  // the rules live with the structs
  return c;
}

}  // namespace shelfdock::io
