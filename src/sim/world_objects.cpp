#include "sim/world_objects.hpp"

#include <cmath>
#include <numbers>

namespace shelfdock::sim {

namespace {
std::array<Eigen::Vector2d, 4> BoxCorners(const geometry::Pose2& T_world_box, double length_m,
                                          double width_m) {
  const double hl = 0.5 * length_m;
  const double hw = 0.5 * width_m;
  return {T_world_box * Eigen::Vector2d(-hl, -hw), T_world_box * Eigen::Vector2d(hl, -hw),
          T_world_box * Eigen::Vector2d(hl, hw), T_world_box * Eigen::Vector2d(-hl, hw)};
}

void AppendClosed(const std::array<Eigen::Vector2d, 4>& corners, const Primitive& proto,
                  std::vector<Primitive>* out) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    Primitive p = proto;
    p.shape = Primitive::Shape::kSegment;
    p.a = corners[i];
    p.b = corners[(i + 1) % corners.size()];
    out->push_back(p);
  }
}
}  // namespace

std::array<Eigen::Vector2d, 4> LegFootprint::Corners() const {
  return BoxCorners(T_world_leg, length_m, width_m);
}

std::array<Eigen::Vector2d, 2> Person::LegCentresAt(double t_s) const {
  const geometry::Pose2 T_world_body = path.PoseAt(t_s);
  // One gait cycle (two steps) per 2 strides of travel; legs swing in anti-phase.
  const double cycle_m = std::max(2.0 * stride_m, 1e-3);
  const double phase =
      2.0 * std::numbers::pi * (path.start_offset_m + path.speed_mps * t_s) / cycle_m;
  const double swing = 0.5 * stride_m * std::sin(phase);
  const double hs = 0.5 * leg_spacing_m;
  return {T_world_body * Eigen::Vector2d(swing, hs), T_world_body * Eigen::Vector2d(-swing, -hs)};
}

Box MovingRobot::BoxAt(double t_s) const {
  Box box;
  box.T_world_box = path.PoseAt(t_s);
  box.length_m = length_m;
  box.width_m = width_m;
  box.height_m = height_m;
  box.material = material;
  return box;
}

std::vector<LegFootprint> ShelfLegFootprints(const ShelfInstance& shelf) {
  std::vector<LegFootprint> legs;
  const auto centres = shelf.model.LegCentres();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    LegFootprint leg;
    leg.shelf_id = shelf.id;
    leg.leg_index = static_cast<int>(i);
    leg.shape = shelf.model.leg.shape;
    geometry::Pose2 T_shelf_leg(centres[i].x(), centres[i].y(), 0.0);
    if (i < shelf.legs_as_built.size()) {
      const geometry::Pose2& built = shelf.legs_as_built[i];
      T_shelf_leg = geometry::Pose2(T_shelf_leg.x + built.x, T_shelf_leg.y + built.y, built.yaw);
    }
    leg.T_world_leg = shelf.T_world_shelf * T_shelf_leg;
    leg.length_m = shelf.model.leg.length_m;
    leg.width_m = shelf.model.leg.width_m;
    legs.push_back(leg);
  }
  return legs;
}

void AppendShelfLegs(const ShelfInstance& shelf, std::vector<Primitive>* out) {
  Primitive proto;
  proto.material = shelf.leg_material;
  proto.kind = ObjectKind::kShelfLeg;
  proto.object_id = shelf.id;
  for (const LegFootprint& leg : ShelfLegFootprints(shelf)) {
    proto.part = leg.leg_index;
    if (leg.shape == geometry::LegShape::kCircle) {
      Primitive p = proto;
      p.shape = Primitive::Shape::kCircle;
      p.a = leg.T_world_leg.translation();
      p.radius_m = 0.5 * leg.length_m;
      out->push_back(p);
    } else {
      AppendClosed(leg.Corners(), proto, out);
    }
  }
}

void AppendWall(const Wall& wall, int index, std::vector<Primitive>* out) {
  const std::size_t n = wall.points.size();
  const std::size_t edges = wall.closed && n > 2 ? n : n - 1;
  for (std::size_t i = 0; n >= 2 && i < edges; ++i) {
    Primitive p = Primitive::Segment(wall.points[i], wall.points[(i + 1) % n]);
    p.height_m = wall.height_m;
    p.material = wall.material;
    p.kind = ObjectKind::kWall;
    p.object_id = index;
    out->push_back(p);
  }
}

void AppendBox(const Box& box, ObjectKind kind, int index, std::vector<Primitive>* out) {
  Primitive proto;
  proto.height_m = box.height_m;
  proto.material = box.material;
  proto.kind = kind;
  proto.object_id = index;
  AppendClosed(BoxCorners(box.T_world_box, box.length_m, box.width_m), proto, out);
}

void AppendRoundPost(const RoundPost& post, int index, std::vector<Primitive>* out) {
  Primitive p = Primitive::Circle(post.centre, post.radius_m);
  p.material = post.material;
  p.kind = ObjectKind::kPost;
  p.object_id = index;
  out->push_back(p);
}

void AppendPerson(const Person& person, double t_s, int index, std::vector<Primitive>* out) {
  const auto legs = person.LegCentresAt(t_s);
  for (std::size_t k = 0; k < legs.size(); ++k) {
    Primitive p = Primitive::Circle(legs[k], person.leg_radius_m);
    p.part = static_cast<int>(k);
    p.height_m = person.height_m;
    p.material = person.material;
    p.kind = ObjectKind::kPerson;
    p.object_id = index;
    out->push_back(p);
  }
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const ShelfInstance& shelf) {
  geometry::ConfigChecker k;  // id and pose: any; the model: checked with the models file
  const double r = shelf.leg_material.reflectivity;  // the file's `leg_reflectivity`
  k.Check(r >= 0.0 && r <= 1.0, "leg_reflectivity", "in [0, 1]");
  // Off its drawing by a build tolerance, not standing somewhere else or turned into itself.
  k.Check(
      shelf.legs_as_built.empty() || shelf.legs_as_built.size() == shelf.model.LegCentres().size(),
      "legs_as_built", "none, or one {x, y, yaw} per leg (4)");
  for (const geometry::Pose2& leg : shelf.legs_as_built) {
    k.Check(std::abs(leg.x) <= kMaxLegBuildError_m && std::abs(leg.y) <= kMaxLegBuildError_m &&
                std::abs(leg.yaw) <= kMaxLegTwist_rad,
            "legs_as_built",
            "each leg within 0.05 m of its design place and 0.785 rad of the "
            "shelf's heading");
  }
  return k.Result();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const Wall& wall) {
  geometry::ConfigChecker k;  // points: the loader requires two or more; closed: either value
  k.Check(wall.height_m > 0.0, "height", "> 0 (metres)");
  k.Nested("", FindConfigViolation(wall.material));
  return k.Result();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const Box& box) {
  geometry::ConfigChecker k;
  k.Check(box.length_m > 0.0, "length", "> 0 (metres)");
  k.Check(box.width_m > 0.0, "width", "> 0 (metres)");
  k.Check(box.height_m > 0.0, "height", "> 0 (metres)");
  k.Nested("", FindConfigViolation(box.material));
  return k.Result();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const Person& person) {
  geometry::ConfigChecker k;
  k.Nested("", FindConfigViolation(person.path));
  k.Check(person.leg_radius_m > 0.0, "leg_radius", "> 0 (metres)");
  k.Check(person.leg_spacing_m >= 0.0, "leg_spacing", ">= 0 (metres)");
  k.Check(person.stride_m >= 0.0, "stride", ">= 0 (metres)");
  k.Check(person.height_m > 0.0, "height", "> 0 (metres)");
  k.Nested("", FindConfigViolation(person.material));
  return k.Result();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const MovingRobot& robot) {
  geometry::ConfigChecker k;
  k.Nested("", FindConfigViolation(robot.path));
  k.Check(robot.length_m > 0.0, "length", "> 0 (metres)");
  k.Check(robot.width_m > 0.0, "width", "> 0 (metres)");
  k.Check(robot.height_m > 0.0, "height", "> 0 (metres)");
  k.Nested("", FindConfigViolation(robot.material));
  return k.Result();
}

}  // namespace shelfdock::sim
