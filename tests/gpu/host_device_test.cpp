// Antumbra on a host's device, in the host's command buffer and image (docs/integration.md):
// the frame equals the one Antumbra renders on its own device, and each misuse is a clear
// error, located in the graph where it is about one of its resources.
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "device_requirement.hpp"
#include "render_test_support.hpp"
#include "test_host.hpp"

namespace antumbra::render_testing {
namespace {

constexpr VkImageUsageFlags kOutputUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                           VK_IMAGE_USAGE_STORAGE_BIT |
                                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

// The default graph with its display image imported: the host's image, not Antumbra's.
fg::GraphDesc graph_with_imported_output() {
  fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss.json");
  graph.resources[static_cast<std::size_t>(graph.find_resource(graph.output))].imported = true;
  return graph;
}

class HostDeviceTest : public RenderTest {
 protected:
  // nullptr (and the test skipped) without a Vulkan device.
  std::unique_ptr<TestHost> make_host(const HostOptions& options = {}) {
    try {
      return std::make_unique<TestHost>(options);
    } catch (const gpu::NoVulkanDeviceError& error) {
      gpu::testing::report_missing_device(error.what());
      skip_reason_ = error.what();
      return nullptr;
    }
  }
  static runtime::SessionOptions on(const TestHost& host) {
    runtime::SessionOptions options;
    options.host_device = host.device();
    options.viewport = kSmall;
    return options;
  }
  static std::vector<std::uint8_t> host_frame(TestHost& host, runtime::RenderSession& session,
                                              const TestHost::Image& output) {
    return host.frame(
        [&](VkCommandBuffer cmd) {
          const runtime::HostSubmission submission = session.record(cmd);
          return std::pair{submission.semaphore, submission.value};
        },
        output);
  }
};

#define MAKE_HOST(var, ...)          \
  auto var = make_host(__VA_ARGS__); \
  if (!(var)) GTEST_SKIP() << skip_reason_

TEST_F(HostDeviceTest, RendersIntoTheHostsImageAsOnItsOwnDevice) {
  MAKE_HOST(host);
  const auto output = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, kOutputUsage);
  Image8 hosted;
  {
    auto session = std::make_unique<runtime::RenderSession>(source_paths(), on(*host));
    EXPECT_TRUE(session->gpu().borrowed());
    // Bound before the graph exists: checked when it loads.
    EXPECT_FALSE(session->bind_image("ldr", TestHost::as_import(output)).has_errors());
    load_graph_ok(*session, graph_with_imported_output());
    session->set_scene(default_scene());
    host_frame(*host, *session, output);
    hosted = {kSmall.width, kSmall.height, 4, host_frame(*host, *session, output)};
    EXPECT_EQ(session->gpu().validation_error_count(), 0u) << validation_report(session->gpu());
  }
  EXPECT_EQ(host->validation_messages(), 0u) << host->last_message();

  OPEN_SESSION(own, kSmall);
  load_graph_ok(*own, load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss.json"));
  own->set_scene(default_scene());
  own->render(2, nullptr);
  const Image8 expected = to_image8(read_output(*own));
  const DiffStats diff = diff_images(expected, hosted, 3);
  const bool same = diff.fraction_within() >= 0.995 && diff.mean_abs < 0.5;
  if (!same) write_failure_images(artifact_dir(), expected, hosted);
  EXPECT_TRUE(same) << describe(diff);
  EXPECT_FALSE(is_blank(read_output(*own)));
}

TEST_F(HostDeviceTest, NamesWhatTheHostsDeviceLacks) {
  HostOptions lacking;
  lacking.skip_push_descriptor = true;
  lacking.skip_timeline = true;
  MAKE_HOST(host, lacking);
  try {
    runtime::RenderSession session(source_paths(), on(*host));
    ADD_FAILURE() << "a device without push descriptors and timeline semaphores was taken";
  } catch (const gpu::HostDeviceError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME), std::string::npos) << text;
    EXPECT_NE(text.find("timelineSemaphore"), std::string::npos) << text;
    EXPECT_NE(text.find("device_setup"), std::string::npos) << text;
  }
}

TEST_F(HostDeviceTest, MisusedImportsAreClearErrors) {
  MAKE_HOST(host);
  auto session = std::make_unique<runtime::RenderSession>(source_paths(), on(*host));
  session->set_scene(default_scene());
  const VkCommandBuffer cmd = host->command_buffer();
  EXPECT_THROW(session->record(cmd), std::logic_error);  // no graph yet
  load_graph_ok(*session, graph_with_imported_output());
  try {
    session->record(cmd);
    ADD_FAILURE() << "recorded with the imported output unbound";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("'ldr'"), std::string::npos) << error.what();
  }
  const auto expect_refused = [&](const std::string& name, const fgvk::ImportedImage& image,
                                  const std::string& why) {
    const base::Diagnostics d = session->bind_image(name, image);
    ASSERT_EQ(d.size(), 1u) << name << ": " << describe(d);
    const auto& diagnostic = *d.begin();
    EXPECT_EQ(diagnostic.code, codes::graph::kImportMismatch);
    EXPECT_NE(diagnostic.message.find(why), std::string::npos) << diagnostic.message;
    EXPECT_GT(diagnostic.line, 0) << "located in the graph's file";
  };
  const auto good = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, kOutputUsage);
  auto wrong_format = TestHost::as_import(good);
  wrong_format.format = VK_FORMAT_B8G8R8A8_UNORM;
  expect_refused("ldr", wrong_format, "format");
  const auto small = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, {80, 45}, kOutputUsage);
  expect_refused("ldr", TestHost::as_import(small), "extent 80x45");
  const auto sampled =
      host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, VK_IMAGE_USAGE_SAMPLED_BIT);
  expect_refused("ldr", TestHost::as_import(sampled), "usage lacks");
  expect_refused("hdr", TestHost::as_import(good), "does not import");
  expect_refused("nowhere", TestHost::as_import(good), "no resource 'nowhere'");
  // None of them bound anything: still refused to record.
  EXPECT_THROW(session->record(cmd), std::logic_error);
  // The usage a graph's use asks for and no more: TRANSFER_SRC only where the graph copies
  // from the image, so a swapchain image that is a colour attachment alone fits.
  const auto attachment =
      host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  const base::Diagnostics fits = session->bind_image("ldr", TestHost::as_import(attachment));
  EXPECT_FALSE(fits.has_errors()) << describe(fits);
  EXPECT_EQ(session->gpu().validation_error_count(), 0u) << validation_report(session->gpu());
  session.reset();
  EXPECT_EQ(host->validation_messages(), 0u) << host->last_message();
}

// A resize reloads the graph at the new size; the host's images of the old size are
// unbound with a note, and the frame runs again once images of the new size are bound.
TEST_F(HostDeviceTest, ResizeAsksForImagesOfTheNewSize) {
  MAKE_HOST(host);
  const auto first = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, kOutputUsage);
  auto session = std::make_unique<runtime::RenderSession>(source_paths(), on(*host));
  load_graph_ok(*session, graph_with_imported_output());
  session->set_scene(default_scene());
  EXPECT_FALSE(session->bind_image("ldr", TestHost::as_import(first)).has_errors());
  host_frame(*host, *session, first);

  constexpr VkExtent2D kResized{128, 72};
  const base::Diagnostics resized = session->resize(kResized);
  ASSERT_FALSE(resized.has_errors()) << describe(resized);
  const base::Diagnostic* note = resized.find(codes::graph::kImportMismatch);
  ASSERT_NE(note, nullptr) << describe(resized);
  EXPECT_EQ(note->severity, base::Severity::note);
  EXPECT_NE(note->message.find("128x72"), std::string::npos) << note->message;
  EXPECT_THROW(session->record(host->command_buffer()), std::logic_error);

  const auto second = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kResized, kOutputUsage);
  EXPECT_FALSE(session->bind_image("ldr", TestHost::as_import(second)).has_errors());
  const Image8 frame{kResized.width, kResized.height, 4, host_frame(*host, *session, second)};
  std::size_t lit = 0;
  for (std::size_t i = 0; i < frame.bytes.size(); i += 4) lit += frame.bytes[i] > 16 ? 1 : 0;
  EXPECT_GT(lit, frame.bytes.size() / 40) << "the resized frame is (nearly) black";
  EXPECT_EQ(session->gpu().validation_error_count(), 0u) << validation_report(session->gpu());
  session.reset();
  EXPECT_EQ(host->validation_messages(), 0u) << host->last_message();
}

// The host's own G-buffer in place of Antumbra's: a graph without its gbuffer pass imports
// depth, normals, albedo and emission, and every pass after (receiver culling in the
// shadow atlas, the penumbra, the lighting) reads the host's images. Here the host's
// G-buffer is drawn by a first session whose G-buffer targets are the same imported images;
// the second session's frame must equal the first's.
TEST_F(HostDeviceTest, TheHostsGBufferFeedsTheShadowPasses) {
  MAKE_HOST(host);
  struct Target {
    const char* name;
    VkFormat format;
    VkImageUsageFlags usage;
  };
  constexpr VkImageUsageFlags kColour =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
  const std::vector<Target> targets{
      {"depth", VK_FORMAT_D32_SFLOAT,
       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
      {"normal", VK_FORMAT_R16G16B16A16_SFLOAT, kColour},
      {"albedo", VK_FORMAT_R8G8B8A8_UNORM, kColour},
      {"emissive", VK_FORMAT_R16G16B16A16_SFLOAT, kColour}};
  std::vector<TestHost::Image> gbuffer;
  gbuffer.reserve(targets.size());
  for (const Target& t : targets) gbuffer.push_back(host->create_image(t.format, kSmall, t.usage));
  // Between the two sessions the G-buffer is read by shaders, as a host's would be.
  const fgvk::HostImageState sampled{VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                                     VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
  const auto bind = [&](runtime::RenderSession& session, bool writes) {
    for (std::size_t i = 0; i < targets.size(); ++i) {
      fgvk::ImportedImage image = TestHost::as_import(gbuffer[i]);
      if (!writes) image.before = sampled;
      image.after = sampled;
      const base::Diagnostics d = session.bind_image(targets[i].name, image);
      EXPECT_FALSE(d.has_errors()) << targets[i].name << ": " << describe(d);
    }
  };
  const auto with_imports = [&](bool keep_gbuffer_pass) {
    fg::GraphDesc graph = graph_with_imported_output();
    for (const Target& t : targets) {
      graph.resources[static_cast<std::size_t>(graph.find_resource(t.name))].imported = true;
    }
    if (!keep_gbuffer_pass) {
      std::erase_if(graph.passes,
                    [](const fg::PassInstanceDesc& p) { return p.type == "gbuffer"; });
    }
    return graph;
  };
  const auto antumbras = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, kOutputUsage);
  const auto hosts = host->create_image(VK_FORMAT_R8G8B8A8_UNORM, kSmall, kOutputUsage);
  Image8 expected;
  Image8 actual;
  {
    auto drawn = std::make_unique<runtime::RenderSession>(source_paths(), on(*host));
    load_graph_ok(*drawn, with_imports(true));
    drawn->set_scene(default_scene());
    bind(*drawn, true);
    EXPECT_FALSE(drawn->bind_image("ldr", TestHost::as_import(antumbras)).has_errors());
    auto fed = std::make_unique<runtime::RenderSession>(source_paths(), on(*host));
    load_graph_ok(*fed, with_imports(false));
    fed->set_scene(default_scene());
    bind(*fed, false);
    EXPECT_FALSE(fed->bind_image("ldr", TestHost::as_import(hosts)).has_errors());
    for (int frame = 0; frame < 2; ++frame) {
      expected = {kSmall.width, kSmall.height, 4, host_frame(*host, *drawn, antumbras)};
      actual = {kSmall.width, kSmall.height, 4, host_frame(*host, *fed, hosts)};
    }
    EXPECT_EQ(drawn->gpu().validation_error_count(), 0u) << validation_report(drawn->gpu());
    EXPECT_EQ(fed->gpu().validation_error_count(), 0u) << validation_report(fed->gpu());
  }
  EXPECT_EQ(host->validation_messages(), 0u) << host->last_message();
  std::size_t lit = 0;
  for (std::size_t i = 0; i < actual.bytes.size(); i += 4) lit += actual.bytes[i] > 16 ? 1 : 0;
  EXPECT_GT(lit, actual.bytes.size() / 40)
      << "the frame from the host's G-buffer is (nearly) black";
  const DiffStats diff = diff_images(expected, actual, 3);
  const bool same = diff.fraction_within() >= 0.995 && diff.mean_abs < 0.5;
  if (!same) write_failure_images(artifact_dir(), expected, actual);
  EXPECT_TRUE(same) << describe(diff);
}

// HostDevice::log_validation: a host whose messenger prints the layer's messages keeps
// Antumbra from printing them again; Antumbra still counts them either way.
TEST_F(HostDeviceTest, ValidationMessagesAreLoggedOnceWhenTheHostPrintsThem) {
  MAKE_HOST(host);
  auto sink = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64);
  spdlog::default_logger()->sinks().push_back(sink);
  const auto logged = [&] {
    std::size_t n = 0;
    for (const std::string& line : sink->last_formatted()) {
      n += line.find("VUID-VkBufferCreateInfo-size") != std::string::npos ? 1 : 0;
    }
    return n;
  };
  for (const bool log : {true, false}) {
    SCOPED_TRACE(log ? "log_validation = true" : "log_validation = false");
    gpu::HostDevice device = host->device();
    device.log_validation = log;
    gpu::Context context(device);
    const std::size_t before = logged();
    // A zero-sized buffer: one error from the layer, to every messenger.
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS) {
      vkDestroyBuffer(context.device(), buffer, nullptr);
    }
    EXPECT_GE(context.validation_error_count(), 1u);
    EXPECT_EQ(logged() > before, log) << ::testing::PrintToString(sink->last_formatted());
  }
  auto& sinks = spdlog::default_logger()->sinks();
  sinks.erase(std::remove(sinks.begin(), sinks.end(), sink), sinks.end());
  EXPECT_GE(host->validation_messages(), 2u) << "the host's own messenger saw both";
}

}  // namespace
}  // namespace antumbra::render_testing
