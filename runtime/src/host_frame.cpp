// The host's frame and images (docs/integration.md, "The frame" and "The host's images"):
// a frame recorded into the host's command buffer, and the host's images bound to the
// graph's imported resources, checked where the graph declares them.
#include <stdexcept>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/runtime/render_session.hpp"

namespace antumbra::runtime {
namespace {

std::string resource_pointer(const std::string& name) {
  return "/resources/" + name;  // graph resource names are identifiers: nothing to escape
}

}  // namespace

HostSubmission RenderSession::record(VkCommandBuffer cmd) {
  if (!scene_) throw std::logic_error("RenderSession::record() before set_scene()");
  if (!executor_->loaded()) {
    throw std::logic_error("RenderSession::record() before a graph is loaded (load_graph)");
  }
  if (cmd == VK_NULL_HANDLE) {
    throw std::invalid_argument("RenderSession::record(): null command buffer");
  }
  executor_->require_imports();  // before anything is recorded into the host's buffer
  frames_->begin_host_frame();
  try {
    record_frame(cmd);
  } catch (...) {
    frames_->abandon_frame();
    throw;
  }
  return {gpu_->timeline(), frames_->end_host_frame()};
}

base::Diagnostics RenderSession::bind_image(const std::string& resource,
                                            const fgvk::ImportedImage& image) {
  base::Diagnostics out;
  if (!executor_->loaded()) {
    executor_->bind_import(resource, image);  // checked when a graph is loaded
    return out;
  }
  const fg::Plan& plan = executor_->plan();
  const int index = plan.find_resource(resource);
  if (index < 0) {
    out.add(live_document_.make(codes::graph::kImportMismatch, base::Severity::error,
                                "the graph has no resource '" + resource + "' to bind an image to",
                                "/resources"));
    return out;
  }
  const std::string why =
      fgvk::import_mismatch(plan.resources[static_cast<std::size_t>(index)], image);
  if (!why.empty()) {
    out.add(live_document_.make(codes::graph::kImportMismatch, base::Severity::error,
                                "the host's image for '" + resource + "': " + why,
                                resource_pointer(resource)));
    return out;
  }
  executor_->bind_import(resource, image);
  return out;
}

base::Diagnostics RenderSession::check_bound_imports(const fg::Plan& plan,
                                                     const base::JsonDocument& document,
                                                     std::vector<std::string>& stale) const {
  base::Diagnostics out;
  for (const auto& r : plan.resources) {
    if (!r.imported) continue;
    const fgvk::ImportedImage* image = executor_->bound_import(r.name);
    if (image == nullptr) continue;  // bound later, before the first frame
    const std::string why = fgvk::import_mismatch(r, *image);
    if (why.empty()) continue;
    fgvk::ImportedImage resized = *image;
    resized.extent = {r.extent.width, r.extent.height};
    if (fgvk::import_mismatch(r, resized).empty()) {
      // Only the size differs: the viewport changed, and the host has new images to bind.
      out.add(document.make(codes::graph::kImportMismatch, base::Severity::note,
                            "the host's image bound to '" + r.name + "' is " +
                                std::to_string(image->extent.width) + "x" +
                                std::to_string(image->extent.height) +
                                ", the new viewport's is not: unbound; bind one of " +
                                std::to_string(r.extent.width) + "x" +
                                std::to_string(r.extent.height) + " before the next frame",
                            resource_pointer(r.name)));
      stale.push_back(r.name);
      continue;
    }
    out.add(document.make(codes::graph::kImportMismatch, base::Severity::error,
                          "the host's image bound to '" + r.name + "': " + why,
                          resource_pointer(r.name)));
  }
  return out;
}

base::Diagnostics RenderSession::resize(VkExtent2D viewport) {
  if (!live_graph_) {
    set_viewport(viewport);
    return {};
  }
  const VkExtent2D before = options_.viewport;
  if (before.width == viewport.width && before.height == viewport.height) return {};
  set_viewport(viewport);
  // A copy: load_graph replaces live_graph_ when it succeeds.
  const fg::GraphDesc graph = *live_graph_;
  base::Diagnostics diagnostics = load_graph(graph);
  if (diagnostics.has_errors()) set_viewport(before);
  return diagnostics;
}

}  // namespace antumbra::runtime
