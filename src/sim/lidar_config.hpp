#pragma once

#include <optional>

#include "geometry/config_violation.hpp"

namespace shelfdock::sim {

/// Which of a beam's separate pulses (returns farther apart than echo_separation_m) the receiver
/// reports. Pulsed scanners commonly offer a choice (first, strongest or last echo).
enum class EchoChoice {
  kFirst,      ///< the nearest pulse covering min_echo_fraction of the beam (the default)
  kStrongest,  ///< the pulse of most energy among those covering min_echo_fraction
  kLast,       ///< the farthest pulse covering min_echo_fraction
};

/// A 2D LiDAR and its flaws. Defaults: the paper's VANJEE WLR-716 (270 deg, 1/3 deg steps =
/// 811 beams, 15 Hz, 0.05-25 m). Each flaw has its own switch so tests can isolate it; the
/// presets for other scanners are config/lidar_*.yaml.
struct LidarConfig {
  // Geometry of the scan.
  double angle_min_rad = -2.356194490192345;          ///< [rad] first beam (-135 deg)
  double angle_increment_rad = 0.005817764173314432;  ///< [rad] 1/3 deg
  int num_beams = 811;                                ///< beams per scan
  double frequency_hz = 15.0;                         ///< [Hz] scans per second
  /// Share of the scan period the beams are spread over: beam i fires at
  /// t0 + i * sweep_fraction / (frequency_hz * (num_beams - 1)). 1 gives the 2.7 cm
  /// skew at 0.4 m/s; a 270 deg window of a 360 deg mirror would be 0.75.
  double sweep_fraction = 1.0;
  double range_min_m = 0.05;  ///< [m]
  double range_max_m = 25.0;  ///< [m]

  // Range noise: sigma = range_noise_sigma_m + range_noise_per_m * range.
  bool enable_range_noise = true;
  double range_noise_sigma_m = 0.010;  ///< [m]
  double range_noise_per_m = 0.0;      ///< [m/m] growth with range
  bool enable_quantisation = true;
  double quantisation_m = 0.001;  ///< [m] range resolution

  // Beam footprint: a beam is a cone, not a line. Where it straddles a depth edge closer than a
  // pulse length, the echo mixes foreground and background into a "trailing" point between them
  // (paper 3.1, Eq. 1); farther apart, the receiver sees two pulses and reports one of them
  // (echo_choice).
  bool enable_footprint = true;
  double beam_divergence_rad = 0.006;  ///< [rad] full cone angle
  double beam_aperture_m = 0.004;      ///< [m] beam width at the window
  int footprint_rays = 5;              ///< sub-rays across the footprint at a depth edge (odd)
  double min_echo_fraction = 0.3;      ///< share of the footprint that must return an echo
  double echo_separation_m = 0.5;  ///< [m] returns farther apart are separate pulses (pulsed ToF:
                                   ///< about c * pulse width / 2); closer ones blend into one
  EchoChoice echo_choice = EchoChoice::kFirst;  ///< which separate pulse is reported (YAML:
                                                ///< first, strongest or last)

  // Dropouts: p = dropout_probability + dark_dropout_gain * (1 - reflectivity)
  //                + (shiny ? shiny_dropout_gain * sin^2(incidence) : 0).
  bool enable_dropouts = true;
  double dropout_probability = 0.002;  ///< [-] any beam
  double dark_dropout_gain = 0.05;     ///< [-] extra on dark surfaces
  double shiny_dropout_gain = 0.3;     ///< [-] extra on specular surfaces at grazing incidence

  // Systematic range error: every return this much longer than the beam's echo (a calibration
  // offset; datasheets give it apart from the noise, e.g. +-40 mm for the UST-10LX, +-60 mm for
  // the TiM571 over their whole range of targets and temperatures).
  double range_bias_m = 0.0;  ///< [m] added to every return; 0: none

  // Stray echoes: with this probability a beam returns an echo from nothing in the world (dust,
  // an insect, another robot's LiDAR pulse) instead of its own, at a range drawn uniformly
  // between range_min_m and the beam's own range (range_max_m when it had none): the "short"
  // and "random" readings of the beam model in Probabilistic Robotics (Thrun et al., 6.3).
  double stray_probability = 0.0;  ///< [-] any beam; 0: off (no random draws)

  // Intensities: reflectivity * cos(incidence) * intensity_scale / max(range, 1 m)^2.
  bool enable_intensities = true;
  double intensity_scale = 1000.0;    ///< [-] sensor units for a white wall at 1 m
  double intensity_noise_rel = 0.05;  ///< [-] relative Gaussian noise

  // Mounting. The scan plane may tilt: pitch (nose down positive) and roll (left side down
  // positive); a beam sinking toward the floor hits it at range h / tan(depression).
  double mount_height_m = 0.20;  ///< [m] scan plane above the floor at the LiDAR
  bool enable_tilt = true;
  double tilt_pitch_rad = 0.0;      ///< [rad]
  double tilt_roll_rad = 0.0;       ///< [rad]
  double yaw_offset_rad = 0.0;      ///< [rad] true minus reported beam angle (calibration)
  double floor_reflectivity = 0.3;  ///< [0..1]

  double ScanPeriod() const { return 1.0 / frequency_hz; }  ///< [s]
  double TimeIncrement() const;                             ///< [s] between beams
  double AngleMax() const { return angle_min_rad + (num_beams - 1) * angle_increment_rad; }
};

/// The first impossible value of the config, if any, keys as in config/lidar_*.yaml (the
/// field names).
std::optional<geometry::ConfigViolation> FindConfigViolation(const LidarConfig& config);

/// A config with every flaw switched off: exact ranges, no dropouts, no stray echoes, no
/// footprint, no tilt.
LidarConfig IdealLidarConfig(LidarConfig config = {});

}  // namespace shelfdock::sim
