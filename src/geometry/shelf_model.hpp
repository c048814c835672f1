#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geometry/config_violation.hpp"

namespace shelfdock::geometry {

/// Cross-section of a shelf leg (round legs: length = width = diameter).
enum class LegShape { kRectangle, kCircle };

/// A leg's cross-section. For round legs length == width == diameter.
struct LegModel {
  LegShape shape = LegShape::kRectangle;
  double length_m = 0.04;  ///< [m] along the shelf's long side (G_h in the paper)
  double width_m = 0.04;   ///< [m] along the shelf's short side (G_w in the paper)

  double Radius() const { return 0.5 * length_m; }  ///< round legs only
  /// Largest extent of the section: the diagonal of a rectangle, the diameter of a circle.
  double Extent() const;
};

/// A shelf type. length/width are leg-centre to leg-centre distances (length >= width); the
/// shelf frame has its origin at the centre, x along the long side.
struct ShelfModel {
  std::string name;
  double length_m = 0.0;  ///< [m] long side, L
  double width_m = 0.0;   ///< [m] short side, W
  LegModel leg;

  double Diagonal() const;
  bool IsSquare(double tolerance_m = 1e-3) const;
  /// [rad] The turn that maps the shelf's legs onto themselves: pi, or pi/2 for a square one.
  /// A detector cannot tell headings this far apart; compare headings modulo it.
  double HeadingPeriod() const;
  /// Leg centres in the shelf frame, counter-clockwise from (-L/2, -W/2).
  std::array<Eigen::Vector2d, 4> LegCentres() const;
};

/// The first impossible value of a leg section (keys `length`, `width`) or of a shelf model
/// (keys as in config/models.yaml: `name`, `length`, `width`, `leg.length`, ...): positive
/// sizes, the long side as length, legs narrower than the shelf.
std::optional<ConfigViolation> FindConfigViolation(const LegModel& leg);
std::optional<ConfigViolation> FindConfigViolation(const ShelfModel& model);
/// A set of models as config/models.yaml lists them: each model's rules under `models[i].`, and
/// names unique across the set.
std::optional<ConfigViolation> FindConfigViolation(const std::vector<ShelfModel>& models);

}  // namespace shelfdock::geometry
