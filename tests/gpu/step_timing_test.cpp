// SessionOptions::time_steps (`antumbra bench --steps`): the labels a pass opens are timed as
// steps of that pass, outside the passes' own timings.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "render_test_support.hpp"

namespace antumbra::render_testing {
namespace {

class StepTimingTest : public RenderTest {
 protected:
  // hard.json with the compute shadow rasteriser, whose cull, raster and resolve are labelled.
  // 128² faces: these tests count timings, and lavapipe draws 1024² faces for seconds a frame.
  static fg::GraphDesc compute_graph() {
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / "hard.json");
    for (auto& p : graph.passes) {
      if (p.type == "point-shadow-atlas") p.params["rasterizer"] = "compute";
    }
    for (auto& r : graph.resources) {
      if (r.name == "atlas") r.size = fg::SizeSpec{false, 1.0, 1.0, 128, 128};
    }
    return graph;
  }
};

TEST_F(StepTimingTest, LabelsInsideAPassAreItsStepsAndNotPasses) {
  runtime::SessionOptions options;
  options.viewport = kSmall;
  options.time_steps = true;
  OPEN_SESSION(session, options);
  load_graph_ok(*session, compute_graph());
  session->set_scene(default_scene());
  session->render(4);
  const auto steps = session->step_timings();
  const auto has = [&](const std::string& name) {
    return std::any_of(steps.begin(), steps.end(), [&](const auto& s) { return s.name == name; });
  };
  EXPECT_TRUE(has("shadows.cull"));
  EXPECT_TRUE(has("shadows.rasterDepth"));
  EXPECT_TRUE(has("shadows.resolve") || has("shadows.copy"));
  for (const auto& step : steps) {
    EXPECT_EQ(step.type, "shadows") << step.name;
    EXPECT_FALSE(step.gpu_samples.empty()) << step.name;
    EXPECT_GE(step.gpu_ms, 0.0) << step.name;
  }
  for (const auto& pass : session->pass_timings()) {
    EXPECT_EQ(pass.name.find('.'), std::string::npos) << "a step among the passes: " << pass.name;
    EXPECT_FALSE(pass.gpu_samples.empty()) << pass.name;
  }
  session->reset_timings();
  EXPECT_TRUE(session->step_timings().empty()) << "reset_timings() forgets the steps too";
}

// A session running for hours holds the samples of its latest frames only: between the
// window and twice it, dropped oldest first, for passes and steps alike.
TEST_F(StepTimingTest, TimingsHoldTheLatestFramesOnly) {
  runtime::SessionOptions options;
  options.viewport = {32, 18};
  options.time_steps = true;
  options.timing_window = 3;
  OPEN_SESSION(session, options);
  load_graph_ok(*session, compute_graph());
  session->set_scene(default_scene());
  session->render(6);
  EXPECT_EQ(session->timing_samples(), 6u);
  session->render(1);  // past twice the window: the latest 3 stay
  EXPECT_EQ(session->timing_samples(), 3u);
  session->render(20);
  EXPECT_GE(session->timing_samples(), 3u);
  EXPECT_LE(session->timing_samples(), 6u);
  for (const auto& pass : session->pass_timings()) EXPECT_LE(pass.gpu_samples.size(), 6u);
  for (const auto& step : session->step_timings()) EXPECT_LE(step.gpu_samples.size(), 6u);
}

TEST_F(StepTimingTest, WithoutTheOptionThereAreNoSteps) {
  OPEN_SESSION(session);
  load_graph_ok(*session, compute_graph());
  session->set_scene(default_scene());
  session->render(3);
  EXPECT_TRUE(session->step_timings().empty());
  EXPECT_FALSE(session->pass_timings().empty());
}

}  // namespace
}  // namespace antumbra::render_testing
