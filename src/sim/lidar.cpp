#include "sim/lidar.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace shelfdock::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDepthEdge_m = 0.05;       // sub-ray spread that counts as straddling an edge
constexpr double kMovingRefresh_s = 0.001;  // how often moving obstacles are re-placed

/// One sub-ray's return: slant range, what it hit and how strongly it reflects.
struct SubHit {
  double range_m = kInf;  // slant range along the beam
  bool hit = false;       // an object (not the floor); kind/object_id/part say which
  ObjectKind kind = ObjectKind::kWall;
  int object_id = -1;
  int part = 0;
  bool floor = false;
  double reflectivity = 0.0;
  double cos_incidence = 1.0;
  bool shiny = false;
};

/// Beam direction in the level frame for a beam at angle theta in the tilted scan plane:
/// d = Ry(pitch) * Rx(-roll) * (cos theta, sin theta, 0). Returns azimuth, horizontal share
/// of a slant metre, and climb per horizontal metre.
void TiltedDirection(double theta, double pitch, double roll, double* azimuth, double* horiz,
                     double* dz_dt) {
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double dx = cp * ct - sp * sr * st;
  const double dy = cr * st;
  const double dz = -sp * ct - cp * sr * st;
  *horiz = std::hypot(dx, dy);
  *azimuth = std::atan2(dy, dx);
  *dz_dt = dz / *horiz;
}
}  // namespace

struct Lidar::Echo {
  SubHit centre;
  double range_m = kNaN;  // after mixing, before noise
  double intensity = 0.0;
  bool mixed = false;
};

Lidar::Lidar(LidarConfig config, std::uint64_t seed) : config_(config), rng_(seed) {
  assert(!FindConfigViolation(config_).has_value());
}

Lidar::Echo Lidar::CastBeam(const World& world, const geometry::Pose2& T_world_lidar,
                            double beam_angle_rad, const std::vector<Primitive>& moving,
                            bool footprint) const {
  const LidarConfig& c = config_;
  double azimuth = beam_angle_rad, horiz = 1.0, dz_dt = 0.0;
  if (c.enable_tilt && (c.tilt_pitch_rad != 0.0 || c.tilt_roll_rad != 0.0)) {
    TiltedDirection(beam_angle_rad, c.tilt_pitch_rad, c.tilt_roll_rad, &azimuth, &horiz, &dz_dt);
  }
  const double floor_t = dz_dt < 0.0 ? c.mount_height_m / -dz_dt : kInf;  // h / tan(depression)

  const double yaw0 = T_world_lidar.yaw + azimuth;
  const Eigen::Vector2d dir0(std::cos(yaw0), std::sin(yaw0));
  auto cast = [&](double u) {  // u in [-0.5, 0.5] across the footprint
    CastQuery q;
    if (u == 0.0) {
      q.ray.dir = dir0;
    } else {
      const double yaw = yaw0 + u * c.beam_divergence_rad;
      q.ray.dir = Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
    }
    const Eigen::Vector2d across(-q.ray.dir.y(), q.ray.dir.x());
    q.ray.origin = T_world_lidar.translation() + u * c.beam_aperture_m * across;
    q.max_t_m = std::min(c.range_max_m * horiz, floor_t);
    q.z0_m = c.mount_height_m;
    q.dz_dt = dz_dt;
    RayHit hit = world.static_grid().Cast(q);
    for (const Primitive& p : moving) CastAgainst(q, p, &hit);
    SubHit s;
    if (hit.primitive != nullptr) {
      s.range_m = hit.t_m / horiz;
      s.hit = true;
      s.kind = hit.primitive->kind;
      s.object_id = hit.primitive->object_id;
      s.part = hit.primitive->part;
      s.reflectivity = hit.primitive->material.reflectivity;
      s.shiny = hit.primitive->material.shiny;
      const Eigen::Vector2d p = q.ray.origin + hit.t_m * q.ray.dir;
      s.cos_incidence = std::abs(SurfaceNormal(*hit.primitive, p, q.ray.origin).dot(q.ray.dir));
    } else if (floor_t <= c.range_max_m * horiz) {
      s.range_m = floor_t / horiz;
      s.floor = true;
      s.reflectivity = c.floor_reflectivity;
      s.cos_incidence = std::abs(dz_dt) * horiz;  // grazing: sin of the depression
    }
    return s;
  };
  auto strength = [](const SubHit& s) {
    return s.reflectivity * std::max(s.cos_incidence, 0.05) / std::max(s.range_m * s.range_m, 1.0);
  };

  Echo echo;
  echo.centre = cast(0.0);
  echo.range_m = echo.centre.range_m;
  echo.intensity = std::isfinite(echo.range_m) ? strength(echo.centre) : 0.0;
  if (!footprint) return echo;

  // Cheap test first: if the footprint's two edges agree with its centre, no depth edge.
  const SubHit left = cast(-0.5);
  const SubHit right = cast(0.5);
  const double lo = std::min({left.range_m, right.range_m, echo.centre.range_m});
  const double hi = std::max({left.range_m, right.range_m, echo.centre.range_m});
  if (std::isfinite(hi) && hi - lo < kDepthEdge_m) return echo;
  if (!std::isfinite(lo)) return echo;  // nothing anywhere in the cone

  // A depth edge. The sub-rays' returns form pulses: returns closer in range than
  // echo_separation_m overlap in time and blend into one echo at their energy-weighted mean range
  // (the mixed "trailing" points of paper 3.1); returns farther apart are separate pulses, and a
  // pulsed time-of-flight receiver reports one that covers at least min_echo_fraction of the beam
  // profile (Gaussian, sigma a quarter of the footprint): the first by default, or the strongest
  // or the last (LidarConfig::echo_choice). A weak first pulse is lost behind the background's.
  const int n = c.footprint_rays;
  struct Return {
    double range_m, weight, energy;
  };
  std::array<Return, 31> returns{};  // footprint_rays <= 31 (validated)
  int n_returns = 0;
  double w_total = 0.0;
  for (int k = 0; k < n; ++k) {
    const double u = -0.5 + static_cast<double>(k) / (n - 1);
    const SubHit s =
        k == 0 ? left : (k == n - 1 ? right : (2 * k == n - 1 ? echo.centre : cast(u)));
    const double w = std::exp(-0.5 * (u / 0.25) * (u / 0.25));
    w_total += w;
    if (std::isfinite(s.range_m)) returns[n_returns++] = {s.range_m, w, w * strength(s)};
  }
  std::sort(returns.begin(), returns.begin() + n_returns,
            [](const Return& a, const Return& b) { return a.range_m < b.range_m; });
  // The pulses that cover enough of the beam, nearest first; the receiver reports one of them
  // (LidarConfig::echo_choice).
  bool found = false;
  double best_energy = 0.0;
  for (int begin = 0; begin < n_returns;) {
    int end = begin + 1;
    while (end < n_returns &&
           returns[end].range_m - returns[end - 1].range_m < c.echo_separation_m) {
      ++end;
    }
    double w = 0.0, e = 0.0, er = 0.0;
    for (int k = begin; k < end; ++k) {
      w += returns[k].weight;
      e += returns[k].energy;
      er += returns[k].energy * returns[k].range_m;
    }
    const bool takes = w >= c.min_echo_fraction * w_total && e > 0.0 &&
                       (!found || c.echo_choice == EchoChoice::kLast ||
                        (c.echo_choice == EchoChoice::kStrongest && e > best_energy));
    if (takes) {
      found = true;
      best_energy = e;
      echo.range_m = er / e;
      echo.intensity = e / w_total;
      echo.mixed = returns[end - 1].range_m - returns[begin].range_m >= kDepthEdge_m;
      if (c.echo_choice == EchoChoice::kFirst) return echo;
    }
    begin = end;
  }
  if (found) return echo;
  echo.range_m = kNaN;
  echo.intensity = 0.0;
  return echo;
}

geometry::LaserScan Lidar::Scan(const World& world, const geometry::Pose2& T_world_lidar,
                                double t0_s) {
  return Scan(
      world, [&T_world_lidar](double) { return T_world_lidar; }, t0_s);
}

geometry::LaserScan Lidar::Scan(const World& world, const PoseAt& T_world_lidar_at, double t0_s) {
  return ScanLabelled(world, T_world_lidar_at, t0_s).scan;
}

LabelledScan Lidar::ScanLabelled(const World& world, const PoseAt& T_world_lidar_at, double t0_s) {
  const LidarConfig& c = config_;
  LabelledScan out;
  geometry::LaserScan& scan = out.scan;
  scan.angle_min = c.angle_min_rad;
  scan.angle_max = c.AngleMax();
  scan.angle_increment = c.angle_increment_rad;
  scan.range_min = c.range_min_m;
  scan.range_max = c.range_max_m;
  scan.time_increment = c.TimeIncrement();
  scan.scan_time = c.ScanPeriod();
  scan.stamp = t0_s;
  const auto n = static_cast<std::size_t>(c.num_beams);
  scan.ranges.assign(n, kNaN);
  if (c.enable_intensities) scan.intensities.assign(n, 0.0);
  out.truth.assign(n, BeamTruth{});

  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const bool moving = world.HasMovingObstacles();
  // People and robots are re-placed every millisecond of the sweep, not every beam: at walking
  // speed they move about a millimetre in that time.
  double moving_t = -std::numeric_limits<double>::infinity();
  auto moving_at = [&](double t) -> const std::vector<Primitive>& {
    if (moving && std::abs(t - moving_t) > kMovingRefresh_s) {
      moving_.clear();
      world.AppendMovingObstacles(t, &moving_);
      moving_t = t;
    }
    return moving_;
  };
  moving_.clear();
  // The beam really leaves at its reported angle plus the calibration error.
  auto theta = [&](std::size_t i) { return scan.BeamAngle(i) + c.yaw_offset_rad; };

  // Pass 1: the centre ray of every beam, each from the pose at its own firing time.
  std::vector<geometry::Pose2> poses(n);
  std::vector<Echo> echoes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = t0_s + static_cast<double>(i) * scan.time_increment;
    poses[i] = T_world_lidar_at(t);
    echoes[i] = CastBeam(world, poses[i], theta(i), moving_at(t), false);
  }
  // Pass 2: the beam footprint only matters where a depth edge lies near the beam, and an
  // edge inside a footprint of half-width w beam steps shows as a jump between centre rays
  // within w beams. Casting the sub-rays only there keeps a scan near the cost of its centre
  // rays. (A thin object that no centre ray hits stays unseen, as with no footprint at all.)
  if (c.enable_footprint) {
    // A silhouette edge is where the surface hit changes: another object, another leg, the
    // floor, or nothing. (A continuous wall seen at grazing incidence is not an edge.)
    auto jump = [&](std::size_t i, std::size_t j) {
      const SubHit& a = echoes[i].centre;
      const SubHit& b = echoes[j].centre;
      return std::isfinite(a.range_m) != std::isfinite(b.range_m) || a.hit != b.hit ||
             a.kind != b.kind || a.object_id != b.object_id || a.part != b.part;
    };
    const auto w = static_cast<std::size_t>(
        std::max(1.0, std::ceil(0.5 * c.beam_divergence_rad / c.angle_increment_rad)));
    std::vector<bool> edge(n, false);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (!jump(i, i + 1)) continue;
      for (std::size_t k = i + 1 >= w ? i + 1 - w : 0; k <= std::min(n - 1, i + w); ++k) {
        edge[k] = true;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!edge[i]) continue;
      const double t = t0_s + static_cast<double>(i) * scan.time_increment;
      echoes[i] = CastBeam(world, poses[i], theta(i), moving_at(t), true);
    }
  }

  // Pass 3: what the sensor makes of each echo.
  for (std::size_t i = 0; i < n; ++i) {
    const Echo& echo = echoes[i];
    BeamTruth& truth = out.truth[i];
    truth.true_range_m = std::isfinite(echo.centre.range_m) ? echo.centre.range_m : kNaN;
    truth.mixed = echo.mixed;
    if (echo.centre.hit) {
      truth.kind = echo.centre.kind;
      truth.object_id = echo.centre.object_id;
      truth.part = echo.centre.part;
    } else if (echo.centre.floor) {
      truth.kind = ObjectKind::kFloor;
    }
    // A stray echo comes before the beam's own (the first echo is reported) or in its place.
    // Drawn only when switched on, so that every other scan stays as it was.
    if (c.stray_probability > 0.0 && uniform(rng_) < c.stray_probability) {
      const double own =
          std::isfinite(echo.range_m) ? std::min(echo.range_m, c.range_max_m) : c.range_max_m;
      const double r = c.range_min_m + (own - c.range_min_m) * uniform(rng_);
      scan.ranges[i] =
          c.enable_quantisation ? std::round(r / c.quantisation_m) * c.quantisation_m : r;
      truth.stray = true;
      if (c.enable_intensities) scan.intensities[i] = 0.05 * c.intensity_scale * uniform(rng_);
      continue;
    }
    if (!std::isfinite(echo.range_m)) continue;

    if (c.enable_dropouts) {
      const SubHit& s = echo.centre;
      double p = c.dropout_probability + c.dark_dropout_gain * (1.0 - s.reflectivity);
      if (s.shiny) p += c.shiny_dropout_gain * (1.0 - s.cos_incidence * s.cos_incidence);
      if (uniform(rng_) < p) continue;
    }
    double r = echo.range_m + c.range_bias_m;
    if (c.enable_range_noise) {
      r += (c.range_noise_sigma_m + c.range_noise_per_m * r) * gauss(rng_);
    }
    if (c.enable_quantisation) r = std::round(r / c.quantisation_m) * c.quantisation_m;
    if (r < c.range_min_m || r > c.range_max_m) continue;
    scan.ranges[i] = r;
    if (c.enable_intensities) {
      const double noise = 1.0 + c.intensity_noise_rel * gauss(rng_);
      scan.intensities[i] = std::max(0.0, c.intensity_scale * echo.intensity * noise);
    }
  }
  return out;
}

}  // namespace shelfdock::sim
