#include "eval/peers/exhaustive_leg_search.hpp"

#include <array>
#include <cmath>

namespace shelfdock::eval::peers {
namespace {

/// The corner v with legs a and b: two sides of one model at a right angle.
bool IsShelfCorner(const Eigen::Vector2d& v, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   const std::vector<geometry::ShelfModel>& models,
                   const perception::LegSearchConfig& config) {
  return perception::FitsSomeModel((a - v).norm(), (b - v).norm(), models,
                                   config.pair_tolerance_m) &&
         perception::IsRightCorner(v, a, b, config.pythagoras_tolerance_m);
}

}  // namespace

std::vector<perception::LegSet> ExhaustiveLegSets(const std::vector<Eigen::Vector2d>& c,
                                                  const std::vector<geometry::ShelfModel>& models,
                                                  const perception::LegSearchConfig& config,
                                                  perception::LegSearchCounts* counts) {
  std::vector<perception::LegSet> sets;
  const int n = static_cast<int>(c.size());
  long long checks = 0;
  // Every 4-subset, in its three cyclic orders: a rectangle when all four corners are right
  // and the sides fit a model.
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        for (int l = k + 1; l < n; ++l) {
          const std::array<std::array<int, 4>, 3> orders = {
              {{i, j, k, l}, {i, j, l, k}, {i, k, j, l}}};
          for (const auto& o : orders) {
            ++checks;
            bool ok = true;
            for (int q = 0; q < 4 && ok; ++q) {
              ok = IsShelfCorner(c[o[(q + 1) % 4]], c[o[q]], c[o[(q + 2) % 4]], models, config);
            }
            if (ok) sets.push_back({{o[0], o[1], o[2], o[3]}, 4});
          }
        }
      }
    }
  }
  // Every 3-subset with each point as the right-angle corner (one leg hidden).
  if (config.allow_three_legs) {
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        for (int k = j + 1; k < n; ++k) {
          const std::array<std::array<int, 3>, 3> corners = {{{j, i, k}, {i, j, k}, {i, k, j}}};
          for (const auto& t : corners) {
            ++checks;
            if (IsShelfCorner(c[t[1]], c[t[0]], c[t[2]], models, config)) {
              sets.push_back({{t[0], t[1], t[2], -1}, 3});
            }
          }
        }
      }
    }
  }
  if (counts != nullptr) counts->checks += checks;
  return sets;
}

}  // namespace shelfdock::eval::peers
