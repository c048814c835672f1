#include "io/scenario_yaml.hpp"

#include <cmath>
#include <limits>

#include "io/input_limits.hpp"
#include "io/yaml_fields.hpp"

namespace shelfdock::io {

namespace {
constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

/// The pose `{x, y, yaw}` of `node` at `where` in `file`: x and y required, yaw defaults to 0.
geometry::Pose2 PoseAt(const YAML::Node& node, const std::string& file, const std::string& where) {
  if (!node.IsDefined() || node.IsNull()) {
    throw InputError(file, where, "required: a pose {x, y, yaw}");
  }
  YamlFields f(node, file, where);
  double x = kUnset, y = kUnset, yaw = 0.0;
  f.Read("x", x);
  f.Read("y", y);
  f.Read("yaw", yaw);
  f.RejectUnknown();
  f.Require(std::isfinite(x), "x", "given (metres)");
  f.Require(std::isfinite(y), "y", "given (metres)");
  return {x, y, yaw};
}

/// `{x, y, yaw}` under `key` (PoseAt).
geometry::Pose2 ReadPose(YamlFields& parent, const std::string& key) {
  return PoseAt(parent.Child(key), parent.file(), parent.KeyPath(key));
}

/// `[{x, y, yaw}, ...]` under `key` (absent: empty), each as ReadPose.
std::vector<geometry::Pose2> ReadPoses(YamlFields& parent, const std::string& key) {
  const YAML::Node node = parent.Child(key);
  if (!node.IsDefined() || node.IsNull()) return {};
  const std::string where = parent.KeyPath(key);
  if (!node.IsSequence() || node.size() > kMaxSceneObjects) {
    throw InputError(parent.file(), where, "expected a list of poses {x, y, yaw}");
  }
  std::vector<geometry::Pose2> poses;
  for (std::size_t i = 0; i < node.size(); ++i) {
    poses.push_back(PoseAt(node[i], parent.file(), where + "[" + std::to_string(i) + "]"));
  }
  return poses;
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
}

sim::PathMotion ReadPath(YamlFields& f) {
  sim::PathMotion m;
  m.waypoints = ReadPoints(f, "path", 1);
  f.Read("speed", m.speed_mps);
  f.Read("closed", m.closed);
  f.Read("start_offset", m.start_offset_m);
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

  ForEach(top, "shelves", [&](YamlFields& f) {
    sim::ScenarioShelf shelf;
    shelf.id = -1;  // required: an absent id breaks the struct's ">= 0" rule
    f.Read("id", shelf.id);
    f.Read("model", shelf.model_name);
    const geometry::ShelfModel* model = FindModel(models, shelf.model_name);
    f.Require(model != nullptr, "model", "a model name from the models file");
    shelf.T_map_shelf = ReadPose(f, "pose");
    if (f.Child("preset").IsDefined()) shelf.T_map_shelf_preset = ReadPose(f, "preset");
    const YAML::Node offset = f.Child("preset_offset");
    if (offset.IsDefined()) {
      YamlFields o(offset, path, f.KeyPath("preset_offset"));
      o.Read("xy_m", shelf.preset_offset_xy_m);
      o.Read("yaw_rad", shelf.preset_offset_yaw_rad);
      o.RejectUnknown();
    }
    sim::ShelfInstance instance;
    instance.id = shelf.id;
    instance.model = *model;
    instance.T_world_shelf = shelf.T_map_shelf;
    f.Read("leg_reflectivity", instance.leg_material.reflectivity);
    f.Read("leg_shiny", instance.leg_material.shiny);
    instance.legs_as_built = ReadPoses(f, "legs_as_built");
    f.Reject(sim::FindConfigViolation(instance));
    s.world.AddShelf(instance);
    s.shelves.push_back(shelf);
  });
  ForEach(top, "walls", [&](YamlFields& f) {
    sim::Wall wall;
    wall.points = ReadPoints(f, "points", 2);
    f.Read("closed", wall.closed);
    f.Read("height", wall.height_m);
    ReadMaterial(f, &wall.material);
    f.Reject(sim::FindConfigViolation(wall));
    s.world.AddWall(wall);
  });
  ForEach(top, "boxes", [&](YamlFields& f) {
    sim::Box box;
    box.T_world_box = ReadPose(f, "pose");
    f.Read("length", box.length_m);
    f.Read("width", box.width_m);
    f.Read("height", box.height_m);
    ReadMaterial(f, &box.material);
    f.Reject(sim::FindConfigViolation(box));
    s.world.AddBox(box);
  });
  ForEach(top, "posts", [&](YamlFields& f) {
    std::string shape = "round";
    double size_m = kUnset;
    f.Read("shape", shape);
    f.Read("size", size_m);
    // `size` is no struct's field: it becomes a round post's diameter or a square post's
    // sides, so it is checked here, before it is turned into either.
    f.Require(std::isfinite(size_m) && size_m > 0.0, "size",
              "given, > 0 (diameter or side, metres)");
    const geometry::Pose2 pose = ReadPose(f, "pose");
    if (shape == "round") {
      sim::RoundPost post;
      post.centre = pose.translation();
      post.radius_m = 0.5 * size_m;
      ReadMaterial(f, &post.material);
      f.Reject(sim::FindConfigViolation(post.material));
      s.world.AddRoundPost(post);
    } else if (shape == "square") {
      sim::Box box;
      box.T_world_box = pose;
      box.length_m = size_m;
      box.width_m = size_m;
      ReadMaterial(f, &box.material);
      f.Reject(sim::FindConfigViolation(box));
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
    f.Read("height", person.height_m);
    ReadMaterial(f, &person.material);
    f.Reject(sim::FindConfigViolation(person));
    s.world.AddPerson(person);
  });
  ForEach(top, "robots", [&](YamlFields& f) {
    sim::MovingRobot robot;
    robot.path = ReadPath(f);
    f.Read("length", robot.length_m);
    f.Read("width", robot.width_m);
    f.Read("height", robot.height_m);
    ReadMaterial(f, &robot.material);
    f.Reject(sim::FindConfigViolation(robot));
    s.world.AddRobot(robot);
  });
  top.RejectUnknown();
  // The shelves' rules, their ids' uniqueness and the target live with sim::Scenario.
  top.Reject(sim::FindConfigViolation(s));
  return s;
}

}  // namespace shelfdock::io
