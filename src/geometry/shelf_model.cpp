#include "geometry/shelf_model.hpp"

#include <cmath>

namespace shelfdock::geometry {

double LegModel::Extent() const {
  return shape == LegShape::kCircle ? length_m : std::hypot(length_m, width_m);
}

double ShelfModel::Diagonal() const { return std::hypot(length_m, width_m); }

bool ShelfModel::IsSquare(double tolerance_m) const {
  return std::abs(length_m - width_m) <= tolerance_m;
}

std::array<Eigen::Vector2d, 4> ShelfModel::LegCentres() const {
  const double hl = 0.5 * length_m;
  const double hw = 0.5 * width_m;
  return {Eigen::Vector2d(-hl, -hw), Eigen::Vector2d(hl, -hw), Eigen::Vector2d(hl, hw),
          Eigen::Vector2d(-hl, hw)};
}

}  // namespace shelfdock::geometry
