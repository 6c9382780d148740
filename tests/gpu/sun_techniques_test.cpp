// The sun's techniques on data/scenes/courtyard-sun.json (a sun whose shadows run from
// 0.5 m to 70 m away, and four lamps), clean under validation and synchronization
// validation: the cascade view shows all four cascades of the default fit, and the
// filtered shadow maps (shadow-moments through every cascade) agree with PCF far better
// than an unshadowed frame does.

#include <array>
#include <string>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr VkExtent2D kView{320, 180};

class SunTechniquesTest : public RenderTest {
 protected:
  Image8 render(const std::string& graph_file, const std::string& output = "") {
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / graph_file);
    if (!output.empty()) graph.output = output;
    runtime::RenderSession* session = open_session(kView);
    EXPECT_NE(session, nullptr) << skip_reason_;
    if (session == nullptr) return {};
    load_graph_ok(*session, graph);
    session->set_scene(load_scene(source_dir() / "data" / "scenes" / "courtyard-sun.json"));
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    return to_image8(read_output(*session));
  }
};

// cascade_view.comp's colours, before shading darkens them: the channel pattern names the
// cascade (red, green, blue, yellow).
int cascade_of(const std::uint8_t* p) {
  const int r = p[0];
  const int g = p[1];
  const int b = p[2];
  if (r + g + b < 40) return -1;
  if (r > 2 * b && g > 2 * b && std::abs(r - g) < r / 4) return 3;
  if (r > g + g / 2 && r > b + b / 2) return 0;
  if (g > r + r / 3 && g > b + b / 3) return 1;
  if (b > r + r / 3 && b > g) return 2;
  return -1;
}

TEST_F(SunTechniquesTest, CascadeViewShowsEveryCascade) {
  const Image8 view = render("csm-debug.json", "cascadeView");
  ASSERT_EQ(view.width, kView.width);
  std::array<int, 4> counts{};
  for (std::size_t i = 0; i + 3 < view.bytes.size(); i += 4) {
    const int c = cascade_of(&view.bytes[i]);
    if (c >= 0) ++counts[static_cast<std::size_t>(c)];
  }
  const int pixels = static_cast<int>(kView.width * kView.height);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_GT(counts[c], pixels / 200) << "cascade " << c + 1 << " (of " << pixels << " pixels)";
  }
  // The nearest cascade covers the ground at the camera's feet, the bottom rows.
  const std::size_t bottom = (static_cast<std::size_t>(kView.height) - 2) * kView.width * 4;
  EXPECT_EQ(cascade_of(&view.bytes[bottom + std::size_t{4} * (kView.width / 2)]), 0);
}

double mean_difference(const Image8& a, const Image8& b) {
  return diff_images(a, b, 0).mean_abs;
}

TEST_F(SunTechniquesTest, FilteredMapsAgreeWithPcfThroughTheCascades) {
  const Image8 pcf = render("csm-debug.json");
  const Image8 unshadowed = render("lighting.json");
  const double shadow_effect = mean_difference(pcf, unshadowed);
  EXPECT_GT(shadow_effect, 4.0) << "the sun's shadows cover much of the frame";
  for (const char* graph : {"vsm.json", "evsm4.json", "msm.json", "vssm.json"}) {
    const double d = mean_difference(render(graph), pcf);
    std::printf("%s: mean |difference| to PCF %.2f/255 (unshadowed: %.2f)\n", graph, d,
                shadow_effect);
    EXPECT_LT(d, 0.25 * shadow_effect) << graph;
  }
}

}  // namespace
