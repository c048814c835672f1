#include "io/robot_yaml.hpp"

#include "io/yaml_fields.hpp"

namespace shelfdock::io {
namespace {

void ReadOdometry(YamlFields f, sim::OdometryNoiseConfig& o) {
  f.Read("wheel_scale_std", o.wheel_scale_std);
  f.Read("wheel_base_scale_std", o.wheel_base_scale_std);
  f.Read("slip_std_m_per_sqrt_m", o.slip_std_m_per_sqrt_m);
  f.RejectUnknown();
  f.Require(o.wheel_scale_std >= 0.0 && o.wheel_scale_std < 0.1, "wheel_scale_std",
            "in [0, 0.1) (a fraction, 0.001 = 0.1 %)");
  f.Require(o.wheel_base_scale_std >= 0.0 && o.wheel_base_scale_std < 0.1, "wheel_base_scale_std",
            "in [0, 0.1) (a fraction)");
  f.Require(o.slip_std_m_per_sqrt_m >= 0.0, "slip_std_m_per_sqrt_m", ">= 0 (m per sqrt(m))");
}

void ReadLocalisation(YamlFields f, sim::LocalisationNoiseConfig& l) {
  f.Read("noise_std_m", l.noise_std_m);
  f.Read("noise_std_rad", l.noise_std_rad);
  f.Read("bias_std_m", l.bias_std_m);
  f.Read("bias_std_rad", l.bias_std_rad);
  f.Read("bias_time_constant_s", l.bias_time_constant_s);
  f.Read("update_rate_hz", l.update_rate_hz);
  f.RejectUnknown();
  f.Require(l.noise_std_m >= 0.0, "noise_std_m", ">= 0 metres");
  f.Require(l.noise_std_rad >= 0.0, "noise_std_rad", ">= 0 radians");
  f.Require(l.bias_std_m >= 0.0, "bias_std_m", ">= 0 metres");
  f.Require(l.bias_std_rad >= 0.0, "bias_std_rad", ">= 0 radians");
  f.Require(l.bias_time_constant_s > 0.0, "bias_time_constant_s", "> 0 seconds");
  f.Require(l.update_rate_hz > 0.0, "update_rate_hz", "> 0 Hz");
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
  f.Require(c.max_v_mps > 0.0, "max_v_mps", "> 0 m/s");
  f.Require(c.max_w_radps > 0.0, "max_w_radps", "> 0 rad/s");
  f.Require(c.max_accel_mps2 > 0.0, "max_accel_mps2", "> 0 m/s^2");
  f.Require(c.max_alpha_radps2 > 0.0, "max_alpha_radps2", "> 0 rad/s^2");
  f.Require(c.wheel_base_m > 0.0, "wheel_base_m", "> 0 metres");
  f.Require(c.footprint_length_m > 0.0, "footprint_length_m", "> 0 metres");
  f.Require(c.footprint_width_m > 0.0, "footprint_width_m", "> 0 metres");
  f.Require(c.control_rate_hz > 0.0, "control_rate_hz", "> 0 Hz");
  f.Require(c.lift_duration_s >= 0.0, "lift_duration_s", ">= 0 seconds");
  f.Require(c.history_s > 0.0, "history_s", "> 0 seconds");
  return c;
}

}  // namespace shelfdock::io
