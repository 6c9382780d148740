#pragma once
// Support for the GPU render tests: sessions with validation + synchronization
// validation on (a test fails when any of its sessions reported a validation error),
// graph/scene loading from the source tree, image read-back (colour and depth) and
// image comparison with PNG artefacts for failures.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::render_testing {

// The source tree (holds data/, passes/, tests/data/gpu/).
std::filesystem::path source_dir();
std::filesystem::path gpu_data_dir();  // tests/data/gpu
// A folder under the build tree for failure artefacts of the running test (created).
std::filesystem::path artifact_dir();

runtime::DataPaths source_paths();

// Throw std::runtime_error with the diagnostics when the file is not valid (gtest
// reports the exception as a failure of the test).
fg::GraphDesc load_graph_file(const std::filesystem::path& path);
fg::GraphDesc default_graph();  // data/graphs/deferred.json
scene::Scene load_scene(const std::filesystem::path& path);
scene::Scene default_scene();                              // data/scenes/atrium.json
std::vector<std::filesystem::path> shipped_graph_files();  // data/graphs/*.json, sorted
std::string read_text(const std::filesystem::path& path);  // "" when unreadable
// One point and one spot light (tests/data/editor/lamps.json): every light path, and the
// reference's largest faces (faceSize 4096) at a cost lavapipe can afford.
scene::Scene point_and_spot_scene();

// Every diagnostic, one per line, for failure messages.
std::string describe(const base::Diagnostics& diagnostics);

// Read-back after render() (which waits for the frames), through gpu::read_image:
// colour formats, and depth (d32f/d16) as one channel.
// `layer`: the array layer of layered images.
gpu::HostImage read_resource(runtime::RenderSession& session, const std::string& resource,
                             std::uint32_t layer = 0);
gpu::HostImage read_output(runtime::RenderSession& session);  // the plan's output resource

// 8-bit image, as written to PNG: the texels quantised like gpu::write_png does.
struct Image8 {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t channels = 4;
  std::vector<std::uint8_t> bytes;
};
Image8 to_image8(const gpu::HostImage& image);
std::optional<Image8> load_png(const std::filesystem::path& path);  // stb_image, as RGBA
bool save_png(const std::filesystem::path& path, const Image8& image);

struct DiffStats {
  std::size_t pixels = 0;
  int max_abs = 0;              // largest per-channel difference, in 1/255 units
  double mean_abs = 0.0;        // mean per-channel difference over all pixels and channels
  std::size_t pixels_over = 0;  // pixels with some channel differing by more than `tolerance`
  int tolerance = 0;
  [[nodiscard]] double fraction_within() const {
    return pixels == 0 ? 1.0 : 1.0 - static_cast<double>(pixels_over) / static_cast<double>(pixels);
  }
};
// Same size and channel count required (checked by the caller).
DiffStats diff_images(const Image8& expected, const Image8& actual, int tolerance);
std::string describe(const DiffStats& stats);
// expected.png, actual.png, diff.png (|a-b| x 16, opaque) into `dir`.
void write_failure_images(const std::filesystem::path& dir, const Image8& expected,
                          const Image8& actual);

// Min/max/variance over the first three channels (all channels for 1-channel images),
// ignoring non-finite texels (counted separately).
struct TexelStats {
  float min = 0.0f;
  float max = 0.0f;
  double mean = 0.0;
  double variance = 0.0;
  std::size_t non_finite = 0;
};
TexelStats texel_stats(const gpu::HostImage& image);
// Some variance: not every texel the same value.
bool is_blank(const gpu::HostImage& image);

// Largest |a-b| over every texel; +inf when the sizes differ.
float max_abs_difference(const gpu::HostImage& a, const gpu::HostImage& b);

std::string validation_report(const gpu::Context& context);

// Copies a folder tree (for temporary data roots with edited shaders).
void copy_tree(const std::filesystem::path& from, const std::filesystem::path& to);

// Sessions opened by a test are checked for validation errors at TearDown (after
// wait_idle), besides the explicit checks a test makes. Shaders are compiled into a
// per-process SPIR-V cache under the temp dir unless ANTUMBRA_CACHE_DIR is set.
class RenderTest : public ::testing::Test {
 protected:
  static constexpr VkExtent2D kSmall{160, 90};
  static constexpr VkExtent2D kGolden{256, 144};

  void SetUp() override;
  void TearDown() override;

  // nullptr (and skip_reason_ set) when no Vulkan device exists: use OPEN_SESSION.
  runtime::RenderSession* open_session(VkExtent2D viewport = kSmall,
                                       const runtime::DataPaths& paths = source_paths());
  // The same with the caller's options (a host's pass types and shader folders); validation
  // is turned on whatever `options` say.
  runtime::RenderSession* open_session(runtime::SessionOptions options,
                                       const runtime::DataPaths& paths = source_paths());
  // Non-fatal check with every kept message in the failure text.
  static void expect_no_validation_errors(runtime::RenderSession& session);
  // Loads the graph and expects no error diagnostics.
  static void load_graph_ok(runtime::RenderSession& session, const fg::GraphDesc& graph);

  std::vector<std::unique_ptr<runtime::RenderSession>> sessions_;
  std::string skip_reason_;
};

}  // namespace antumbra::render_testing

// Opens a session into `var`, or skips the test when no Vulkan device exists.
#define OPEN_SESSION(var, ...)                                         \
  ::antumbra::runtime::RenderSession* var = open_session(__VA_ARGS__); \
  if ((var) == nullptr) GTEST_SKIP() << skip_reason_
