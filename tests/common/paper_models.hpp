#pragma once
// The paper's Table 1 shelf models (the values of config/models.yaml), for tests of every layer
// that need a shelf without reading the YAML.

#include <vector>

#include "geometry/shelf_model.hpp"

namespace shelfdock::testing {

inline geometry::ShelfModel MakeModel(const char* name, double length, double width,
                                      geometry::LegShape shape, double leg) {
  geometry::ShelfModel m;
  m.name = name;
  m.length_m = length;
  m.width_m = width;
  m.leg.shape = shape;
  m.leg.length_m = leg;
  m.leg.width_m = leg;
  return m;
}

inline std::vector<geometry::ShelfModel> PaperModels() {
  using geometry::LegShape;
  return {MakeModel("t1-round-900x810", 0.90, 0.81, LegShape::kCircle, 0.026),
          MakeModel("t1-rect-1075x883", 1.075, 0.883, LegShape::kRectangle, 0.04),
          MakeModel("t1-rect-1250x1250", 1.25, 1.25, LegShape::kRectangle, 0.04),
          MakeModel("t1-rect-1080x856", 1.08, 0.856, LegShape::kRectangle, 0.04)};
}

/// Shelf 2 of Table 1, the paper's docking experiment.
inline geometry::ShelfModel PaperShelf2() { return PaperModels()[1]; }

}  // namespace shelfdock::testing
