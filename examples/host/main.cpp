// An engine that takes Antumbra in (docs/integration.md, "A host in 200 lines:
// examples/host"). The engine owns the window, the instance, the device, the swapchain, the
// command buffers and the frame's synchronisation (vulkan_host.cpp), and a pass of its own
// (overlay.cpp). Antumbra renders the scene with layered soft shadows into the engine's
// image, recorded into the engine's command buffer. This file is the integration itself.
//
//   host [--headless [--out F.png]] [--frames N] [--size WxH] [--resize WxH] [--no-overlay]
//        [--validation] [--scene FILE] [--graph FILE]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/fg/graph_source.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_builder.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "overlay.hpp"
#include "vulkan_host.hpp"

const char* antumbra_data_dir();  // data_dir.cpp: the package's Antumbra_DATA_DIR

namespace {

using namespace antumbra;

struct Options {
  bool headless = false;
  bool overlay = true;
  bool validation = false;
  int frames = -1;  // -1: until the window closes (headless: 3)
  VkExtent2D size{1280, 720};
  VkExtent2D resize{0, 0};  // the window's size after the first frame (a test of resizing)
  std::string out = "host.png";
  std::string scene;  // empty: the scene built below
  std::string graph = std::string(antumbra_data_dir()) + "/data/graphs/layered-ssss.json";
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool value = i + 1 < argc;
    if (arg == "--headless") {
      o.headless = true;
    } else if (arg == "--no-overlay") {
      o.overlay = false;
    } else if (arg == "--validation") {
      o.validation = true;
    } else if (arg == "--frames" && value) {
      o.frames = std::atoi(argv[++i]);
    } else if (arg == "--out" && value) {
      o.out = argv[++i];
    } else if (arg == "--scene" && value) {
      o.scene = argv[++i];
    } else if (arg == "--graph" && value) {
      o.graph = argv[++i];
    } else if (arg == "--size" && value) {
      if (std::sscanf(argv[++i], "%ux%u", &o.size.width, &o.size.height) != 2) return false;
    } else if (arg == "--resize" && value) {
      if (std::sscanf(argv[++i], "%ux%u", &o.resize.width, &o.resize.height) != 2) return false;
    } else {
      return false;
    }
  }
  if (o.headless && o.frames < 0) o.frames = 3;
  return o.frames != 0 && o.size.width >= 8 && o.size.height >= 8;
}

// The engine's scene, handed over through calls: no scene file. scene.json beside this
// file is the same scene for the programs that read files (the integration test's
// comparison). SceneBuilder checks each call and computes the bounds culling reads.
scene::Scene build_scene() {
  scene::SceneBuilder builder;
  builder.set_name("host");
  scene::Camera camera;
  camera.position = {0.0f, 4.5f, 10.0f};
  camera.target = {0.0f, 0.8f, 0.0f};
  builder.set_camera(camera);
  builder.set_ambient(glm::vec3(0.02f));
  const auto floor =
      builder.add_material({.name = "floor", .albedo = glm::vec3(0.6f), .roughness = 0.9f});
  const auto stone =
      builder.add_material({.name = "stone", .albedo = {0.72f, 0.68f, 0.6f}, .roughness = 0.8f});
  const auto wood =
      builder.add_material({.name = "wood", .albedo = {0.5f, 0.33f, 0.18f}, .roughness = 0.7f});
  const auto add = [&builder](const scene::Mesh& mesh, glm::vec3 position,
                              scene::MaterialId material) {
    builder.add_mesh({}, mesh.vertices, mesh.indices, material,
                     glm::translate(glm::mat4(1.0f), position));
  };
  add(scene::make_box({14.0f, 0.2f, 14.0f}), {0.0f, -0.1f, 0.0f}, floor);
  for (const float x : {-3.0f, 3.0f}) {
    for (const float z : {-3.0f, 3.0f})
      add(scene::make_cylinder(0.35f, 2.5f, 20), {x, 1.25f, z}, stone);
  }
  add(scene::make_box({1.0f, 1.0f, 1.0f}), {0.0f, 0.5f, 0.0f}, wood);
  add(scene::make_box({0.7f, 0.7f, 0.7f}), {1.3f, 0.35f, 0.9f}, wood);
  add(scene::make_box({2.0f, 0.6f, 0.6f}), {-1.6f, 0.3f, 1.6f}, stone);
  const auto light = [&builder](const char* name, glm::vec3 position, glm::vec3 color) {
    builder.add_light({.name = name,
                       .position = position,
                       .color = color,
                       .intensity = 8.0f,
                       .range = 6.0f,
                       .size = 0.25f});
  };
  light("warm", {2.0f, 1.6f, 0.0f}, {1.0f, 0.55f, 0.25f});
  light("cool", {-2.0f, 1.6f, 0.0f}, {0.3f, 0.55f, 1.0f});
  light("green", {-3.0f, 2.2f, -4.5f}, {0.4f, 1.0f, 0.4f});
  light("rose", {3.0f, 2.2f, -4.5f}, {1.0f, 0.35f, 0.6f});
  return builder.build();
}

// The engine's animation: the first two lights circle the centre, handed over every frame.
std::vector<scene::PointLight> lights_at(std::vector<scene::PointLight> lights, int frame) {
  for (std::size_t i = 0; i < 2 && i < lights.size(); ++i) {
    const float angle = 0.05f * static_cast<float>(frame) + 3.14159f * static_cast<float>(i);
    lights[i].position = {2.0f * std::cos(angle), lights[i].position.y, 2.0f * std::sin(angle)};
  }
  return lights;
}

// Antumbra's diagnostics name the graph file, line:column and the fix; notes are for tools.
bool report(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note)
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
  return !diagnostics.has_errors();
}

// The engine's image as the graph's imported output (docs/integration.md, "The host's
// images"): where the engine left it and where Antumbra is to leave it.
fgvk::ImportedImage imported(const VulkanHost& vk, const VulkanHost::Target& target) {
  fgvk::ImportedImage image;
  image.image = target.image;
  image.view = target.view;
  image.format = vk.format();
  image.extent = vk.extent();
  image.usage = target.usage;
  // Before: last frame's contents are not needed (UNDEFINED); the engine's last use of it
  // (the copy, or the acquire that the submission waits for) is at `before_stage`.
  image.before = {VK_IMAGE_LAYOUT_UNDEFINED, target.before_stage, VK_ACCESS_2_NONE};
  // After: a colour attachment, visible to the overlay's blending that follows.
  image.after = {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
  return image;
}

int run(const Options& o) {
  VulkanHost vk(o.headless, o.validation, o.size);
  {
    // Antumbra on the engine's device (docs/integration.md, "The host's device"): it makes
    // no instance or device, and rotates its per-frame data over the engine's frames.
    runtime::SessionOptions options;
    options.host_device = vk.device();
    options.viewport = vk.extent();
    options.frames_in_flight = VulkanHost::kFramesInFlight;
    runtime::RenderSession session(runtime::DataPaths{antumbra_data_dir()}, options);

    // The scene: the engine's own, or a file through Antumbra's loader (--scene).
    scene::Scene scene;
    if (o.scene.empty()) {
      scene = build_scene();
    } else {
      auto loaded = scene::load_scene_file(o.scene);
      if (!report(loaded.diagnostics())) return 1;
      scene = std::move(loaded.value());
    }
    const std::vector<scene::PointLight> lights = scene.lights;
    session.set_scene(std::move(scene));

    // The graph: Antumbra's default, with its output made the engine's image ("import")
    // in the engine's format. Diagnostics are located in the graph file.
    std::string output;
    const auto import_output = [&](fg::GraphDesc& graph) {
      const int index = graph.find_resource(graph.output);
      if (index < 0) return;  // the compile names what is wrong with the output
      auto& resource = graph.resources[static_cast<std::size_t>(index)];
      resource.imported = true;
      resource.format =
          vk.format() == VK_FORMAT_B8G8R8A8_UNORM ? fg::Format::bgra8 : fg::Format::rgba8;
      output = graph.output;
    };
    if (!report(session.load_graph(fg::GraphSource::from_file(o.graph), import_output))) return 1;
    std::optional<Overlay> overlay;
    if (o.overlay) overlay.emplace(vk.device().device, vk.format());

    for (int frame = 0; (o.frames < 0 || frame < o.frames) && vk.poll(); ++frame) {
      const VulkanHost::Frame f = vk.begin_frame();
      // A new window size: Antumbra reloads the graph at it ("Resize") and unbinds the old
      // image; the new one is bound below, as every frame (a swapchain rotates images).
      if (f.resized) {
        std::printf("host: window resized to %ux%u\n", vk.extent().width, vk.extent().height);
        if (!report(session.resize(vk.extent()))) return 1;
      }
      if (!report(session.bind_image(output, imported(vk, f.target)))) return 1;
      if (o.scene.empty()) session.set_lights(lights_at(lights, frame));
      // Antumbra's frame, into the engine's command buffer ("The frame"); the engine's
      // submission signals what it returns.
      const runtime::HostSubmission submission = session.record(f.cmd);
      if (overlay) {  // the engine's own pass, after Antumbra's, into the same image
        overlay->draw(f.cmd, f.target.view, vk.extent(), static_cast<std::uint32_t>(frame));
      }
      vk.end_frame(f, submission.semaphore, submission.value, o.headless && frame + 1 == o.frames);
      if (frame == 0 && o.resize.width > 0) vk.request_size(o.resize);
    }
    vk.wait_idle();  // the overlay's pipeline is destroyed next
    if (o.headless && !gpu::write_png(o.out, vk.read_back())) return 1;
    if (o.headless && o.overlay) {
      const VkRect2D bar = Overlay::bar(vk.extent());
      std::printf("host: overlay rows %d-%u\n", bar.offset.y, bar.offset.y + bar.extent.height - 1);
    }
  }  // the session goes before the device it borrows
  if (vk.validation_messages() > 0) {
    std::fprintf(stderr, "host: %zu validation message(s)\n", vk.validation_messages());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: host [--headless [--out F.png]] [--frames N] [--size WxH] [--resize WxH]\n"
                 "            [--no-overlay] [--validation] [--scene FILE] [--graph FILE]\n");
    return 2;
  }
  try {
    return run(options);
  } catch (const antumbra::gpu::NoVulkanDeviceError& error) {
    std::fprintf(stderr, "host: no Vulkan device: %s\n", error.what());
    return 77;  // what the integration test skips on
  } catch (const std::exception& error) {
    std::fprintf(stderr, "host: %s\n", error.what());
    return 1;
  }
}
