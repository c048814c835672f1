#include "sim/obstacle_grid.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::sim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxCellsPerAxis = 2048;
}  // namespace

bool CastAgainst(const CastQuery& query, const Primitive& primitive, RayHit* best) {
  const double t = IntersectRay(query.ray, primitive);
  if (!(t < best->t_m) || t > query.max_t_m) return false;
  const double z = query.z0_m + t * query.dz_dt;
  if (z > primitive.height_m || z < 0.0) return false;  // the beam passes over it
  best->t_m = t;
  best->primitive = &primitive;
  return true;
}

RayHit CastAll(const CastQuery& query, std::span<const Primitive> primitives) {
  RayHit best;
  for (const Primitive& p : primitives) CastAgainst(query, p, &best);
  return best;
}

ObstacleGrid::ObstacleGrid(std::vector<Primitive> primitives, double cell_size_m)
    : primitives_(std::move(primitives)), cell_(cell_size_m) {
  if (primitives_.empty()) return;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInf);
  Eigen::Vector2d hi = Eigen::Vector2d::Constant(-kInf);
  for (const Primitive& p : primitives_) {
    Eigen::Vector2d a, b;
    p.Bounds(&a, &b);
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  // Keep the grid bounded for huge sparse worlds by growing the cells instead.
  const Eigen::Vector2d extent = hi - lo;
  cell_ = std::max(cell_, extent.maxCoeff() / kMaxCellsPerAxis);
  min_ = lo.array() - 1e-6;
  nx_ = static_cast<int>(std::floor(extent.x() / cell_)) + 1;
  ny_ = static_cast<int>(std::floor(extent.y() / cell_)) + 1;

  // Two passes (count, fill) into a compressed layout: cache friendly and allocation free later.
  std::vector<std::vector<int>> cells(static_cast<std::size_t>(nx_) * ny_);
  for (int i = 0; i < static_cast<int>(primitives_.size()); ++i) {
    Eigen::Vector2d a, b;
    primitives_[i].Bounds(&a, &b);
    const int x0 = std::clamp(static_cast<int>((a.x() - min_.x()) / cell_), 0, nx_ - 1);
    const int x1 = std::clamp(static_cast<int>((b.x() - min_.x()) / cell_), 0, nx_ - 1);
    const int y0 = std::clamp(static_cast<int>((a.y() - min_.y()) / cell_), 0, ny_ - 1);
    const int y1 = std::clamp(static_cast<int>((b.y() - min_.y()) / cell_), 0, ny_ - 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) cells[static_cast<std::size_t>(y) * nx_ + x].push_back(i);
    }
  }
  cell_start_.assign(cells.size() + 1, 0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    cell_start_[k + 1] = cell_start_[k] + static_cast<int>(cells[k].size());
  }
  indices_.reserve(static_cast<std::size_t>(cell_start_.back()));
  for (const auto& c : cells) indices_.insert(indices_.end(), c.begin(), c.end());
}

RayHit ObstacleGrid::Cast(const CastQuery& query) const {
  RayHit best;
  if (primitives_.empty()) return best;
  const Eigen::Vector2d& o = query.ray.origin;
  const Eigen::Vector2d& d = query.ray.dir;
  const Eigen::Vector2d max = min_ + Eigen::Vector2d(nx_ * cell_, ny_ * cell_);

  // Clip the ray to the grid's box (slab test).
  double t_enter = 0.0;
  double t_leave = query.max_t_m;
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (o[k] < min_[k] || o[k] > max[k]) return best;
      continue;
    }
    double t0 = (min_[k] - o[k]) / d[k];
    double t1 = (max[k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_leave = std::min(t_leave, t1);
  }
  if (t_enter > t_leave) return best;

  const Eigen::Vector2d p = o + t_enter * d;
  int cx = std::clamp(static_cast<int>((p.x() - min_.x()) / cell_), 0, nx_ - 1);
  int cy = std::clamp(static_cast<int>((p.y() - min_.y()) / cell_), 0, ny_ - 1);
  const int step_x = d.x() >= 0.0 ? 1 : -1;
  const int step_y = d.y() >= 0.0 ? 1 : -1;
  const double dt_x = std::abs(d.x()) > 1e-15 ? cell_ / std::abs(d.x()) : kInf;
  const double dt_y = std::abs(d.y()) > 1e-15 ? cell_ / std::abs(d.y()) : kInf;
  const double next_x_edge = min_.x() + (cx + (step_x > 0 ? 1 : 0)) * cell_;
  const double next_y_edge = min_.y() + (cy + (step_y > 0 ? 1 : 0)) * cell_;
  double t_x = std::abs(d.x()) > 1e-15 ? (next_x_edge - o.x()) / d.x() : kInf;
  double t_y = std::abs(d.y()) > 1e-15 ? (next_y_edge - o.y()) / d.y() : kInf;

  while (true) {
    const std::size_t cell = static_cast<std::size_t>(cy) * nx_ + cx;
    for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
      CastAgainst(query, primitives_[static_cast<std::size_t>(indices_[k])], &best);
    }
    // Any hit inside this cell is final: primitives crossed later lie beyond the cell's exit.
    const double t_exit = std::min(t_x, t_y);
    if (best.t_m <= t_exit || t_exit > t_leave) break;
    if (t_x < t_y) {
      cx += step_x;
      t_x += dt_x;
    } else {
      cy += step_y;
      t_y += dt_y;
    }
    if (cx < 0 || cx >= nx_ || cy < 0 || cy >= ny_) break;
  }
  return best;
}

}  // namespace shelfdock::sim
