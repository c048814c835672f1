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

// The points [lo, hi) a search looks at, with what every piece among them asks again and again:
// which consecutive points are beam neighbours, and the sums of ranges and beams from lo (a
// wall seen at a grazing angle steps at every beam, and each step is tried with every piece
// length that fits a leg; recomputing these per piece was a quarter of a one-shelf detection).
class Surroundings {
 public:
  Surroundings(const std::vector<ScanPoint>& points, std::size_t lo, std::size_t hi,
               const ProtrusionLimits& limits)
      : points_(points),
        lo_(lo),
        linked_(hi - lo, 0),
        range_sum_(hi - lo + 1, 0.0),
        beam_sum_(hi - lo + 1, 0.0) {
    // The running sums stay in registers: read back from the arrays, each point waited for the
    // previous store (a tenth of the surface test's time on a room's scan).
    double range_sum = 0.0;
    double beam_sum = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      linked_[i - lo] = i > 0 && Neighbours(points[i - 1], points[i], limits);
      range_sum += points[i].range;
      beam_sum += points[i].beam;
      range_sum_[i - lo + 1] = range_sum;
      beam_sum_[i - lo + 1] = beam_sum;
    }
  }
  const std::vector<ScanPoint>& points() const { return points_; }
  std::size_t lo() const { return lo_; }
  std::size_t hi() const { return lo_ + linked_.size(); }
  // Points i - 1 and i are beam neighbours (lo <= i < hi; never for i = 0).
  bool Linked(std::size_t i) const { return linked_[i - lo_] != 0; }
  // Mean range and beam of [from, to) (lo <= from < to <= hi).
  void Mean(std::size_t from, std::size_t to, double& range, double& beam) const {
    const double n = static_cast<double>(to - from);
    range = (range_sum_[to - lo_] - range_sum_[from - lo_]) / n;
    beam = (beam_sum_[to - lo_] - beam_sum_[from - lo_]) / n;
  }

 private:
  const std::vector<ScanPoint>& points_;
  std::size_t lo_;
  std::vector<char> linked_;
  std::vector<double> range_sum_;
  std::vector<double> beam_sum_;
};

// The points beside [begin, end): up to `count` consecutive beam neighbours on each side,
// as [before, begin) and [end, after). The surroundings reach past every piece by more than
// `count` (or to the scan's ends), so they never cut a side short.
std::size_t ReachBack(const Surroundings& s, std::size_t begin, int count) {
  std::size_t i = begin;
  while (i > s.lo() && static_cast<int>(begin - i) < count && s.Linked(i)) --i;
  return i;
}
std::size_t ReachOn(const Surroundings& s, std::size_t end, int count) {
  std::size_t i = end;
  while (i < s.hi() && static_cast<int>(i - end) < count && s.Linked(i)) ++i;
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
std::optional<Beside> PointsBeside(const Surroundings& s, std::size_t begin, std::size_t end,
                                   const ProtrusionLimits& limits) {
  const std::vector<ScanPoint>& points = s.points();
  const int k = std::max(1, limits.surface_points);
  const Beside b{ReachBack(s, begin, k), begin, end, ReachOn(s, end, k)};
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
bool MayStandOut(const Surroundings& s, const Beside& side, const ProtrusionLimits& limits) {
  double r_before, b_before, r_after, b_after, r_piece, b_piece;
  s.Mean(side.begin, side.end, r_piece, b_piece);
  if (side.before == side.begin || side.end == side.after) {  // an open end: one side's mean
    const bool open_after = side.end == side.after;
    s.Mean(open_after ? side.before : side.end, open_after ? side.begin : side.after, r_before,
           b_before);
    return r_before - r_piece >= 0.5 * limits.min_offset_m;
  }
  s.Mean(side.before, side.begin, r_before, b_before);
  s.Mean(side.end, side.after, r_after, b_after);
  if (b_after == b_before) return false;
  const double t = (b_piece - b_before) / (b_after - b_before);
  return r_before + t * (r_after - r_before) - r_piece >= 0.5 * limits.min_offset_m;
}

// How far [begin, end) stands out in front of the line through the points beside it, in sigmas
// of its mean offset; nullopt when the points beside it do not make one surface. The points
// beside it may lie beyond the cluster: the far point of the step at a leg's edge is often
// dropped as a mixed point, which breaks the cluster there.
std::optional<double> StandOut(const Surroundings& s, const Beside& side,
                               const ProtrusionLimits& limits) {
  const std::vector<ScanPoint>& points = s.points();
  const int k = std::max(1, limits.surface_points);
  const auto [before, begin, end, after] = side;
  // The surface's line from a wider stretch beside the piece (kLineReach times as many points
  // on each side): a line through a few points either side can tilt to pass between a wall on
  // one side and the rest of a leg on the other, and then a part of the leg stands out from it.
  // The points right beside the piece must lie on that line (below): at the apex of a box's
  // corner or a round object they stand out with the piece.
  const std::size_t wide_before = ReachBack(s, begin, kLineReach * k);
  const std::size_t wide_after = ReachOn(s, end, kLineReach * k);
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

// The surroundings of the points [begin, end): every point the sides and the surface's line of a
// piece among them may reach, and one more on each side.
Surroundings Around(const std::vector<ScanPoint>& points, std::size_t begin, std::size_t end,
                    const ProtrusionLimits& limits) {
  const std::size_t reach =
      static_cast<std::size_t>(kLineReach * std::max(1, limits.surface_points)) + 1;
  return Surroundings(points, begin > reach ? begin - reach : 0,
                      std::min(points.size(), end + reach), limits);
}

}  // namespace

std::optional<double> ProtrusionSigmas(const std::vector<ScanPoint>& points, std::size_t begin,
                                       std::size_t end, const ProtrusionLimits& limits) {
  if (begin >= end || end > points.size()) return std::nullopt;
  const Surroundings s = Around(points, begin, end, limits);
  const auto side = PointsBeside(s, begin, end, limits);
  if (!side || !MayStandOut(s, *side, limits)) return std::nullopt;
  return StandOut(s, *side, limits);
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
  const Surroundings s = Around(points, span.begin, span.end, limits);
  const double reach = limits.roi_radius_m + limits.max_extent_m;
  const double reach2 = reach * reach;
  auto fits = [&](std::size_t a, std::size_t b) {  // [a, b) no wider than a leg
    return (points[b - 1].p - points[a].p).norm() <= limits.max_extent_m;
  };
  auto consider = [&](std::size_t a, std::size_t b, std::optional<Scored>& best) {
    const auto side = PointsBeside(s, a, b, limits);
    if (!side || !MayStandOut(s, *side, limits)) return;
    const auto z = StandOut(s, *side, limits);
    if (z && *z >= limits.offset_sigmas && (!best || *z > best->z)) best = Scored{{a, b}, *z};
  };
  // A boundary k lies between points k - 1 and k; the pieces lie inside the span, the steps
  // that start or end them may cross its ends (a cluster break).
  for (std::size_t k = std::max<std::size_t>(span.begin, 1); k <= span.end && k < points.size();
       ++k) {
    if (!s.Linked(k)) continue;
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
