// The host's images bound to imported graph resources (docs/integration.md, "The host's
// images"): checked against the plan, applied to each loaded plan, and the host's own
// states as the first barrier's source and the final barrier's target.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "antumbra/fgvk/executor.hpp"
#include "executor_state.hpp"

namespace antumbra::fgvk {
namespace {

std::string usage_names(VkImageUsageFlags flags) {
  static constexpr std::pair<VkImageUsageFlagBits, const char*> kNames[] = {
      {VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC"},
      {VK_IMAGE_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST"},
      {VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED"},
      {VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE"},
      {VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT"},
      {VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "DEPTH_STENCIL_ATTACHMENT"}};
  std::string text;
  for (const auto& [bit, name] : kNames) {
    if ((flags & bit) != 0) text += (text.empty() ? "" : " | ") + std::string(name);
  }
  return text;
}

std::string extent_text(std::uint32_t width, std::uint32_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// The graph's name of a VkFormat where it has one ("bgra8 (VkFormat 44)"), else the number.
std::string format_text(VkFormat format) {
  for (const fg::Format f : fg::all_formats()) {
    if (f != fg::Format::undefined && to_vk_format(f) == format) {
      return std::string(fg::to_string(f)) + " (VkFormat " + std::to_string(format) + ")";
    }
  }
  return "VkFormat " + std::to_string(format) + " (no graph format)";
}

}  // namespace

std::string import_mismatch(const fg::PlanResource& resource, const ImportedImage& image) {
  std::string why;
  const auto add = [&](const std::string& text) { why += (why.empty() ? "" : "; ") + text; };
  if (!resource.imported) return "the graph does not import it (add \"import\": true)";
  if (image.image == VK_NULL_HANDLE || image.view == VK_NULL_HANDLE) add("a null image or view");
  if (image.format != to_vk_format(resource.format)) {
    add("format " + format_text(image.format) + " is not the resource's " +
        format_text(to_vk_format(resource.format)) +
        " (a graph whose resource has the image's format takes it: \"format\" in the graph, "
        "or a fg::GraphEdit)");
  }
  if (image.extent.width != resource.extent.width ||
      image.extent.height != resource.extent.height) {
    add("extent " + extent_text(image.extent.width, image.extent.height) +
        " is not the resource's " + extent_text(resource.extent.width, resource.extent.height) +
        " (its size resolved against the viewport)");
  }
  if (image.layers != resource.layers) {
    add(std::to_string(image.layers) + " layer(s), the resource has " +
        std::to_string(resource.layers));
  }
  // image_usage() gives every image Antumbra creates TRANSFER_SRC (any may be read back);
  // of the host's image it is asked only where the graph copies from it, so a swapchain
  // image that offers no more than a colour attachment fits.
  VkImageUsageFlags needed = image_usage(resource);
  const auto& uses = resource.usages;
  if (std::find(uses.begin(), uses.end(), fg::Access::transfer_src) == uses.end()) {
    needed &= ~VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT};
  }
  if ((image.usage & needed) != needed) {
    add("usage lacks " + usage_names(needed & ~image.usage) + " (the graph uses it as " +
        usage_names(needed) + ")");
  }
  return why;
}

void Executor::bind_import(const std::string& resource, const ImportedImage& image) {
  imports_[resource] = image;
  if (!state_) return;
  const int index = state_->plan.find_resource(resource);
  if (index < 0 || !state_->plan.resources[static_cast<std::size_t>(index)].imported) return;
  auto& bound = state_->resources[static_cast<std::size_t>(index)].bound_image;
  bound.image = image.image;
  bound.view = image.view;
  bound.array_view = image.array_view != VK_NULL_HANDLE ? image.array_view : image.view;
}

const ImportedImage* Executor::bound_import(std::string_view resource) const {
  const auto it = imports_.find(resource);
  return it == imports_.end() ? nullptr : &it->second;
}

void Executor::unbind_import(std::string_view resource) {
  if (const auto it = imports_.find(resource); it != imports_.end()) imports_.erase(it);
  if (!state_) return;
  const int index = state_->plan.find_resource(resource);
  if (index < 0 || !state_->plan.resources[static_cast<std::size_t>(index)].imported) return;
  auto& bound = state_->resources[static_cast<std::size_t>(index)].bound_image;
  bound.image = VK_NULL_HANDLE;
  bound.view = VK_NULL_HANDLE;
  bound.array_view = VK_NULL_HANDLE;
}

void Executor::apply_imports(State& state) const {
  for (std::size_t i = 0; i < state.plan.resources.size(); ++i) {
    const auto& r = state.plan.resources[i];
    if (!r.imported) continue;
    const ImportedImage* image = bound_import(r.name);
    if (image == nullptr) continue;
    auto& bound = state.resources[i].bound_image;
    bound.image = image->image;
    bound.view = image->view;
    bound.array_view = image->array_view != VK_NULL_HANDLE ? image->array_view : image->view;
  }
}

void Executor::require_imports() const {
  if (!state_) throw std::logic_error("Executor::require_imports() before load()");
  for (const auto& r : state_->plan.resources) {
    if (!r.imported || r.first_use < 0 || bound_import(r.name) != nullptr) continue;
    throw std::logic_error("graph resource '" + r.name +
                           "' is imported and no host image is bound to it (bind it before "
                           "recording a frame; docs/integration.md)");
  }
}

SyncState Executor::source_of(const fg::PlanBarrier& barrier) const {
  const auto& rr = state_->resources[static_cast<std::size_t>(barrier.resource)];
  if (barrier.source == fg::BarrierSource::imported) {
    const auto& r = state_->plan.resources[static_cast<std::size_t>(barrier.resource)];
    const HostImageState& before = bound_import(r.name)->before;
    return {before.stages, before.access, before.layout};
  }
  return recorded_source(barrier, rr, state_->frames_recorded == 0);
}

SyncState Executor::target_of(const fg::PlanBarrier& barrier) const {
  const auto& rr = state_->resources[static_cast<std::size_t>(barrier.resource)];
  if (barrier.to_host) {
    const auto& r = state_->plan.resources[static_cast<std::size_t>(barrier.resource)];
    const HostImageState& after = bound_import(r.name)->after;
    return {after.stages, after.access, after.layout};
  }
  return sync_state(barrier.to, barrier.to_stage, rr.depth);
}

}  // namespace antumbra::fgvk
