// Links Antumbra::Antumbra (tests/integration/install_test.sh): what a host renderer does
// with the installed package. A RenderSession on the default device with validation on,
// the installed default graph and scene, two 160x90 frames, a PNG; any validation message
// fails. Exit 77 when there is no Vulkan device (the script decides whether that may skip).
#include <cstdio>
#include <exception>
#include <string>

#include "antumbra/fg/graph_source.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace runtime = antumbra::runtime;

// Antumbra_DATA_DIR of the package, compiled into data_dir.cpp.
const char* antumbra_data_dir();

namespace {

int render(const std::string& out) {
  const runtime::DataPaths paths{antumbra_data_dir()};
  auto graph = antumbra::fg::read_graph(
      antumbra::fg::GraphSource::from_file((paths.graphs() / "layered-ssss.json").string()));
  auto scene = antumbra::scene::load_scene_file((paths.scenes() / "atrium.json").string());
  if (!graph.ok() || !scene.ok()) {
    std::printf("FAIL: reading the installed graph or scene:\n%s%s",
                graph.diagnostics().to_text().c_str(), scene.diagnostics().to_text().c_str());
    return 1;
  }
  runtime::SessionOptions options;
  options.validation = true;
  options.viewport = {160, 90};
  runtime::RenderSession session(paths, options);
  if (const auto diagnostics = session.load_graph(graph.value()); diagnostics.has_errors()) {
    std::printf("FAIL: loading the graph:\n%s", diagnostics.to_text().c_str());
    return 1;
  }
  session.set_scene(std::move(scene.value()));
  session.render(2, nullptr);
  const auto& plan = session.executor().plan();
  session.write_image(plan.resources.at(static_cast<std::size_t>(plan.output)).name, out);
  auto& gpu = session.gpu();
  if (gpu.validation_error_count() + gpu.validation_warning_count() > 0) {
    for (const auto& m : gpu.validation_messages()) {
      std::printf("validation: %s: %s\n", m.id_name.c_str(), m.text.c_str());
    }
    std::printf("FAIL: %zu validation error(s), %zu warning(s)\n", gpu.validation_error_count(),
                gpu.validation_warning_count());
    return 1;
  }
  std::printf("PASS: rendered 2 frames on %s, wrote %s\n", gpu.device_name().c_str(), out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::printf("usage: render_frames OUT.png\n");
    return 2;
  }
  try {
    return render(argv[1]);
  } catch (const antumbra::gpu::NoVulkanDeviceError& e) {
    std::printf("no Vulkan device: %s\n", e.what());
    return 77;
  } catch (const std::exception& e) {
    std::printf("FAIL: %s\n", e.what());
    return 1;
  }
}
