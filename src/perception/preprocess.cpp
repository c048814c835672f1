#include "perception/preprocess.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "perception/depth_step.hpp"
#include "perception/range_noise.hpp"
#include "perception/surface_continuation.hpp"
#include "perception/surface_protrusion.hpp"

namespace shelfdock::perception {

std::vector<ScanPoint> ScanToPoints(const geometry::LaserScan& scan) {
  std::vector<ScanPoint> out;
  out.reserve(scan.ranges.size());
  // The cos and sin of each beam's bearing come from the previous beam's, turned by the angle
  // increment (one complex multiplication instead of a sincos per beam, which was a quarter of a
  // detection's time on a room's scan), taken exactly every kAnchorBeams beams so that rounding
  // cannot build up (it stays below 1e-14 of the range). Each block's bearings are turned in a
  // loop of their own: with the points made in the same loop, the sincos call at each anchor
  // kept the running cos and sin in memory, and each beam waited for the previous one's store.
  constexpr std::size_t kAnchorBeams = 32;
  const double cos_step = std::cos(scan.angle_increment);
  const double sin_step = std::sin(scan.angle_increment);
  std::array<double, kAnchorBeams> cos_beam{};
  std::array<double, kAnchorBeams> sin_beam{};
  for (std::size_t anchor = 0; anchor < scan.ranges.size(); anchor += kAnchorBeams) {
    const std::size_t count = std::min(kAnchorBeams, scan.ranges.size() - anchor);
    const double anchor_angle = scan.BeamAngle(anchor);
    double c = std::cos(anchor_angle);
    double s = std::sin(anchor_angle);
    cos_beam[0] = c;
    sin_beam[0] = s;
    for (std::size_t k = 1; k < count; ++k) {
      const double c_prev = c;
      c = c_prev * cos_step - s * sin_step;
      s = s * cos_step + c_prev * sin_step;
      cos_beam[k] = c;
      sin_beam[k] = s;
    }
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = anchor + k;
      if (!scan.HasReturn(i)) continue;
      const double r = scan.ranges[i];
      out.push_back({Eigen::Vector2d(r * cos_beam[k], r * sin_beam[k]), r, scan.BeamAngle(i),
                     static_cast<int>(i)});
    }
  }
  return out;
}

namespace {
// A floor under the range noise the protrusion test divides by: a scan whose noise could not be
// estimated (no surfaces) reports 0.
constexpr double kMinProtrusionNoise_m = 0.005;

// The range-adaptive break test between beam neighbours a and b.
bool SameCluster(const ScanPoint& a, const ScanPoint& b, double alpha,
                 const PreprocessConfig& config) {
  // Neighbouring returns on one surface are about r * alpha apart (more at grazing
  // incidence); dropped beams in between widen the allowed gap proportionally.
  const int steps = std::max(1, std::abs(b.beam - a.beam));
  // A long hole is no surface: without a background (open space behind a shelf), the two back
  // legs are consecutive valid points 60 beams apart, and a gap widened by 60 beam spacings
  // would join them into one cluster.
  if (steps - 1 > config.cluster_max_missing_beams) return false;
  const double r = std::min(a.range, b.range);
  const double gap =
      config.cluster_gap_m + config.cluster_gap_beams * r * alpha * static_cast<double>(steps);
  return (b.p - a.p).squaredNorm() <= gap * gap;
}

// The span [begin, end) of `points` with its centroid and extent.
ClusterSpan MakeSpan(const std::vector<ScanPoint>& points, std::size_t begin, std::size_t end) {
  ClusterSpan span;
  span.begin = begin;
  span.end = end;
  double extent2 = 0.0;
  for (std::size_t k = begin; k < end; ++k) {
    span.centroid += points[k].p;
    extent2 = std::max(extent2, (points[k].p - points[begin].p).squaredNorm());
  }
  span.centroid /= static_cast<double>(end - begin);
  span.extent_m = std::sqrt(extent2);
  return span;
}
}  // namespace

std::vector<ClusterSpan> ClusterSpans(const std::vector<ScanPoint>& points,
                                      double angle_increment_rad, const PreprocessConfig& config) {
  std::vector<ClusterSpan> spans;
  const double alpha = std::abs(angle_increment_rad);
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= points.size(); ++i) {
    if (i < points.size() && SameCluster(points[i - 1], points[i], alpha, config)) continue;
    spans.push_back(MakeSpan(points, begin, i));
    begin = i;
  }
  return spans;
}

std::vector<Cluster> ClusterPoints(const std::vector<ScanPoint>& points, double angle_increment_rad,
                                   const PreprocessConfig& config) {
  std::vector<Cluster> clusters;
  for (const ClusterSpan& span : ClusterSpans(points, angle_increment_rad, config)) {
    Cluster c;
    c.points.assign(points.begin() + static_cast<std::ptrdiff_t>(span.begin),
                    points.begin() + static_cast<std::ptrdiff_t>(span.end));
    c.centroid = span.centroid;
    c.extent_m = span.extent_m;
    clusters.push_back(std::move(c));
  }
  return clusters;
}

double TrailingAngle(double range_far_m, double range_near_m, double alpha_rad) {
  return std::atan2(range_near_m * std::sin(alpha_rad),
                    range_far_m - range_near_m * std::cos(alpha_rad));
}

int RemoveTrailingPoints(std::vector<ScanPoint>& pts, double angle_increment_rad,
                         const PreprocessConfig& config) {
  if (pts.size() < 2) return 0;
  const double alpha = std::abs(angle_increment_rad);
  // Eq. 1's test beta < beta_min without its atan: beta is the angle of (x, y) = (|OF| - |ON|
  // cos(alpha), |ON| sin(alpha)), y > 0, and for 0 < beta_min <= pi that angle is below beta_min
  // exactly when x sin(beta_min) - y cos(beta_min) > 0 (an atan2 and a sincos per depth jump
  // were a tenth of a one-shelf detection). Neighbours are one or two beams apart.
  const double min_angle = config.trailing_min_angle_rad;
  const double sin_min = std::sin(min_angle);
  const double cos_min = std::cos(min_angle);
  const std::array<double, 3> sin_alpha{0.0, std::sin(alpha), std::sin(2.0 * alpha)};
  const std::array<double, 3> cos_alpha{1.0, std::cos(alpha), std::cos(2.0 * alpha)};
  std::vector<char> drop(pts.size(), 0);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    if (std::abs(pts[i + 1].beam - pts[i].beam) > 2) continue;  // not neighbours
    const bool first_far = pts[i].range > pts[i + 1].range;
    const ScanPoint& far = first_far ? pts[i] : pts[i + 1];
    const ScanPoint& near = first_far ? pts[i + 1] : pts[i];
    // Eq. 1 alone would flag range noise at short range, where neighbouring beams are only
    // millimetres apart; a mixed point also needs a depth jump larger than the noise.
    if (far.range - near.range < config.trailing_min_jump_m) continue;
    const int steps = std::max(1, std::abs(far.beam - near.beam));
    const double x = far.range - near.range * cos_alpha[steps];
    const double y = near.range * sin_alpha[steps];
    if (min_angle > 0.0 && x * sin_min - y * cos_min > 0.0) drop[first_far ? i : i + 1] = 1;
  }
  // Compact in place (no second buffer).
  std::size_t write = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!drop[i]) pts[write++] = pts[i];
  }
  const int removed = static_cast<int>(pts.size() - write);
  pts.resize(write);
  return removed;
}

double NarrowestLegSection(const std::vector<geometry::ShelfModel>& models) {
  double narrowest = std::numeric_limits<double>::infinity();
  for (const auto& m : models) narrowest = std::min({narrowest, m.leg.width_m, m.leg.length_m});
  return narrowest;
}

double MaxLegExtent(const std::vector<geometry::ShelfModel>& models, const PreprocessConfig& config,
                    double range_noise_m) {
  double max_extent = 0.0;
  for (const auto& m : models) max_extent = std::max(max_extent, m.leg.Extent());
  // At 20 mm range noise the four returns of a 40 mm leg seen corner-on spread over 0.1 m in
  // depth: a fixed margin alone threw such legs away (eval-layouts, 20 mm classes).
  return max_extent + std::max(config.leg_extent_margin_m,
                               config.leg_extent_noise_sigmas * std::sqrt(2.0) * range_noise_m);
}

double SplitStep(const PreprocessConfig& config, double range_noise_m) {
  return std::max(config.split_min_step_m,
                  config.split_noise_steps * std::sqrt(2.0) * range_noise_m);
}

double SurfaceTolerance(const PreprocessConfig& config, double range_noise_m) {
  return std::max(config.surface_tolerance_m, config.surface_noise_sigmas * range_noise_m);
}

ProtrusionLimits SurfaceTestLimits(const PreprocessConfig& config, double range_noise_m,
                                   double max_leg_extent_m) {
  ProtrusionLimits limits;
  limits.range_noise_m = std::max(range_noise_m, kMinProtrusionNoise_m);
  limits.surface_points = config.inner_surface_points;
  limits.surface_rms_m = SurfaceTolerance(config, range_noise_m);
  limits.max_missing_beams = config.cluster_max_missing_beams;
  limits.max_extent_m = max_leg_extent_m;
  limits.min_step_m =
      std::max(config.split_min_step_m, config.inner_step_sigmas * std::sqrt(2.0) * range_noise_m);
  return limits;
}

// Beams a leg of the models' narrowest section spans at `centroid`'s range.
double BeamsAcrossSmallestLeg(const Eigen::Vector2d& centroid, double angle_increment_rad,
                              const std::vector<geometry::ShelfModel>& models) {
  const double spacing = std::max(centroid.norm() * std::abs(angle_increment_rad), 1e-6);
  return NarrowestLegSection(models) / spacing;
}

// True when the two beams on each side of `beam` returned from one surface there (each pair
// within flat_m of each other): the background a lone return at `beam` stands in front of, seen
// clean. A thin leg seen by a sensor that blends its edge beams with what stands behind has a
// blend beside it, off the surface.
bool OnSurfaceBothSides(const std::vector<ScanPoint>& points, int beam, double flat_m) {
  const std::size_t k = IndexOfBeam(points, beam);
  if (k == points.size() || points[k].beam != beam) return false;
  auto flat = [&](std::size_t a, std::size_t b) {
    return points[a].beam + 1 == points[b].beam &&
           std::abs(points[a].range - points[b].range) < flat_m;
  };
  return k >= 2 && k + 2 < points.size() && flat(k - 2, k - 1) && flat(k + 1, k + 2) &&
         points[k - 1].beam == beam - 1 && points[k + 1].beam == beam + 1;
}

bool FitsLegSize(const Eigen::Vector2d& centroid, double extent_m, std::size_t num_points,
                 double angle_increment_rad, const std::vector<geometry::ShelfModel>& models,
                 const PreprocessConfig& config, double max_extent_m) {
  if (num_points == 0 || models.empty() || extent_m > max_extent_m) return false;
  // Beams expected across the smallest leg at this range: a short-range cluster of one or two
  // points is noise or a mixed point, not a leg.
  const double expected = BeamsAcrossSmallestLeg(centroid, angle_increment_rad, models);
  const int needed = std::max(config.min_points,
                              static_cast<int>(std::floor(config.min_point_fraction * expected)));
  return static_cast<int>(num_points) >= needed;
}

PreprocessOutput Preprocess(const std::vector<ScanPoint>& points, double angle_increment_rad,
                            const std::optional<geometry::Pose2>& T_lidar_preset,
                            const std::vector<geometry::ShelfModel>& models,
                            const PreprocessConfig& config) {
  PreprocessOutput out;
  double longest_diagonal = 0.0;
  for (const auto& m : models) longest_diagonal = std::max(longest_diagonal, m.Diagonal());
  const double roi_radius = config.roi_gamma * longest_diagonal;

  // The paper filters trailing points inside each cluster. A mixed point sits between a leg
  // and the background, usually farther from both than the break distance, so it would form a
  // cluster of its own and escape that test: Eq. 1 is applied to beam neighbours before
  // clustering instead (the leg's own point is the near one and is kept).
  out.points = points;
  out.trailing_removed = RemoveTrailingPoints(out.points, angle_increment_rad, config);

  // How the sensor makes mixed points, from the scan's large depth steps before the filter
  // dropped any. A pulsed sensor that separates far echoes, as our simulator's and the real
  // recordings', leaves them mostly clean (3 % bridged in our scenes, 1.5 % and 7.7 % in the two
  // real bags; no scan of 2000 simulated and 1965 real ones with 4 bridged and half of them); one
  // that blends every echo (config/lidar_variants/blend_any.yaml) bridges 84 % (757 of 1000 scans
  // over that bar), and a thin leg's returns before a far background are blends pulled toward it
  // by centimetres, its outline's edge beams mostly lost. A scan with few steps stays below the
  // bar. Each surface of a step goes on for a beam within kFlat_m (10-20 mm noise, a surface
  // seen obliquely), and a mixed point lies farther than that from both.
  constexpr double kFlat_m = 0.1;
  out.edge_blending = EstimateEdgeBlending(points, config.blend_probe_gap_m, kFlat_m);
  out.blends_every_echo = config.blend_any_share > 0.0 &&
                          out.edge_blending.bridged >= config.blend_any_min_bridged &&
                          out.edge_blending.Share() >= config.blend_any_share;

  // Clustering runs on all points and the ROI is applied to whole clusters: cutting points at
  // the ROI circle first would turn the clipped end of a wall into a leg-sized fragment.
  // Only candidates are copied out (a scan has a few hundred clusters, most of them wall
  // pieces).
  out.spans = ClusterSpans(out.points, angle_increment_rad, config);
  out.range_noise_m = EstimateRangeNoise(out.points, out.spans).sigma_m;
  const double max_leg_extent = MaxLegExtent(models, config, out.range_noise_m);
  const double split_step = SplitStep(config, out.range_noise_m);
  const double surface_tolerance = SurfaceTolerance(config, out.range_noise_m);
  // `piece` (a span or part of span si) as a candidate, when it has min_points and fits a leg.
  auto add_candidate = [&](const ClusterSpan& piece, int si, std::size_t min_points,
                           bool from_surface = false) {
    if (piece.size() < min_points ||
        !FitsLegSize(piece.centroid, piece.extent_m, piece.size(), angle_increment_rad, models,
                     config, max_leg_extent)) {
      return false;
    }
    if (ContinuesSurface(out.points, piece.begin, piece.end, config.surface_max_step_m,
                         max_leg_extent, surface_tolerance)) {
      return false;
    }
    // An end piece and a split piece may be the same points: one candidate for them.
    for (auto it = out.candidates.rbegin(); it != out.candidates.rend() && it->span == si; ++it) {
      if (it->points.size() == piece.size() &&
          it->points.front().beam == out.points[piece.begin].beam) {
        return false;
      }
    }
    Cluster c;
    c.points.assign(out.points.begin() + static_cast<std::ptrdiff_t>(piece.begin),
                    out.points.begin() + static_cast<std::ptrdiff_t>(piece.end));
    c.centroid = piece.centroid;
    c.extent_m = piece.extent_m;
    c.span = si;
    c.from_surface = from_surface;
    c.edges = FindSilhouetteEdges(points, c.points.front(), c.points.back(), split_step);
    // One return whose neighbours on both sides passed by and returned from farther away marks
    // something narrower than two beam spacings. Where the narrowest leg spans more beams than
    // lone_return_max_beams, the beams beside would have hit such a leg too: the return is no
    // leg but a stray echo (dust, another robot's LiDAR; config/lidar_variants/stray_echoes.yaml)
    // or a thin thing no shelf stands on. Min_point_fraction cannot tell it: a leg peeking past an
    // occluder, or one whose other returns dropped out, shows one return too, but not one with
    // the background on both sides.
    if (config.lone_return_max_beams > 0.0 && c.points.size() == 1 && c.edges.before_rad &&
        c.edges.after_rad && c.edges.before_step_m.value_or(0.0) > config.lone_return_min_step_m &&
        c.edges.after_step_m.value_or(0.0) > config.lone_return_min_step_m &&
        OnSurfaceBothSides(points, c.points.front().beam, kFlat_m) &&
        BeamsAcrossSmallestLeg(c.centroid, angle_increment_rad, models) >
            config.lone_return_max_beams) {
      ++out.stray_returns;
      return false;
    }
    out.candidates.push_back(std::move(c));
    return true;
  };
  ProtrusionLimits protrusion = SurfaceTestLimits(config, out.range_noise_m, max_leg_extent);
  protrusion.min_offset_m = config.inner_min_offset_m;
  protrusion.offset_sigmas = config.inner_offset_sigmas;
  if (T_lidar_preset) {
    protrusion.roi_centre = T_lidar_preset->translation();
    protrusion.roi_radius_m = roi_radius;
  }
  auto in_roi = [&](const Eigen::Vector2d& p) {
    return !T_lidar_preset || (p - T_lidar_preset->translation()).norm() <= roi_radius;
  };
  for (std::size_t si = 0; si < out.spans.size(); ++si) {
    const ClusterSpan& span = out.spans[si];
    // A leg just in front of a wall (a shelf pushed against it, a row's back legs before a
    // rack) lies inside the wall's cluster; the ROI is then tested on the piece, since a long
    // wall's centroid may lie far from the preset. Only clusters too wide to be a leg with
    // something touching it (split at their strongest step below) are surfaces: the middle of
    // a person's leg stands out in front of its sides as well (eval-layouts
    // --scenes-per-class 1000 --seed0 5001: 3 people beside legs lost when any cluster wider
    // than a leg was searched).
    if (config.split_inner_pieces && span.extent_m > max_leg_extent + config.split_max_extra_m) {
      for (const PieceRange& r : SurfaceProtrusions(out.points, span, protrusion)) {
        const ClusterSpan piece = MakeSpan(out.points, r.begin, r.end);
        if (in_roi(piece.centroid)) {
          out.split_candidates += add_candidate(piece, static_cast<int>(si), 2, true);
        }
      }
    }
    if (!in_roi(span.centroid)) continue;
    ++out.clusters;
    out.roi_points += static_cast<int>(span.size());
    if (add_candidate(span, static_cast<int>(si), 1)) continue;
    const int s = static_cast<int>(si);
    // A leg may stand just in front of a wall or a box, closer to it than the break distance:
    // a leg-sized piece at either end of the cluster, a split step in front of the rest.
    if (config.split_end_pieces) {
      const EndPieces ends = FrontEndPieces(out.points, span, max_leg_extent, split_step);
      if (ends.front_end) {
        out.split_candidates +=
            add_candidate(MakeSpan(out.points, span.begin, *ends.front_end), s, 2);
      }
      if (ends.back_begin) {
        out.split_candidates +=
            add_candidate(MakeSpan(out.points, *ends.back_begin, span.end), s, 2);
      }
    }
    // Too wide for a leg, but not by much: a leg with something touching it (a person's leg,
    // a box) is cut out at the strongest depth step, when that step stands out of the noise.
    if (span.extent_m > max_leg_extent + config.split_max_extra_m) continue;
    // A piece needs two points: one return beside a step is as often a mixed point.
    if (const auto k = StrongestDepthStep(out.points, span, split_step)) {
      out.split_candidates += add_candidate(MakeSpan(out.points, span.begin, *k), s, 2);
      out.split_candidates += add_candidate(MakeSpan(out.points, *k, span.end), s, 2);
    }
  }
  // The reverse: range noise comparable to the beam spacing (20 mm at half a metre) breaks one
  // leg into neighbouring fragments, each too narrow to show the leg's width. Runs of
  // neighbouring clusters whose breaks are no deeper than the noise explains (the split step)
  // and no longer than the missing beams a cluster tolerates are offered whole as well, when
  // the whole fits a leg; the fragments stay candidates too, the evidence decides.
  auto noise_break = [&](std::size_t a, std::size_t b) {
    const ScanPoint& p = out.points[a];
    const ScanPoint& q = out.points[b];
    return std::abs(q.beam - p.beam) - 1 <= config.cluster_max_missing_beams &&
           std::abs(q.range - p.range) <= split_step;
  };
  for (std::size_t si = 0; config.join_noise_breaks && si + 1 < out.spans.size(); ++si) {
    const ClusterSpan& first = out.spans[si];
    if (T_lidar_preset && (first.centroid - T_lidar_preset->translation()).norm() > roi_radius) {
      continue;
    }
    for (std::size_t sj = si + 1; sj < out.spans.size(); ++sj) {
      if (!noise_break(out.spans[sj - 1].end - 1, out.spans[sj].begin)) break;
      const ClusterSpan whole = MakeSpan(out.points, first.begin, out.spans[sj].end);
      if (whole.extent_m > max_leg_extent) break;
      out.joined_candidates += add_candidate(whole, static_cast<int>(si), 2);
    }
  }
  return out;
}

}  // namespace shelfdock::perception
