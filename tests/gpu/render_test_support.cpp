#include "render_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <stb_image.h>

#include "antumbra/base/json_document.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/frame_loop.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "device_requirement.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::render_testing {
namespace fs = std::filesystem;

fs::path source_dir() {
  return fs::path(ANTUMBRA_TEST_SOURCE_DIR);
}
fs::path gpu_data_dir() {
  return source_dir() / "tests" / "data" / "gpu";
}

fs::path artifact_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info != nullptr ? std::string(info->test_suite_name()) + "." + info->name()
                                     : std::string("unknown");
  std::replace(name.begin(), name.end(), '/', '_');
  fs::path dir = fs::path(ANTUMBRA_TEST_BINARY_DIR) / "gpu_test_output" / name;
  fs::create_directories(dir);
  return dir;
}

runtime::DataPaths source_paths() {
  return runtime::DataPaths{source_dir()};
}

std::string describe(const base::Diagnostics& diagnostics) {
  std::string text;
  for (const auto& d : diagnostics) text += "\n  " + base::format_text(d);
  return text;
}

fg::GraphDesc load_graph_file(const fs::path& path) {
  auto document = base::load_json_file(path.string());
  if (!document.ok()) {
    throw std::runtime_error("cannot read " + path.string() + describe(document.diagnostics()));
  }
  auto graph = fg::parse_graph(document.value());
  if (!graph.ok()) {
    throw std::runtime_error("invalid graph " + path.string() + describe(graph.diagnostics()));
  }
  return std::move(graph.value());
}

fg::GraphDesc default_graph() {
  return load_graph_file(source_dir() / "data" / "graphs" / "deferred.json");
}

scene::Scene load_scene(const fs::path& path) {
  auto scene = scene::load_scene_file(path.string());
  if (!scene.ok()) {
    throw std::runtime_error("invalid scene " + path.string() + describe(scene.diagnostics()));
  }
  return std::move(scene.value());
}

scene::Scene default_scene() {
  return load_scene(source_dir() / "data" / "scenes" / "atrium.json");
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> shipped_graph_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(source_dir() / "data" / "graphs")) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

scene::Scene point_and_spot_scene() {
  scene::Scene scene = load_scene(source_dir() / "tests" / "data" / "editor" / "lamps.json");
  std::erase_if(scene.lights, [](const scene::PointLight& light) {
    return light.name != "lamp a" && light.name != "spot";
  });
  if (scene.lights.size() != 2) throw std::runtime_error("lamps.json lost 'lamp a' or 'spot'");
  return scene;
}

gpu::HostImage read_resource(runtime::RenderSession& session, const std::string& resource,
                             std::uint32_t layer) {
  const gpu::Image* image = session.executor().gpu_image(resource);
  const fgvk::BoundImage* bound = session.executor().image(resource);
  if (image == nullptr || bound == nullptr) {
    throw std::runtime_error("resource \"" + resource + "\" is not a realised image");
  }
  if (layer >= bound->layers) {
    throw std::out_of_range("resource \"" + resource + "\" has " + std::to_string(bound->layers) +
                            " layer(s); layer " + std::to_string(layer) + " was asked for");
  }
  return gpu::read_image(session.gpu(), *image, bound->layout, layer);
}

gpu::HostImage read_output(runtime::RenderSession& session) {
  const auto& plan = session.executor().plan();
  return read_resource(session, plan.resources.at(static_cast<std::size_t>(plan.output)).name);
}

Image8 to_image8(const gpu::HostImage& image) {
  Image8 out{image.width, image.height, image.channels, {}};
  out.bytes.resize(image.texels.size());
  std::transform(image.texels.begin(), image.texels.end(), out.bytes.begin(), [](float v) {
    const float clamped = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
  });
  return out;
}

std::optional<Image8> load_png(const fs::path& path) {
  int width = 0;
  int height = 0;
  int channels = 0;
  stbi_uc* data = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
  if (data == nullptr) return std::nullopt;
  Image8 image{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 4, {}};
  image.bytes.assign(data, data + std::size_t(width) * std::size_t(height) * 4);
  stbi_image_free(data);
  return image;
}

bool save_png(const fs::path& path, const Image8& image) {
  gpu::HostImage host{image.width, image.height, image.channels, {}};
  host.texels.resize(image.bytes.size());
  std::transform(image.bytes.begin(), image.bytes.end(), host.texels.begin(),
                 [](std::uint8_t v) { return static_cast<float>(v) / 255.0f; });
  return gpu::write_png(path, host);  // v/255*255 rounds back to v exactly
}

DiffStats diff_images(const Image8& expected, const Image8& actual, int tolerance) {
  DiffStats stats;
  stats.tolerance = tolerance;
  stats.pixels = std::size_t{expected.width} * expected.height;
  const std::uint32_t channels = expected.channels;
  double sum = 0.0;
  for (std::size_t p = 0; p < stats.pixels; ++p) {
    bool over = false;
    for (std::uint32_t c = 0; c < channels; ++c) {
      const std::size_t i = p * channels + c;
      const int d = std::abs(int(expected.bytes[i]) - int(actual.bytes[i]));
      stats.max_abs = std::max(stats.max_abs, d);
      sum += d;
      over = over || d > tolerance;
    }
    if (over) ++stats.pixels_over;
  }
  const double samples = static_cast<double>(stats.pixels) * channels;
  stats.mean_abs = samples > 0 ? sum / samples : 0.0;
  return stats;
}

std::string describe(const DiffStats& stats) {
  std::ostringstream out;
  out << stats.pixels_over << " of " << stats.pixels << " pixels differ by more than "
      << stats.tolerance << "/255 (" << 100.0 * stats.fraction_within() << "% within); max "
      << stats.max_abs << "/255, mean " << stats.mean_abs << "/255";
  return out.str();
}

void write_failure_images(const fs::path& dir, const Image8& expected, const Image8& actual) {
  save_png(dir / "expected.png", expected);
  save_png(dir / "actual.png", actual);
  if (expected.width != actual.width || expected.height != actual.height ||
      expected.channels != actual.channels) {
    return;
  }
  Image8 diff = actual;
  for (std::size_t i = 0; i < diff.bytes.size(); ++i) {
    const bool alpha = diff.channels == 4 && i % 4 == 3;
    const int d = std::abs(int(expected.bytes[i]) - int(actual.bytes[i]));
    diff.bytes[i] = alpha ? 255 : static_cast<std::uint8_t>(std::min(255, d * 16));
  }
  save_png(dir / "diff.png", diff);
}

TexelStats texel_stats(const gpu::HostImage& image) {
  TexelStats stats;
  stats.min = std::numeric_limits<float>::infinity();
  stats.max = -std::numeric_limits<float>::infinity();
  const std::uint32_t used = std::min<std::uint32_t>(image.channels, 3);
  double sum = 0.0;
  double sum_sq = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.texels.size(); ++i) {
    if (i % image.channels >= used) continue;
    const float v = image.texels[i];
    if (!std::isfinite(v)) {
      ++stats.non_finite;
      continue;
    }
    stats.min = std::min(stats.min, v);
    stats.max = std::max(stats.max, v);
    sum += v;
    sum_sq += double(v) * v;
    ++count;
  }
  if (count > 0) {
    stats.mean = sum / double(count);
    stats.variance = std::max(0.0, sum_sq / double(count) - stats.mean * stats.mean);
  }
  return stats;
}

bool is_blank(const gpu::HostImage& image) {
  const auto stats = texel_stats(image);
  return !(stats.max > stats.min) || stats.variance < 1e-8;
}

float max_abs_difference(const gpu::HostImage& a, const gpu::HostImage& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    return std::numeric_limits<float>::infinity();
  }
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.texels.size(); ++i) {
    worst = std::max(worst, std::abs(a.texels[i] - b.texels[i]));
  }
  return worst;
}

std::string validation_report(const gpu::Context& context) {
  return std::to_string(context.validation_error_count()) +
         " validation error(s):" + gpu::testing::format_validation_messages(context);
}

void copy_tree(const fs::path& from, const fs::path& to) {
  fs::create_directories(to);
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

namespace {

// One SPIR-V cache per test process, removed at exit; keeps the user's cache out of
// the tests and the tests independent of stale entries.
void use_private_shader_cache() {
  static std::unique_ptr<gpu::testing::TempDir> cache;
  if (cache) return;
  if (const char* dir = std::getenv("ANTUMBRA_CACHE_DIR"); dir != nullptr && *dir != '\0') return;
  cache = std::make_unique<gpu::testing::TempDir>();
  ::setenv("ANTUMBRA_CACHE_DIR", cache->path().c_str(), 1);
}

}  // namespace

void RenderTest::SetUp() {
  use_private_shader_cache();
}

void RenderTest::TearDown() {
  for (auto& session : sessions_) {
    session->gpu().wait_idle();
    expect_no_validation_errors(*session);
  }
  sessions_.clear();
}

runtime::RenderSession* RenderTest::open_session(VkExtent2D viewport,
                                                 const runtime::DataPaths& paths) {
  runtime::SessionOptions options;
  options.viewport = viewport;
  return open_session(std::move(options), paths);
}

runtime::RenderSession* RenderTest::open_session(runtime::SessionOptions options,
                                                 const runtime::DataPaths& paths) {
  options.validation = true;  // ContextOptions::sync_validation defaults to on
  try {
    sessions_.push_back(std::make_unique<runtime::RenderSession>(paths, options));
  } catch (const gpu::NoVulkanDeviceError& error) {
    gpu::testing::report_missing_device(error.what());
    skip_reason_ = std::string("no Vulkan device: ") + error.what();
    return nullptr;
  }
  auto& session = *sessions_.back();
  EXPECT_TRUE(session.gpu().validation_enabled()) << "validation layer not enabled";
  return &session;
}

void RenderTest::expect_no_validation_errors(runtime::RenderSession& session) {
  EXPECT_EQ(session.gpu().validation_error_count(), 0u) << validation_report(session.gpu());
}

void RenderTest::load_graph_ok(runtime::RenderSession& session, const fg::GraphDesc& graph) {
  const auto diagnostics = session.load_graph(graph);
  ASSERT_FALSE(diagnostics.has_errors()) << "graph " << graph.name << ":" << describe(diagnostics);
}

}  // namespace antumbra::render_testing
