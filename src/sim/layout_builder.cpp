#include "sim/layout_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shelfdock::sim::layout {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double PointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

bool SegmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double d1 = Cross(b - a, c - a), d2 = Cross(b - a, d - a);
  const double d3 = Cross(d - c, a - c), d4 = Cross(d - c, b - c);
  return ((d1 > 0.0) != (d2 > 0.0)) && ((d3 > 0.0) != (d4 > 0.0));
}

double SegmentDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  if (SegmentsCross(a, b, c, d)) return 0.0;
  return std::min({PointSegmentDistance(a, c, d), PointSegmentDistance(b, c, d),
                   PointSegmentDistance(c, a, b), PointSegmentDistance(d, a, b)});
}

/// The solid's edges as (start, end) pairs: closed for polygons, open for polylines.
std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> Edges(const Solid& s) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges;
  const std::size_t n = s.points.size();
  const std::size_t count = s.kind == Solid::Kind::kPolygon ? n : (n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i < count; ++i) edges.emplace_back(s.points[i], s.points[(i + 1) % n]);
  return edges;
}

/// Inside a convex polygon of either winding.
bool Inside(const Solid& polygon, const Eigen::Vector2d& p) {
  if (polygon.kind != Solid::Kind::kPolygon) return false;
  bool positive = false, negative = false;
  for (const auto& [a, b] : Edges(polygon)) {
    const double c = Cross(b - a, p - a);
    positive |= c > 0.0;
    negative |= c < 0.0;
  }
  return !(positive && negative);
}

double OutlineDistance(const Solid& a, const Solid& b) {
  for (const auto& p : b.points) {
    if (Inside(a, p)) return 0.0;
  }
  for (const auto& p : a.points) {
    if (Inside(b, p)) return 0.0;
  }
  double best = kInf;
  for (const auto& [p, q] : Edges(a)) {
    for (const auto& [r, s] : Edges(b)) best = std::min(best, SegmentDistance(p, q, r, s));
  }
  return best;
}
}  // namespace

SceneRng::SceneRng(std::uint64_t seed, std::uint64_t stream, std::uint64_t attempt) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(attempt)};
  engine_.seed(seq);
}

double SceneRng::Uniform(double lo, double hi) {
  // The top 53 bits as a double in [0, 1).
  const double u = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

int SceneRng::Int(int lo, int hi) {
  const int k = lo + static_cast<int>(std::floor(Uniform(0.0, hi - lo + 1.0)));
  return std::min(k, hi);
}

std::size_t SceneRng::Index(std::size_t n) {
  return static_cast<std::size_t>(Int(0, static_cast<int>(n) - 1));
}

bool SceneRng::Chance(double p) { return Uniform(0.0, 1.0) < p; }

double SceneRng::Angle() { return Uniform(-std::numbers::pi, std::numbers::pi); }

Solid Solid::Circle(const Eigen::Vector2d& centre, double radius_m) {
  Solid s;
  s.kind = Kind::kCircle;
  s.centre = centre;
  s.radius_m = radius_m;
  return s;
}

Solid Solid::Rectangle(const geometry::Pose2& T_world_rect, double length_m, double width_m) {
  Solid s;
  s.kind = Kind::kPolygon;
  const double hl = 0.5 * length_m, hw = 0.5 * width_m;
  s.points = {T_world_rect * Eigen::Vector2d(-hl, -hw), T_world_rect * Eigen::Vector2d(hl, -hw),
              T_world_rect * Eigen::Vector2d(hl, hw), T_world_rect * Eigen::Vector2d(-hl, hw)};
  s.centre = T_world_rect.translation();
  return s;
}

Solid Solid::Polyline(std::vector<Eigen::Vector2d> points) {
  Solid s;
  s.kind = Kind::kPolyline;
  s.points = std::move(points);
  return s;
}

double SolidDistance(const Solid& a, const Eigen::Vector2d& p) {
  if (a.kind == Solid::Kind::kCircle) return std::max(0.0, (p - a.centre).norm() - a.radius_m);
  if (Inside(a, p)) return 0.0;
  double best = kInf;
  for (const auto& [s, e] : Edges(a)) best = std::min(best, PointSegmentDistance(p, s, e));
  return best;
}

double SolidDistance(const Solid& a, const Solid& b) {
  if (a.kind == Solid::Kind::kCircle) return std::max(0.0, SolidDistance(b, a.centre) - a.radius_m);
  if (b.kind == Solid::Kind::kCircle) return std::max(0.0, SolidDistance(a, b.centre) - b.radius_m);
  return OutlineDistance(a, b);
}

void SceneBuilder::AddShelf(const ShelfInstance& shelf) {
  world_.AddShelf(shelf);
  for (const LegFootprint& leg : ShelfLegFootprints(shelf)) {
    solids_.push_back(leg.shape == geometry::LegShape::kCircle
                          ? Solid::Circle(leg.T_world_leg.translation(), 0.5 * leg.length_m)
                          : Solid::Rectangle(leg.T_world_leg, leg.length_m, leg.width_m));
  }
}

void SceneBuilder::AddWall(const Wall& wall) {
  world_.AddWall(wall);
  std::vector<Eigen::Vector2d> points = wall.points;
  if (wall.closed && !points.empty()) points.push_back(points.front());
  solids_.push_back(Solid::Polyline(std::move(points)));
}

void SceneBuilder::AddBox(const Box& box) {
  world_.AddBox(box);
  solids_.push_back(Solid::Rectangle(box.T_world_box, box.length_m, box.width_m));
}

bool SceneBuilder::TryAddBox(const Box& box, double gap_m) {
  if (!Fits({Solid::Rectangle(box.T_world_box, box.length_m, box.width_m)}, gap_m)) return false;
  AddBox(box);
  return true;
}

bool SceneBuilder::TryAddRoundPost(const RoundPost& post, double gap_m) {
  const Solid solid = Solid::Circle(post.centre, post.radius_m);
  if (!Fits({solid}, gap_m)) return false;
  world_.AddRoundPost(post);
  solids_.push_back(solid);
  return true;
}

bool SceneBuilder::TryAddPerson(const Eigen::Vector2d& left, const Eigen::Vector2d& right,
                                double leg_radius_m, double gap_m) {
  const std::vector<Solid> legs = {Solid::Circle(left, leg_radius_m),
                                   Solid::Circle(right, leg_radius_m)};
  if (!Fits(legs, gap_m)) return false;
  // Person::LegCentresAt puts the legs across the walking direction, the first on its left:
  // a person standing still "walks" along `forward` at zero speed and zero stride.
  const Eigen::Vector2d across = (left - right).normalized();
  const Eigen::Vector2d forward(across.y(), -across.x());
  const Eigen::Vector2d mid = 0.5 * (left + right);
  Person person;
  person.path.waypoints = {mid, mid + 0.1 * forward};
  person.path.speed_mps = 0.0;
  person.stride_m = 0.0;
  person.leg_radius_m = leg_radius_m;
  person.leg_spacing_m = (left - right).norm();
  world_.AddPerson(person);
  solids_.insert(solids_.end(), legs.begin(), legs.end());
  return true;
}

void SceneBuilder::KeepFree(const Eigen::Vector2d& centre, double radius_m) {
  free_.push_back(Solid::Circle(centre, radius_m));
}

double SceneBuilder::Clearance(const Eigen::Vector2d& p) const {
  double best = kInf;
  for (const Solid& s : solids_) best = std::min(best, SolidDistance(s, p));
  return best;
}

void SceneBuilder::Bounds(Eigen::Vector2d* min, Eigen::Vector2d* max) const {
  *min = Eigen::Vector2d::Constant(kInf);
  *max = Eigen::Vector2d::Constant(-kInf);
  auto grow = [&](const Eigen::Vector2d& p, double r) {
    *min = min->cwiseMin(p - Eigen::Vector2d::Constant(r));
    *max = max->cwiseMax(p + Eigen::Vector2d::Constant(r));
  };
  for (const auto* list : {&solids_, &free_}) {
    for (const Solid& s : *list) {
      if (s.kind == Solid::Kind::kCircle) grow(s.centre, s.radius_m);
      for (const auto& p : s.points) grow(p, 0.0);
    }
  }
}

bool SceneBuilder::Fits(const std::vector<Solid>& added, double gap_m) const {
  for (const Solid& a : added) {
    for (const Solid& s : solids_) {
      if (SolidDistance(a, s) < gap_m) return false;
    }
    for (const Solid& f : free_) {
      if (SolidDistance(a, f) < gap_m) return false;
    }
  }
  return true;
}

}  // namespace shelfdock::sim::layout
