#include "perception/leg_search.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace shelfdock::perception {
namespace {

struct Neighbour {
  int index;
  double dist;
};

bool FitsSomeSide(double d, const std::vector<geometry::ShelfModel>& models, double tolerance_m) {
  for (const auto& m : models) {
    if (std::abs(d - m.length_m) < tolerance_m || std::abs(d - m.width_m) < tolerance_m) {
      return true;
    }
  }
  return false;
}

}  // namespace

// True when the corner `v` with legs `a` and `b` is a right angle: |ab| ~ sqrt(|va|^2 + |vb|^2).
bool IsRightCorner(const Eigen::Vector2d& v, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   double tolerance_m) {
  const double legs = std::sqrt((a - v).squaredNorm() + (b - v).squaredNorm());
  return std::abs((a - b).norm() - legs) < tolerance_m;
}

// True when the sides (s1, s2) are (L, W) or (W, L) of some model.
bool FitsSomeModel(double s1, double s2, const std::vector<geometry::ShelfModel>& models,
                   double tolerance_m) {
  for (const auto& m : models) {
    const bool lw =
        std::abs(s1 - m.length_m) < tolerance_m && std::abs(s2 - m.width_m) < tolerance_m;
    const bool wl =
        std::abs(s1 - m.width_m) < tolerance_m && std::abs(s2 - m.length_m) < tolerance_m;
    if (lw || wl) return true;
  }
  return false;
}

std::vector<LegSet> SearchLegSets(const std::vector<Eigen::Vector2d>& centres,
                                  const std::vector<geometry::ShelfModel>& models,
                                  const LegSearchConfig& config, LegSearchCounts* counts) {
  std::vector<LegSet> sets;
  const int n = static_cast<int>(centres.size());
  if (n < 3 || models.empty()) return sets;
  const double tol = config.pair_tolerance_m;
  double longest_side = 0.0;
  for (const auto& m : models) longest_side = std::max(longest_side, m.length_m);

  // Criterion 1: pairs whose length fits a model side, found by a sweep in x.
  std::vector<int> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(),
            [&](int a, int b) { return centres[a].x() < centres[b].x(); });
  long long checks = 0;
  std::vector<std::vector<Neighbour>> neighbours(n);
  for (int s = 0; s < n; ++s) {
    const int i = by_x[s];
    for (int t = s + 1; t < n; ++t) {
      const int j = by_x[t];
      if (centres[j].x() - centres[i].x() > longest_side + tol) break;
      const double d = (centres[j] - centres[i]).norm();
      ++checks;
      if (!FitsSomeSide(d, models, tol)) continue;
      neighbours[i].push_back({j, d});
      neighbours[j].push_back({i, d});
    }
  }

  std::set<std::array<int, 4>> seen;
  auto add = [&](const LegSet& set) {
    std::array<int, 4> key = set.legs;
    std::sort(key.begin(), key.end());
    if (seen.insert(key).second) sets.push_back(set);
  };

  const double r4 = config.fourth_leg_radius_m;
  const double ptol = config.pythagoras_tolerance_m;
  for (int v = 0; v < n && static_cast<int>(sets.size()) < config.max_leg_sets; ++v) {
    const auto& nb = neighbours[v];
    for (std::size_t p = 0; p < nb.size(); ++p) {
      for (std::size_t q = p + 1; q < nb.size(); ++q) {
        const int a = nb[p].index;
        const int b = nb[q].index;
        // Criterion 2: two sides of one model meeting at a right angle.
        ++checks;
        if (!FitsSomeModel(nb[p].dist, nb[q].dist, models, tol)) continue;
        if (!IsRightCorner(centres[v], centres[a], centres[b], ptol)) continue;

        const Eigen::Vector2d predicted = centres[a] + centres[b] - centres[v];
        int fourth = -1;
        double best = r4;
        for (int k = 0; k < n; ++k) {
          if (k == v || k == a || k == b) continue;
          ++checks;
          const double d = (centres[k] - predicted).norm();
          if (d < best) {
            best = d;
            fourth = k;
          }
        }
        // Criterion 3: any three of the four legs form a right triangle.
        if (fourth >= 0 && IsRightCorner(centres[a], centres[v], centres[fourth], ptol) &&
            IsRightCorner(centres[b], centres[v], centres[fourth], ptol) &&
            IsRightCorner(centres[fourth], centres[a], centres[b], ptol)) {
          add({{a, v, b, fourth}, 4});
        } else if (config.allow_three_legs) {
          add({{a, v, b, -1}, 3});
        }
      }
    }
  }
  if (counts != nullptr) counts->checks += checks;
  return sets;
}

}  // namespace shelfdock::perception
