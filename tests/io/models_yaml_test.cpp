// The shelf models file and the choice of models a map names (io::SelectModels, behind
// `detect --model` and the Python module's `only`).
#include "io/models_yaml.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

const std::string kModels = std::string(SHELFDOCK_SOURCE_DIR) + "/config/models.yaml";

std::vector<std::string> Names(const std::vector<geometry::ShelfModel>& models) {
  std::vector<std::string> names;
  for (const auto& m : models) names.push_back(m.name);
  return names;
}

TEST(SelectModelsTest, NoNameKeepsEveryModel) {
  const auto models = ReadShelfModels(kModels);
  EXPECT_EQ(Names(SelectModels(models, {}, kModels, "--model")), Names(models));
}

TEST(SelectModelsTest, KeepsTheNamedModelsInTheOrderNamedEachOnce) {
  const auto models = ReadShelfModels(kModels);
  const auto kept = SelectModels(
      models, {"t1-rect-1080x856", "t1-round-900x810", "t1-rect-1080x856"}, kModels, "--model");
  EXPECT_EQ(Names(kept), (std::vector<std::string>{"t1-rect-1080x856", "t1-round-900x810"}));
  EXPECT_DOUBLE_EQ(kept[0].width_m, 0.856);  // the model itself, not a copy of another
}

TEST(SelectModelsTest, AnUnknownNameNamesTheFileTheOptionAndTheNamesItHolds) {
  const auto models = ReadShelfModels(kModels);
  try {
    SelectModels(models, {"t1-rect-1075x883", "t1-rect-1000x800"}, kModels, "--model");
    FAIL() << "no error for an unknown model";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("models.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("--model"), std::string::npos) << what;
    EXPECT_NE(what.find("'t1-rect-1000x800'"), std::string::npos) << what;
    EXPECT_NE(what.find("t1-rect-1250x1250"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace shelfdock::io
