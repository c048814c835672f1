#include "perception/surface_protrusion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <Eigen/Eigenvalues>

namespace shelfdock::perception {
namespace {

// A surface seen at a grazing angle places itself poorly along the beams.
constexpr double kMinCosIncidence = 0.2;
// Fewest points on each side that show the surface behind a piece: two may both be a leg's
// (a part of a leg would then stand out in front of its own rest).
constexpr std::size_t kMinSidePoints = 3;
// The surface's line comes from this many times surface_points on each side.
constexpr int kLineReach = 3;

// Beam neighbours: consecutive valid points with at most max_missing_beams beams without a
// return between them (dark patches drop some) and, when surface_max_step_m is finite, no
// farther apart than that.
bool Neighbours(const ScanPoint& a, const ScanPoint& b, const ProtrusionLimits& limits) {
  if (std::abs(b.beam - a.beam) - 1 > limits.max_missing_beams) return false;
  return std::isinf(limits.surface_max_step_m) ||
         (b.p - a.p).squaredNorm() <= limits.surface_max_step_m * limits.surface_max_step_m;
}

// The points beside [begin, end): up to `count` consecutive beam neighbours on each side,
// as [before, begin) and [end, after).
std::size_t ReachBack(const std::vector<ScanPoint>& points, std::size_t begin, int count,
                      const ProtrusionLimits& limits) {
  std::size_t i = begin;
  while (i > 0 && static_cast<int>(begin - i) < count &&
         Neighbours(points[i - 1], points[i], limits)) {
    --i;
  }
  return i;
}
std::size_t ReachOn(const std::vector<ScanPoint>& points, std::size_t end, int count,
                    const ProtrusionLimits& limits) {
  std::size_t i = end;
  while (i < points.size() && static_cast<int>(i - end) < count &&
         Neighbours(points[i - 1], points[i], limits)) {
    ++i;
  }
  return i;
}

// A piece [begin, end) and the surface_points right beside it, [before, begin) and
// [end, after).
struct Beside {
  std::size_t before = 0;
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t after = 0;
};

// The side of `b` without points ends the object at a silhouette edge: the return past the piece
// there (the next beam's, up to max_missing_beams on) lies farther than the piece's end by
// more than min_step_m, or there is none (the sky past a shelf's corner). A nearer return there
// is an occluder: what it hides may be the surface going on in front of the piece.
bool OpenEnd(const std::vector<ScanPoint>& points, const Beside& b,
             const ProtrusionLimits& limits) {
  // One object: the piece's ranges within a leg's extent of each other (not an occluder's
  // returns and the surface's behind it).
  const auto [nearest, farthest] =
      std::minmax_element(points.begin() + static_cast<std::ptrdiff_t>(b.begin),
                          points.begin() + static_cast<std::ptrdiff_t>(b.end),
                          [](const ScanPoint& x, const ScanPoint& y) { return x.range < y.range; });
  if (farthest->range - nearest->range > limits.max_extent_m) return false;
  const bool open_after = b.after == b.end;
  const std::size_t last = open_after ? b.end - 1 : b.begin;  // the piece's point at that end
  const std::size_t past = open_after ? b.end : b.begin;      // index of the return past it
  if (open_after ? past >= points.size() : past == 0) return true;
  const ScanPoint& q = open_after ? points[past] : points[past - 1];
  if (std::abs(q.beam - points[last].beam) - 1 > limits.max_missing_beams) return true;
  return q.range - farthest->range > limits.min_step_m;
}

// The piece with the points right beside it; nullopt when either side has fewer than
// kMinSidePoints.
std::optional<Beside> PointsBeside(const std::vector<ScanPoint>& points, std::size_t begin,
                                   std::size_t end, const ProtrusionLimits& limits) {
  const int k = std::max(1, limits.surface_points);
  const Beside b{ReachBack(points, begin, k, limits), begin, end, ReachOn(points, end, k, limits)};
  const std::size_t shorter = std::min(b.begin - b.before, b.after - b.end);
  const std::size_t longer = std::max(b.begin - b.before, b.after - b.end);
  if (longer < kMinSidePoints) return std::nullopt;
  if (shorter == 0 && limits.open_end && OpenEnd(points, b, limits)) return b;
  if (shorter < static_cast<std::size_t>(std::max(1, limits.short_side_points))) {
    return std::nullopt;
  }
  return b;
}

// A quick look first (most pieces a step starts are none: a wall seen at a grazing angle steps
// at every beam): the piece's mean range in front of the sides' mean ranges interpolated to its
// middle beam by half the offset StandOut asks for.
bool MayStandOut(const std::vector<ScanPoint>& points, const Beside& side,
                 const ProtrusionLimits& limits) {
  auto mean_of = [&](std::size_t from, std::size_t to, double& range, double& beam) {
    range = 0.0;
    beam = 0.0;
    for (std::size_t i = from; i < to; ++i) {
      range += points[i].range;
      beam += points[i].beam;
    }
    range /= static_cast<double>(to - from);
    beam /= static_cast<double>(to - from);
  };
  double r_before, b_before, r_after, b_after, r_piece, b_piece;
  mean_of(side.begin, side.end, r_piece, b_piece);
  if (side.before == side.begin || side.end == side.after) {  // an open end: one side's mean
    const bool open_after = side.end == side.after;
    mean_of(open_after ? side.before : side.end, open_after ? side.begin : side.after, r_before,
            b_before);
    return r_before - r_piece >= 0.5 * limits.min_offset_m;
  }
  mean_of(side.before, side.begin, r_before, b_before);
  mean_of(side.end, side.after, r_after, b_after);
  if (b_after == b_before) return false;
  const double t = (b_piece - b_before) / (b_after - b_before);
  return r_before + t * (r_after - r_before) - r_piece >= 0.5 * limits.min_offset_m;
}

// How far [begin, end) stands out in front of the line through the points beside it, in sigmas
// of its mean offset; nullopt when the points beside it do not make one surface. The points
// beside it may lie beyond the cluster: the far point of the step at a leg's edge is often
// dropped as a mixed point, which breaks the cluster there.
std::optional<double> StandOut(const std::vector<ScanPoint>& points, const Beside& side,
                               const ProtrusionLimits& limits) {
  const int k = std::max(1, limits.surface_points);
  const auto [before, begin, end, after] = side;
  // The surface's line from a wider stretch beside the piece (kLineReach times as many points
  // on each side): a line through a few points either side can tilt to pass between a wall on
  // one side and the rest of a leg on the other, and then a part of the leg stands out from it.
  // The points right beside the piece must lie on that line (below): at the apex of a box's
  // corner or a round object they stand out with the piece.
  const std::size_t wide_before = ReachBack(points, begin, kLineReach * k, limits);
  const std::size_t wide_after = ReachOn(points, end, kLineReach * k, limits);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  int n_wide = 0;
  auto each_wide = [&](auto&& f) {
    for (std::size_t i = wide_before; i < begin; ++i) f(points[i]);
    for (std::size_t i = end; i < wide_after; ++i) f(points[i]);
  };
  each_wide([&](const ScanPoint& q) {
    mean += q.p;
    ++n_wide;
  });
  mean /= static_cast<double>(n_wide);
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  each_wide([&](const ScanPoint& q) { scatter += (q.p - mean) * (q.p - mean).transpose(); });
  // Total least squares: the normal is the scatter's smaller axis.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  const Eigen::Vector2d normal = eig.eigenvectors().col(0);
  if (std::sqrt(eig.eigenvalues()(0) / n_wide) > limits.surface_rms_m) return std::nullopt;
  const double c = normal.dot(mean);
  // The returns' mean offset in front of the line along their beams: the line's range on each
  // bearing minus the return's.
  auto mean_offset = [&](std::size_t from, std::size_t to) -> std::optional<double> {
    double sum = 0.0;
    for (std::size_t i = from; i < to; ++i) {
      const Eigen::Vector2d u = points[i].p / points[i].range;
      const double cos_incidence = normal.dot(u);
      if (std::abs(cos_incidence) < kMinCosIncidence) return std::nullopt;
      sum += c / cos_incidence - points[i].range;
    }
    return sum / static_cast<double>(to - from);
  };
  const auto offset = mean_offset(begin, end);
  // An open end's side has no points: nothing there stands out with the piece.
  const auto offset_before =
      before == begin ? std::optional<double>(0.0) : mean_offset(before, begin);
  const auto offset_after = end == after ? std::optional<double>(0.0) : mean_offset(end, after);
  if (!offset || !offset_before || !offset_after || *offset < limits.min_offset_m) {
    return std::nullopt;
  }
  // Each side lies on the line, not in front of it with the piece: a line through the wall on
  // one side and the rest of the leg on the other would pass between them, and a part of the
  // leg would stand out from it.
  if (std::max(*offset_before, *offset_after) > 0.5 * *offset) return std::nullopt;
  const double n = static_cast<double>(end - begin);
  const double sigma = limits.range_noise_m * std::sqrt(1.0 / n + 1.0 / n_wide);
  if (sigma <= 0.0) return std::nullopt;
  return *offset / sigma;
}

}  // namespace

std::optional<double> ProtrusionSigmas(const std::vector<ScanPoint>& points, std::size_t begin,
                                       std::size_t end, const ProtrusionLimits& limits) {
  if (begin >= end || end > points.size()) return std::nullopt;
  const auto side = PointsBeside(points, begin, end, limits);
  if (!side || !MayStandOut(points, *side, limits)) return std::nullopt;
  return StandOut(points, *side, limits);
}

std::vector<PieceRange> SurfaceProtrusions(const std::vector<ScanPoint>& points,
                                           const ClusterSpan& span,
                                           const ProtrusionLimits& limits) {
  struct Scored {
    PieceRange piece;
    double z;
  };
  std::vector<Scored> found;
  if (span.size() < 2) return {};
  const double reach = limits.roi_radius_m + limits.max_extent_m;
  const double reach2 = reach * reach;
  auto fits = [&](std::size_t a, std::size_t b) {  // [a, b) no wider than a leg
    return (points[b - 1].p - points[a].p).norm() <= limits.max_extent_m;
  };
  auto consider = [&](std::size_t a, std::size_t b, std::optional<Scored>& best) {
    const auto side = PointsBeside(points, a, b, limits);
    if (!side || !MayStandOut(points, *side, limits)) return;
    const auto z = StandOut(points, *side, limits);
    if (z && *z >= limits.offset_sigmas && (!best || *z > best->z)) best = Scored{{a, b}, *z};
  };
  // A boundary k lies between points k - 1 and k; the pieces lie inside the span, the steps
  // that start or end them may cross its ends (a cluster break).
  for (std::size_t k = std::max<std::size_t>(span.begin, 1); k <= span.end && k < points.size();
       ++k) {
    if (!Neighbours(points[k - 1], points[k], limits)) continue;
    if (limits.roi_centre && (points[k].p - *limits.roi_centre).squaredNorm() > reach2) continue;
    // A step toward the sensor at k starts a piece [k, j) ...
    if (k < span.end && points[k - 1].range - points[k].range >= limits.min_step_m) {
      std::optional<Scored> best;
      for (std::size_t j = k + 2; j <= span.end && fits(k, j); ++j) consider(k, j, best);
      if (best) found.push_back(*best);
    }
    // ... a step away from it at k ends a piece [i, k).
    if (k >= span.begin + 2 && points[k].range - points[k - 1].range >= limits.min_step_m) {
      std::optional<Scored> best;
      for (std::size_t i = k - 2; i + 1 > span.begin && fits(i, k); --i) {
        consider(i, k, best);
        if (i == 0) break;
      }
      if (best) found.push_back(*best);
    }
  }
  // Overlapping pieces: the one standing out most.
  std::sort(found.begin(), found.end(), [](const Scored& a, const Scored& b) { return a.z > b.z; });
  std::vector<PieceRange> out;
  for (const Scored& s : found) {
    const bool overlaps = std::any_of(out.begin(), out.end(), [&](const PieceRange& r) {
      return s.piece.begin < r.end && r.begin < s.piece.end;
    });
    if (!overlaps) out.push_back(s.piece);
  }
  std::sort(out.begin(), out.end(),
            [](const PieceRange& a, const PieceRange& b) { return a.begin < b.begin; });
  return out;
}

}  // namespace shelfdock::perception
