// Every fixture in tests/data/scenes/bad/ fails with one expected diagnostic, located
// by code, JSON Pointer and line.
#include <gtest/gtest.h>

#include <filesystem>

#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

const std::string kBadDir = std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/bad/";

struct BadScene {
  const char* file;
  const char* code;
  const char* pointer;
  int line;
  const char* message_contains = "";
};

// GoogleTest looks the printer up by this name.
void PrintTo(const BadScene& s, std::ostream* os) {  // NOLINT(readability-identifier-naming)
  *os << s.file;
}

class BadScenes : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadScenes, ReportsTheExpectedLocatedDiagnostic) {
  const BadScene& expected = GetParam();
  const std::string path = kBadDir + expected.file;
  const auto result = load_scene_file(path);
  ASSERT_FALSE(result.ok());
  const base::Diagnostics& diagnostics = result.diagnostics();
  const base::Diagnostic* d = diagnostics.find(expected.code);
  ASSERT_NE(d, nullptr) << "got:\n" << diagnostics.to_text();
  EXPECT_EQ(d->severity, base::Severity::error);
  EXPECT_EQ(d->file, path);
  EXPECT_EQ(d->pointer, expected.pointer) << diagnostics.to_text();
  EXPECT_EQ(d->line, expected.line) << diagnostics.to_text();
  EXPECT_GT(d->column, 0);
  EXPECT_NE(d->message.find(expected.message_contains), std::string::npos) << d->message;
  const std::string text = base::format_text(*d);
  EXPECT_EQ(text.rfind(path + ":" + std::to_string(expected.line) + ":", 0), 0u) << text;
  EXPECT_NE(text.find(std::string("error[") + expected.code + "]"), std::string::npos) << text;
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BadScenes,
    ::testing::Values(
        BadScene{"syntax_error.json", "FG001", "/objects/0", 5},
        BadScene{"unknown_key.json", "SC004", "/lights/0/rnage", 5, "did you mean 'range'?"},
        BadScene{"wrong_type.json", "SC003", "/camera/fovY", 4, "expected a number"},
        BadScene{"negative_range.json", "SC006", "/lights/1/range", 7, "> 0"},
        BadScene{"negative_intensity.json", "SC006", "/lights/0/intensity", 5, ">= 0"},
        BadScene{"negative_size.json", "SC006", "/lights/0/size", 5},
        BadScene{"bad_roughness.json", "SC006", "/materials/shiny/roughness", 5, "in [0, 1]"},
        BadScene{"unknown_material.json", "SC010", "/objects/0/material", 6,
                 "did you mean 'stone'?"},
        BadScene{"unknown_primitive.json", "SC012", "/objects/1/primitive", 6, "'cube'"},
        BadScene{"bad_vec3.json", "SC007", "/lights/0/position", 6, "3 numbers"},
        BadScene{"missing_version.json", "SC001", "", 1},
        BadScene{"newer_version.json", "SC002", "/version", 2, "newer"},
        BadScene{"duplicate_light_name.json", "SC021", "/lights/2/name", 7, "/lights/0"},
        BadScene{"empty_light_name.json", "SC020", "/lights/0/name", 5},
        BadScene{"missing_light_position.json", "SC005", "/lights/0", 5, "'position'"},
        BadScene{"unknown_light_type.json", "SC022", "/lights/0/type", 5, "'area'"},
        BadScene{"second_directional.json", "SC024", "/lights/1/type", 6, "/lights/0"},
        BadScene{"zero_light_direction.json", "SC025", "/lights/0/direction", 5},
        BadScene{"spot_inner_angle.json", "SC026", "/lights/0/innerAngle", 6},
        BadScene{"camera_degenerate.json", "SC023", "/camera/target", 4},
        BadScene{"far_before_near.json", "SC006", "/camera/far", 4},
        BadScene{"arch_too_wide.json", "SC014", "/objects/0", 5},
        BadScene{"primitive_and_gltf.json", "SC013", "/objects/0", 5},
        BadScene{"too_many_copies.json", "SC015", "/objects/0/repeat", 6},
        BadScene{"missing_gltf.json", "SC030", "/objects/0/gltf", 5},
        BadScene{"malformed_gltf.json", "SC035", "/objects/1/gltf", 6, "bad_index.gltf"},
        BadScene{"gltf_cycle.json", "SC036", "/objects/0/gltf", 5, "cycle"}));

TEST(BadScenesDirectory, EveryFixtureIsInTheTable) {
  // Adding a fixture without an expectation would leave it untested.
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
    count += entry.path().extension() == ".json" ? 1 : 0;
  }
  EXPECT_EQ(count, 27u);
}

TEST(BadScenesDirectory, MissingSceneFileIsReported) {
  const auto result = load_scene_file(kBadDir + "no_such_scene.json");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.diagnostics().find("FG000"), nullptr);
}

}  // namespace
}  // namespace antumbra::scene
