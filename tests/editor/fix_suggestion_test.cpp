// Suggested fixes: computed by search, verified by re-colouring, applied as one undoable
// command, and really bringing the layout under the layer_cap (also on random layouts).
#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "antumbra/editor/fix_suggestion.hpp"
#include "antumbra/editor/layer_status.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::fixture;

layering::LayeringOptions layer_cap(int k) {
  layering::LayeringOptions options;
  options.max_layers = k;
  return options;
}

struct Lamp {
  float x = 0.0f;
  float z = 0.0f;
  float range = 1.0f;
  int spot_angle = 0;  // > 0: a spot light pointing down with this outer half-angle
};

// A scene whose lights are point lights at height 2, and optionally the sun (first, so
// that sphere and scene indices differ).
SceneDocument scene_of(const std::vector<Lamp>& lamps, bool sun = false) {
  std::ostringstream text;
  text << R"({"version": 1, "camera": {"position": [0, 10, 10], "target": [0, 0, 0]}, "lights": [)";
  if (sun) text << R"({"name": "sun", "type": "directional", "direction": [0, -1, 0]}, )";
  for (std::size_t i = 0; i < lamps.size(); ++i) {
    text << (i ? ", " : "") << R"({"name": "lamp )" << i << R"(", "position": [)" << lamps[i].x
         << ", 2, " << lamps[i].z << R"(], "range": )" << lamps[i].range;
    if (lamps[i].spot_angle > 0) {
      text << R"(, "type": "spot", "direction": [0, -1, 0], "angle": )" << lamps[i].spot_angle;
    }
    text << "}";
  }
  text << "]}";
  return testing::take(SceneDocument::parse(text.str(), "generated.json"));
}

// The fix, applied to a copy of the lights, really fits the layer_cap.
void expect_fix_fits(const std::vector<scene::PointLight>& lights, const LayerFix& fix, int k) {
  std::vector<scene::PointLight> fixed = lights;
  ASSERT_LT(fix.light, fixed.size());
  EXPECT_EQ(fixed[fix.light].name, fix.name);
  if (fix.kind == FixKind::reduce_range) {
    EXPECT_LT(fix.new_range, fix.old_range);
    EXPECT_GT(fix.new_range, 0.0f);
    fixed[fix.light].range = fix.new_range;
  } else {
    EXPECT_EQ(fix.new_position.y, fix.old_position.y);  // moves stay on the ground plane
    fixed[fix.light].position = fix.new_position;
  }
  const LayerReport report = analyse_layers(fixed, layer_cap(k));
  EXPECT_FALSE(report.over_cap()) << fix.description;
  EXPECT_LE(report.layers_needed, k);
  EXPECT_EQ(report.layers_needed, fix.layers_needed);
}

// The lights with every change of a several-light fix made.
std::vector<scene::PointLight> lights_with(std::vector<scene::PointLight> lights,
                                           const MultiLightFix& fix) {
  for (const LayerFix& c : fix.changes) {
    lights[c.light].range = c.new_range;
    lights[c.light].position = c.new_position;
  }
  return lights;
}

TEST(SuggestFix, NothingToFixWhenTheLayoutFits) {
  const auto doc = SceneDocument::load(fixture("lamps.json"));
  const FixSuggestion s = suggest_fix(doc->lights(), layer_cap(3));
  EXPECT_FALSE(s.needed);
  EXPECT_EQ(s.best(), nullptr);
  EXPECT_NE(s.message.find("fits"), std::string::npos) << s.message;
}

TEST(SuggestFix, ShrinksOneRangeOfATriangleAsOneUndoableStep) {
  auto doc = testing::take(SceneDocument::load(fixture("lamps.json")));
  doc.set_position(2, {1.5f, 2.0f, 1.0f});  // lamp c between a and b: 4 layers needed
  LayerStatus status(layer_cap(3));
  ASSERT_TRUE(status.update(doc).over_cap());
  const FixSuggestion s = status.suggestion(doc);  // a copy: the cache changes with the edit
  ASSERT_TRUE(s.needed);
  ASSERT_TRUE(s.range_fix.has_value()) << s.message;
  ASSERT_TRUE(s.move_fix.has_value()) << s.message;
  EXPECT_EQ(s.best(), &*s.range_fix);
  EXPECT_FALSE(s.multi_fix.has_value());  // one light suffices: nothing bigger is searched
  ASSERT_EQ(s.changes().size(), 1u);
  EXPECT_EQ(s.description(), s.range_fix->description);
  // c sits inside both a's and b's reach, so only cutting the a-b overlap helps:
  // |ab| = 3 and r_b = 2, so a's range must drop below 1 (touching is no conflict).
  const LayerFix& fix = *s.range_fix;
  EXPECT_EQ(fix.name, "lamp a");
  EXPECT_FLOAT_EQ(fix.new_range, 0.99f);
  EXPECT_EQ(fix.description, "reduce range of 'lamp a' from 2.0 to 0.99 m");
  EXPECT_NE(s.message.find(fix.description), std::string::npos) << s.message;
  expect_fix_fits(doc.lights(), fix, 3);
  expect_fix_fits(doc.lights(), *s.move_fix, 3);
  EXPECT_NE(s.move_fix->description.find("move '"), std::string::npos);

  const std::size_t steps = doc.history().undo_count();
  ASSERT_TRUE(apply_fix(doc, fix));
  EXPECT_EQ(doc.history().undo_count(), steps + 1);
  EXPECT_EQ(doc.history().undo_description(), "Suggested fix: " + fix.description);
  EXPECT_FALSE(status.update(doc).over_cap());
  EXPECT_FALSE(status.suggestion(doc).needed);
  // The saved file says the same to the engine.
  const auto scene = scene::parse_scene_text(doc.to_text(), doc.file().string());
  ASSERT_TRUE(scene.ok());
  EXPECT_FALSE(analyse_layers(scene->lights, layer_cap(3)).over_cap());
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(status.update(doc).over_cap());

  // A move is applied the same way.
  ASSERT_TRUE(apply_fix(doc, *s.move_fix));
  EXPECT_EQ(doc.lights()[s.move_fix->light].position, s.move_fix->new_position);
  EXPECT_FALSE(status.update(doc).over_cap());
}

TEST(SuggestFix, AStaleFixIsRefused) {
  auto doc = testing::take(SceneDocument::load(fixture("lamps.json")));
  doc.set_position(2, {1.5f, 2.0f, 1.0f});
  const FixSuggestion s = suggest_fix(doc.lights(), layer_cap(3));
  ASSERT_NE(s.best(), nullptr);
  doc.set_name(s.best()->light, "renamed");
  EXPECT_FALSE(apply_fix(doc, *s.best()));
}

// Two separate tight groups of four: each needs 4 layers, a change to one light can fix
// only one group.
std::vector<Lamp> two_groups_of_four() {
  std::vector<Lamp> lamps;
  for (float base : {0.0f, 20.0f}) {
    for (int i = 0; i < 4; ++i)
      lamps.push_back({base + (i % 2 == 0 ? 0.0f : 1.0f), i < 2 ? 0.0f : 1.0f, 2.0f});
  }
  return lamps;
}

TEST(SuggestFix, ChangesOneLightPerGroupWhenNoSingleLightFixExists) {
  const SceneDocument doc = scene_of(two_groups_of_four());
  const FixSuggestion s = suggest_fix(doc.lights(), layer_cap(3));
  EXPECT_TRUE(s.needed);
  EXPECT_FALSE(s.range_fix.has_value());
  EXPECT_FALSE(s.move_fix.has_value());
  EXPECT_EQ(s.best(), nullptr);
  EXPECT_NE(s.message.find("no change to one light"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("needs 4"), std::string::npos) << s.message;
  ASSERT_TRUE(s.multi_fix.has_value()) << s.message;
  ASSERT_EQ(s.multi_fix->changes.size(), 2u) << s.message;
  EXPECT_LT(s.multi_fix->changes[0].light, 4u);  // one in each group
  EXPECT_GE(s.multi_fix->changes[1].light, 4u);
  EXPECT_EQ(s.changes().size(), 2u);
  EXPECT_EQ(s.description(), s.multi_fix->description);
  EXPECT_NE(s.message.find(s.multi_fix->description), std::string::npos) << s.message;
  EXPECT_FALSE(analyse_layers(lights_with(doc.lights(), *s.multi_fix), layer_cap(3)).over_cap());
}

TEST(SuggestFix, DefaultAtriumAtCapThreeGetsASeveralLightFix) {
  auto doc = testing::take(SceneDocument::load(testing::source_file("data/scenes/atrium.json")));
  const std::vector<scene::PointLight> before = doc.lights();
  LayerStatus status(layer_cap(3));
  ASSERT_TRUE(status.update(doc).over_cap());
  EXPECT_EQ(status.report().layers_needed, 4);     // a 4x4 grid where every 2x2 block is a K4
  const FixSuggestion s = status.suggestion(doc);  // a copy: the cache changes with the edit
  ASSERT_TRUE(s.needed);
  EXPECT_EQ(s.best(), nullptr) << "a one-light fix of the atrium? " << s.message;
  ASSERT_TRUE(s.multi_fix.has_value()) << s.message;
  const MultiLightFix& fix = *s.multi_fix;
  // Each change only removes conflicts of its own light, and the four corner 2x2 blocks
  // share no light: no fix can change fewer than four lights.
  EXPECT_EQ(fix.changes.size(), 4u) << fix.description;
  for (const LayerFix& change : fix.changes) {
    EXPECT_EQ(doc.lights()[change.light].name, change.name);
    if (change.kind == FixKind::reduce_range) {
      EXPECT_LT(change.new_range, change.old_range);
      EXPECT_GE(change.new_range, 0.5f * change.old_range);  // the default limit
    }
  }
  // The real colouring of the changed lights fits the layer_cap.
  const LayerReport fixed = analyse_layers(lights_with(doc.lights(), fix), layer_cap(3));
  EXPECT_FALSE(fixed.over_cap()) << fix.description;
  EXPECT_LE(fixed.layers_needed, 3);
  EXPECT_EQ(fixed.layers_needed, fix.layers_needed);

  // Applied: one undo step that brings the document under the layer_cap ...
  const std::size_t steps = doc.history().undo_count();
  const EditResult applied = apply_fix(doc, s);
  ASSERT_TRUE(applied) << applied.message;
  EXPECT_TRUE(applied.changed);
  EXPECT_EQ(doc.history().undo_count(), steps + 1);
  EXPECT_EQ(doc.history().undo_description(), "Suggested fix: change 4 lights");
  EXPECT_FALSE(status.update(doc).over_cap());
  EXPECT_LE(status.report().layers_needed, 3);
  EXPECT_FALSE(status.suggestion(doc).needed);
  const auto scene = scene::parse_scene_text(doc.to_text(), doc.file().string());
  ASSERT_TRUE(scene.ok());
  EXPECT_FALSE(analyse_layers(scene->lights, layer_cap(3)).over_cap());
  // ... and one undo restores every light exactly; redo makes every change again.
  ASSERT_TRUE(doc.undo());
  testing::expect_same_lights(before, doc.lights());
  EXPECT_FALSE(doc.can_undo());
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  testing::expect_same_lights(lights_with(before, fix), doc.lights());
}

TEST(SuggestFix, AStaleSeveralLightFixChangesNothing) {
  auto doc = scene_of(two_groups_of_four());
  const FixSuggestion s = suggest_fix(doc.lights(), layer_cap(3));
  ASSERT_TRUE(s.multi_fix.has_value()) << s.message;
  ASSERT_TRUE(doc.set_name(s.multi_fix->changes.back().light, "renamed"));
  const std::vector<scene::PointLight> before = doc.lights();
  const std::size_t steps = doc.history().undo_count();
  EXPECT_FALSE(apply_fix(doc, s));
  EXPECT_EQ(doc.history().undo_count(), steps);
  testing::expect_same_lights(before, doc.lights());
}

TEST(SuggestFix, SaysWhyWhenNoFixExistsWithinTheLimits) {
  // Five lamps within 10 cm of each other: no range cut to half separates two of them,
  // and moves are limited to 1 m.
  std::vector<Lamp> lamps;
  lamps.reserve(5);
  for (int i = 0; i < 5; ++i) lamps.push_back({0.02f * static_cast<float>(i), 0.0f, 2.0f});
  const SceneDocument doc = scene_of(lamps);
  FixSearchOptions limits;
  limits.max_move = 1.0f;
  const FixSuggestion s = suggest_fix(doc.lights(), layer_cap(3), limits);
  EXPECT_TRUE(s.needed);
  EXPECT_EQ(s.best(), nullptr);
  EXPECT_FALSE(s.multi_fix.has_value());
  EXPECT_TRUE(s.changes().empty());
  EXPECT_NE(s.message.find("nor changes to several within the limits"), std::string::npos)
      << s.message;
  EXPECT_NE(s.message.find("neither leaves the other's reach keeping 50% of its range or "
                           "moving up to 1.0 m"),
            std::string::npos)
      << s.message;
  auto copy = scene_of(lamps);
  EXPECT_FALSE(apply_fix(copy, s));

  // The atrium under a limit of three changed lights: its fix needs four.
  const auto atrium = SceneDocument::load(testing::source_file("data/scenes/atrium.json"));
  limits = {};
  limits.max_lights_changed = 3;
  const FixSuggestion a = suggest_fix(atrium->lights(), layer_cap(3), limits);
  EXPECT_FALSE(a.multi_fix.has_value());
  EXPECT_NE(a.message.find("at most 3 lights"), std::string::npos) << a.message;
}

// For one light, the largest range on the centimetre grid that fits, by brute force.
float largest_fitting_range(std::vector<scene::PointLight> lights, std::size_t i, int k) {
  const float old_range = lights[i].range;
  for (int cm = static_cast<int>(std::ceil(old_range * 100.0f)) - 1; cm >= 1; --cm) {
    lights[i].range = static_cast<float>(cm / 100.0);
    if (lights[i].range >= old_range) continue;
    if (!analyse_layers(lights, layer_cap(k)).over_cap()) return lights[i].range;
  }
  return 0.0f;
}

TEST(SuggestFix, RandomLayoutsWithAFixedSeed) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<float> coordinate(0.0f, 12.0f);
  std::uniform_real_distribution<float> reach(1.0f, 3.0f);
  int over_cap = 0;
  int range_fixes = 0;
  int move_fixes = 0;
  int multi_fixes = 0;
  for (int layout = 0; layout < 40; ++layout) {
    SCOPED_TRACE("layout " + std::to_string(layout));
    const bool sun = layout % 4 >= 2;  // the sun's own layer raises the layer_cap it needs by one
    const int k = 2 + layout % 2 + (sun ? 1 : 0);
    std::vector<Lamp> lamps(8 + rng() % 10);
    for (Lamp& lamp : lamps) {
      lamp = {std::round(coordinate(rng) * 100.0f) / 100.0f,
              std::round(coordinate(rng) * 100.0f) / 100.0f,
              std::round(reach(rng) * 100.0f) / 100.0f};
      // Every third light a spot: its sphere is its cone's bound, which a range change
      // both shrinks and moves.
      if (rng() % 3 == 0) lamp.spot_angle = 20 + static_cast<int>(rng() % 60);
    }
    SceneDocument doc = scene_of(lamps, sun);
    const FixSuggestion s = suggest_fix(doc.lights(), layer_cap(k));
    EXPECT_EQ(s.needed, analyse_layers(doc.lights(), layer_cap(k)).over_cap());
    if (!s.needed) continue;
    ++over_cap;
    if (s.range_fix) {
      ++range_fixes;
      expect_fix_fits(doc.lights(), *s.range_fix, k);
      // No light's range can be cut by noticeably less (brute force on a 1 cm grid).
      for (std::size_t i = sun ? 1 : 0; i < doc.lights().size(); ++i) {
        const float best = largest_fitting_range(doc.lights(), i, k);
        if (best <= 0.0f) continue;
        const float r = doc.lights()[i].range;
        EXPECT_GE((r - best) / r, s.range_fix->cost - 0.011f / r)
            << doc.lights()[i].name << " fits at " << best << "; suggested "
            << s.range_fix->description;
      }
    }
    if (!s.range_fix) {  // and when none is offered, none exists (brute force again)
      for (std::size_t i = sun ? 1 : 0; i < doc.lights().size(); ++i)
        EXPECT_EQ(largest_fitting_range(doc.lights(), i, k), 0.0f) << doc.lights()[i].name;
    }
    if (s.move_fix) {
      ++move_fixes;
      expect_fix_fits(doc.lights(), *s.move_fix, k);
    }
    if (const LayerFix* fix = s.best()) {
      ASSERT_TRUE(apply_fix(doc, *fix));
      EXPECT_FALSE(analyse_layers(doc.lights(), layer_cap(k)).over_cap());
      ASSERT_TRUE(doc.undo());
      EXPECT_TRUE(analyse_layers(doc.lights(), layer_cap(k)).over_cap());
    } else if (s.multi_fix) {  // several lights: one step, and undo restores every one
      ++multi_fixes;
      EXPECT_NE(s.message.find("no change to one light"), std::string::npos) << s.message;
      const std::vector<scene::PointLight> before = doc.lights();
      ASSERT_TRUE(apply_fix(doc, s));
      EXPECT_FALSE(analyse_layers(doc.lights(), layer_cap(k)).over_cap()) << s.message;
      ASSERT_TRUE(doc.undo());
      testing::expect_same_lights(before, doc.lights());
    } else {
      EXPECT_NE(s.message.find("no change"), std::string::npos);
    }
  }
  // The seed gives a mix; make sure the test really exercised the search.
  RecordProperty("over_cap", over_cap);
  RecordProperty("range_fixes", range_fixes);
  RecordProperty("move_fixes", move_fixes);
  RecordProperty("multi_fixes", multi_fixes);
  EXPECT_GE(over_cap, 10);
  EXPECT_GE(range_fixes, 3);
  EXPECT_GE(move_fixes, 3);
}

}  // namespace
}  // namespace antumbra::editor

namespace antumbra::editor {
namespace {

double milliseconds_to_suggest(std::span<const scene::PointLight> lights, int k,
                               FixSuggestion& out) {
  const auto start = std::chrono::steady_clock::now();
  out = suggest_fix(lights, layer_cap(k));
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// 1024 lamps on a 32x32 grid, `spacing` metres apart, range 1.
std::vector<Lamp> grid_of_1024(float spacing) {
  std::vector<Lamp> lamps;
  lamps.reserve(1024);
  for (int i = 0; i < 1024; ++i) {
    lamps.push_back(
        {spacing * static_cast<float>(i % 32), spacing * static_cast<float>(i >> 5), 1.0f});
  }
  return lamps;
}

TEST(SuggestFixTiming, TheAtriumAnd1024Lights) {
  FixSuggestion s;
  const auto atrium = SceneDocument::load(testing::source_file("data/scenes/atrium.json"));
  double atrium_ms = 1e9;
  for (int i = 0; i < 5; ++i)
    atrium_ms = std::min(atrium_ms, milliseconds_to_suggest(atrium->lights(), 3, s));
  EXPECT_TRUE(s.multi_fix.has_value());
  const std::string atrium_fix = s.description();

  // Sparse (no conflicts) but for two tight groups of four, far apart: two lights change.
  std::vector<Lamp> lamps = grid_of_1024(3.0f);
  for (Lamp& lamp : lamps) lamp.range = 1.2f;
  for (int g = 0; g < 2; ++g) {
    for (int i = 0; i < 4; ++i) {
      lamps[(600 * static_cast<std::size_t>(g)) + static_cast<std::size_t>(i)] = {
          200.0f + 50.0f * static_cast<float>(g) + (i % 2 == 0 ? 0.0f : 1.0f), i < 2 ? 0.0f : 1.0f,
          2.0f};
    }
  }
  const SceneDocument sparse = scene_of(lamps);
  const double sparse_ms = milliseconds_to_suggest(sparse.lights(), 3, s);
  ASSERT_TRUE(s.multi_fix.has_value()) << s.message;
  EXPECT_EQ(s.multi_fix->changes.size(), 2u);

  // Over the layer_cap everywhere (the atrium's king graph, 32x32): far past any fix of a few
  // lights, so the search must give up quickly, saying why.
  std::vector<Lamp> dense = grid_of_1024(1.5f);
  for (Lamp& lamp : dense) lamp.range = 1.1f;  // diagonals 2.12 m apart conflict
  const SceneDocument crowded = scene_of(dense);
  const double dense_ms = milliseconds_to_suggest(crowded.lights(), 3, s);
  EXPECT_FALSE(s.multi_fix.has_value());
  EXPECT_NE(s.message.find("nor changes to several"), std::string::npos) << s.message;
  std::printf("atrium fix: %s\n", atrium_fix.c_str());
  std::printf("suggest_fix: atrium %.2f ms, 1024 sparse %.1f ms, 1024 crowded %.1f ms\n  %s\n",
              atrium_ms, sparse_ms, dense_ms, s.message.c_str());
  RecordProperty("atrium_ms", std::to_string(atrium_ms));
  RecordProperty("sparse_1024_ms", std::to_string(sparse_ms));
  RecordProperty("crowded_1024_ms", std::to_string(dense_ms));
}

}  // namespace
}  // namespace antumbra::editor
