#include "geometry/shelf_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shelfdock::geometry {

double LegModel::Extent() const {
  return shape == LegShape::kCircle ? length_m : std::hypot(length_m, width_m);
}

double ShelfModel::Diagonal() const { return std::hypot(length_m, width_m); }

bool ShelfModel::IsSquare(double tolerance_m) const {
  return std::abs(length_m - width_m) <= tolerance_m;
}

double ShelfModel::HeadingPeriod() const {
  return IsSquare() ? 0.5 * std::numbers::pi : std::numbers::pi;
}

std::array<Eigen::Vector2d, 4> ShelfModel::LegCentres() const {
  const double hl = 0.5 * length_m;
  const double hw = 0.5 * width_m;
  return {Eigen::Vector2d(-hl, -hw), Eigen::Vector2d(hl, -hw), Eigen::Vector2d(hl, hw),
          Eigen::Vector2d(-hl, hw)};
}

std::optional<ConfigViolation> FindConfigViolation(const LegModel& leg) {
  ConfigChecker check;  // shape: either value
  check.Check(leg.length_m > 0.0, "length", "> 0 (metres)");
  check.Check(leg.width_m > 0.0, "width", "> 0 (metres)");
  return check.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const ShelfModel& m) {
  ConfigChecker check;
  check.Check(!m.name.empty(), "name", "a non-empty string");
  check.Check(m.length_m > 0.0, "length", "> 0 (leg centre to leg centre, metres)");
  check.Check(m.width_m > 0.0, "width", "> 0 (leg centre to leg centre, metres)");
  check.Check(m.length_m >= m.width_m, "length", ">= width (length is the long side)");
  check.Nested("leg", FindConfigViolation(m.leg));
  check.Check(m.leg.length_m < m.width_m, "leg.length", "smaller than the shelf's width");
  return check.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const std::vector<ShelfModel>& models) {
  ConfigChecker check;
  for (auto it = models.begin(); it != models.end(); ++it) {
    const std::string where = "models[" + std::to_string(it - models.begin()) + "]";
    const bool unique = std::none_of(
        models.begin(), it, [&](const ShelfModel& earlier) { return earlier.name == it->name; });
    check.Check(unique, where + ".name", "unique among the models");
    check.Nested(where, FindConfigViolation(*it));
  }
  return check.Result();
}

}  // namespace shelfdock::geometry
