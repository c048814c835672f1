#include "io/scenario_yaml.hpp"

#include <cmath>
#include <limits>
#include <set>

#include "io/input_limits.hpp"
#include "io/yaml_fields.hpp"

namespace shelfdock::io {

namespace {
constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

/// `{x, y, yaw}` under `key`: x and y required, yaw defaults to 0.
geometry::Pose2 ReadPose(YamlFields& parent, const std::string& key) {
  const YAML::Node node = parent.Child(key);
  if (!node.IsDefined() || node.IsNull()) {
    throw InputError(parent.file(), parent.KeyPath(key), "required: a pose {x, y, yaw}");
  }
  YamlFields f(node, parent.file(), parent.KeyPath(key));
  double x = kUnset, y = kUnset, yaw = 0.0;
  f.Read("x", x);
  f.Read("y", y);
  f.Read("yaw", yaw);
  f.RejectUnknown();
  f.Require(std::isfinite(x), "x", "given (metres)");
  f.Require(std::isfinite(y), "y", "given (metres)");
  return {x, y, yaw};
}

/// `[[x, y], [x, y], ...]` under `key`, at least `min_points` of them.
std::vector<Eigen::Vector2d> ReadPoints(YamlFields& parent, const std::string& key,
                                        std::size_t min_points) {
  const YAML::Node node = parent.Child(key);
  const std::string where = parent.KeyPath(key);
  if (!node.IsDefined() || !node.IsSequence() || node.size() < min_points) {
    throw InputError(
        parent.file(), where,
        "required: a list of at least " + std::to_string(min_points) + " points [x, y] (metres)");
  }
  if (node.size() > kMaxSceneObjects) {
    throw InputError(parent.file(), where,
                     std::to_string(node.size()) + " points exceed the limit of " +
                         std::to_string(kMaxSceneObjects));
  }
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (!node[i].IsSequence() || node[i].size() != 2) {
      throw InputError(parent.file(), at, "expected a point [x, y]");
    }
    try {
      const Eigen::Vector2d p(node[i][0].as<double>(), node[i][1].as<double>());
      if (!p.allFinite()) throw InputError(parent.file(), at, "expected finite numbers");
      points.push_back(p);
    } catch (const YAML::Exception&) {
      throw InputError(parent.file(), at, "expected a point [x, y] of numbers");
    }
  }
  return points;
}

void ReadMaterial(YamlFields& f, sim::Material* m) {
  f.Read("reflectivity", m->reflectivity);
  f.Read("shiny", m->shiny);
  f.Require(m->reflectivity >= 0.0 && m->reflectivity <= 1.0, "reflectivity", "in [0, 1]");
}

double ReadHeight(YamlFields& f, double height_m) {
  f.Read("height", height_m);
  f.Require(height_m > 0.0, "height", "> 0 (metres)");
  return height_m;
}

sim::PathMotion ReadPath(YamlFields& f) {
  sim::PathMotion m;
  m.waypoints = ReadPoints(f, "path", 1);
  f.Read("speed", m.speed_mps);
  f.Read("closed", m.closed);
  f.Read("start_offset", m.start_offset_m);
  f.Require(m.speed_mps >= 0.0 && m.speed_mps < 10.0, "speed", "in [0, 10) m/s");
  return m;
}

/// Runs `read` on each map of the optional list under `key`, with its `key[i]` path.
template <typename Fn>
void ForEach(YamlFields& top, const std::string& key, Fn read) {
  const YAML::Node list = top.Child(key);
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) throw InputError(top.file(), key, "expected a list");
  if (list.size() > kMaxSceneObjects) {
    throw InputError(top.file(), key,
                     std::to_string(list.size()) + " entries exceed the limit of " +
                         std::to_string(kMaxSceneObjects));
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    YamlFields f(list[i], top.file(), key + "[" + std::to_string(i) + "]");
    read(f);
    f.RejectUnknown();
  }
}

const geometry::ShelfModel* FindModel(const std::vector<geometry::ShelfModel>& models,
                                      const std::string& name) {
  for (const auto& m : models) {
    if (m.name == name) return &m;
  }
  return nullptr;
}
}  // namespace

sim::Scenario ReadScenario(const std::string& path,
                           const std::vector<geometry::ShelfModel>& models) {
  const YAML::Node root = LoadYamlFile(path);
  YamlFields top(root, path, "");
  sim::Scenario s;
  top.Read("name", s.name);
  top.Read("target_shelf", s.target_shelf_id);
  s.T_map_robot_start = ReadPose(top, "robot_start");

  std::set<int> ids;
  ForEach(top, "shelves", [&](YamlFields& f) {
    sim::ScenarioShelf shelf;
    shelf.id = -1;
    f.Read("id", shelf.id);
    f.Require(shelf.id >= 0, "id", "given, an integer >= 0 (the code under the shelf)");
    f.Require(ids.insert(shelf.id).second, "id", "unique among the shelves");
    f.Read("model", shelf.model_name);
    const geometry::ShelfModel* model = FindModel(models, shelf.model_name);
    f.Require(model != nullptr, "model", "a model name from the models file");
    shelf.T_map_shelf = ReadPose(f, "pose");
    if (f.Child("preset").IsDefined()) shelf.T_map_shelf_preset = ReadPose(f, "preset");
    const YAML::Node offset = f.Child("preset_offset");
    if (offset.IsDefined()) {
      f.Require(!shelf.T_map_shelf_preset, "preset_offset", "absent when preset is given");
      YamlFields o(offset, path, f.KeyPath("preset_offset"));
      o.Read("xy_m", shelf.preset_offset_xy_m);
      o.Read("yaw_rad", shelf.preset_offset_yaw_rad);
      o.RejectUnknown();
      o.Require(shelf.preset_offset_xy_m >= 0.0, "xy_m", ">= 0 (metres)");
      o.Require(shelf.preset_offset_yaw_rad >= 0.0, "yaw_rad", ">= 0 (radians)");
    }
    sim::ShelfInstance instance;
    instance.id = shelf.id;
    instance.model = *model;
    instance.T_world_shelf = shelf.T_map_shelf;
    f.Read("leg_reflectivity", instance.leg_material.reflectivity);
    f.Read("leg_shiny", instance.leg_material.shiny);
    f.Require(
        instance.leg_material.reflectivity >= 0.0 && instance.leg_material.reflectivity <= 1.0,
        "leg_reflectivity", "in [0, 1]");
    s.world.AddShelf(instance);
    s.shelves.push_back(shelf);
  });
  ForEach(top, "walls", [&](YamlFields& f) {
    sim::Wall wall;
    wall.points = ReadPoints(f, "points", 2);
    f.Read("closed", wall.closed);
    wall.height_m = ReadHeight(f, wall.height_m);
    ReadMaterial(f, &wall.material);
    s.world.AddWall(wall);
  });
  ForEach(top, "boxes", [&](YamlFields& f) {
    sim::Box box;
    box.T_world_box = ReadPose(f, "pose");
    f.Read("length", box.length_m);
    f.Read("width", box.width_m);
    f.Require(box.length_m > 0.0, "length", "> 0 (metres)");
    f.Require(box.width_m > 0.0, "width", "> 0 (metres)");
    box.height_m = ReadHeight(f, box.height_m);
    ReadMaterial(f, &box.material);
    s.world.AddBox(box);
  });
  ForEach(top, "posts", [&](YamlFields& f) {
    std::string shape = "round";
    double size_m = kUnset;
    f.Read("shape", shape);
    f.Read("size", size_m);
    f.Require(std::isfinite(size_m) && size_m > 0.0, "size",
              "given, > 0 (diameter or side, metres)");
    const geometry::Pose2 pose = ReadPose(f, "pose");
    if (shape == "round") {
      sim::RoundPost post;
      post.centre = pose.translation();
      post.radius_m = 0.5 * size_m;
      ReadMaterial(f, &post.material);
      s.world.AddRoundPost(post);
    } else if (shape == "square") {
      sim::Box box;
      box.T_world_box = pose;
      box.length_m = size_m;
      box.width_m = size_m;
      ReadMaterial(f, &box.material);
      s.world.AddBox(box);
    } else {
      f.Require(false, "shape", "round or square");
    }
  });
  ForEach(top, "people", [&](YamlFields& f) {
    sim::Person person;
    person.path = ReadPath(f);
    f.Read("leg_radius", person.leg_radius_m);
    f.Read("leg_spacing", person.leg_spacing_m);
    f.Read("stride", person.stride_m);
    f.Require(person.leg_radius_m > 0.0, "leg_radius", "> 0 (metres)");
    f.Require(person.leg_spacing_m >= 0.0, "leg_spacing", ">= 0 (metres)");
    f.Require(person.stride_m >= 0.0, "stride", ">= 0 (metres)");
    person.height_m = ReadHeight(f, person.height_m);
    ReadMaterial(f, &person.material);
    s.world.AddPerson(person);
  });
  ForEach(top, "robots", [&](YamlFields& f) {
    sim::MovingRobot robot;
    robot.path = ReadPath(f);
    f.Read("length", robot.length_m);
    f.Read("width", robot.width_m);
    f.Require(robot.length_m > 0.0, "length", "> 0 (metres)");
    f.Require(robot.width_m > 0.0, "width", "> 0 (metres)");
    robot.height_m = ReadHeight(f, robot.height_m);
    ReadMaterial(f, &robot.material);
    s.world.AddRobot(robot);
  });
  top.RejectUnknown();
  if (s.target_shelf_id != -1) {
    top.Require(s.FindShelf(s.target_shelf_id) != nullptr, "target_shelf",
                "the id of a shelf in this scenario");
  }
  return s;
}

}  // namespace shelfdock::io
