#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::perception {

/// Indices of 3 or 4 cluster centres that form a rectangle or a right triangle, in cyclic
/// order around the shape. With 3 legs, legs[1] is the right-angle corner and legs[3] == -1
/// (the hidden leg would sit at legs[0] + legs[2] - legs[1]).
struct LegSet {
  std::array<int, 4> legs{-1, -1, -1, -1};
  int count = 0;  ///< 3 or 4
};

/// Work done by a search, for comparing it with an exhaustive one.
struct LegSearchCounts {
  long long checks = 0;  ///< candidate checks: pair lengths, corners and fourth-leg tests
};

/// True when the corner `v` with legs `a` and `b` is a right angle: |ab| ~ sqrt(|va|^2 + |vb|^2).
bool IsRightCorner(const Eigen::Vector2d& v, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   double tolerance_m);

/// True when the sides (s1, s2) meeting at a corner are (L, W) or (W, L) of some model.
bool FitsSomeModel(double s1, double s2, const std::vector<geometry::ShelfModel>& models,
                   double tolerance_m);

/// Paper 3.2, pruned search: (1) a pair's length must fit a side of some model, (2) a triangle
/// with two such sides must nearly satisfy Pythagoras and match one model's (L, W), (3) a
/// fourth leg near the predicted corner is accepted only if every three of the four legs form
/// a right triangle. Pairs come from a sweep over centres sorted by x, so the work grows with
/// the number of near neighbours, not with n^3. Sets are unique.
std::vector<LegSet> SearchLegSets(const std::vector<Eigen::Vector2d>& centres,
                                  const std::vector<geometry::ShelfModel>& models,
                                  const LegSearchConfig& config, LegSearchCounts* counts = nullptr);

}  // namespace shelfdock::perception
