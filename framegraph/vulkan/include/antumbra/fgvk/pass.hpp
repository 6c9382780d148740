#pragma once
// The runtime side of a pass type: what the executor calls. A pass records its
// draws or dispatches into the command buffer it is given; the executor has already
// placed every barrier its ports need (a pass never issues barriers for graph
// resources), opened a debug label and started a timestamp scope.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/fg/plan.hpp"

namespace antumbra::gpu {
class Context;
class ShaderCompiler;
}  // namespace antumbra::gpu

namespace antumbra::fgvk {

struct FrameResources;

// Thrown by Pass::prepare() when user-editable input (a shader) is broken; carries
// the located diagnostics so callers can print them and keep the last good state.
class PassError : public std::runtime_error {
 public:
  PassError(const std::string& what, base::Diagnostics diagnostics)
      : std::runtime_error(what), diagnostics_(std::move(diagnostics)) {}
  [[nodiscard]] const base::Diagnostics& diagnostics() const { return diagnostics_; }

 private:
  base::Diagnostics diagnostics_;
};

// A graph image as a pass sees it.
struct BoundImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;        // all layers (2D, or 2D array when layers > 1)
  VkImageView array_view = VK_NULL_HANDLE;  // all layers as a 2D array, even for one layer
  VkFormat format = VK_FORMAT_UNDEFINED;
  fg::Format graph_format = fg::Format::undefined;
  VkExtent2D extent{};
  std::uint32_t layers = 1;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // the layout the executor put it in
};

struct BoundBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};

// Ports of one pass resolved to realised resources (nullptr for unbound optional ports).
class PassBindings {
 public:
  struct Entry {
    std::string port;
    const BoundImage* image = nullptr;
    const BoundBuffer* buffer = nullptr;
  };
  explicit PassBindings(std::vector<Entry> entries) : entries_(std::move(entries)) {}
  PassBindings() = default;

  // Ports are named by constants shared with the pass's description (fg::PortId), and a
  // port the pass does not declare throws std::logic_error: a pass that asks for it has a
  // bug, which must not pass for an unbound optional port.
  [[nodiscard]] const BoundImage* image(fg::PortId port) const;
  [[nodiscard]] const BoundBuffer* buffer(fg::PortId port) const;
  // The image of a required port: throws std::logic_error when unbound, because the
  // graph compiler has already guaranteed required ports are bound.
  [[nodiscard]] const BoundImage& required_image(fg::PortId port) const;

 private:
  [[nodiscard]] const Entry& entry(fg::PortId port) const;

  std::vector<Entry> entries_;
};

// Shared samplers owned by the executor.
struct Samplers {
  VkSampler nearest_clamp = VK_NULL_HANDLE;
  VkSampler linear_clamp = VK_NULL_HANDLE;
};

// Handed to Pass::prepare() whenever the plan or the shaders change.
struct PrepareContext {
  gpu::Context& gpu;
  gpu::ShaderCompiler& shaders;
  const fg::PlanPass& pass;
  const PassBindings& bindings;
  // The folders a shader's relative name (tonemap/tonemap.frag) is searched in, in order:
  // the built-in passes/ folder, then a host's (docs/adding-a-pass.md).
  const std::vector<std::filesystem::path>& shader_dirs;
  VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
};

// Structured findings a pass reports about a frame (for example: the light layout
// needs more shadow layers than the cap allows). `render` prints them, `--format json`
// emits them and the editor lists them; they never stop the frame.
struct PassMessage {
  std::string pass;  // the pass instance's name
  std::string code;  // stable, from base/diagnostic_codes.hpp (e.g. layering::kOverCap)
  base::Severity severity = base::Severity::warning;
  std::string message;
  base::Json details;  // machine-readable payload
  // The parameter the message is about (e.g. "maxLayers"), so that reports point at it
  // in the graph file; empty: the pass itself.
  std::string param;
};

class FrameReport {
 public:
  void add(PassMessage message) { messages_.push_back(std::move(message)); }
  // Replaces the message of the same pass and code (added when not there): counts that
  // become known once the GPU has finished the frame.
  void replace(PassMessage message);
  void clear() { messages_.clear(); }
  [[nodiscard]] const std::vector<PassMessage>& messages() const { return messages_; }

 private:
  std::vector<PassMessage> messages_;
};

// Handed to Pass::execute() once per frame.
struct ExecuteContext {
  gpu::Context& gpu;
  VkCommandBuffer cmd;
  const fg::PlanPass& pass;
  const PassBindings& bindings;
  const FrameResources& frame;
  const Samplers& samplers;
  FrameReport& report;
};

class Pass {
 public:
  Pass() = default;
  Pass(const Pass&) = delete;
  Pass& operator=(const Pass&) = delete;
  virtual ~Pass() = default;

  // Creates pipelines for the formats of the bound resources. May throw; the
  // executor then keeps the previous state.
  virtual void prepare(PrepareContext& context) = 0;
  virtual void execute(ExecuteContext& context) = 0;
  // Shader files the pass depends on (with includes), for file watching.
  [[nodiscard]] virtual std::vector<std::string> shader_files() const { return {}; }
  // A reload: after every pass of the new graph is prepared, each is offered the live
  // graph's pass of the same name and type. Resources whose description did not change
  // are handed over with their contents, so a pass that caches work in its images (the
  // shadow atlas) may take over the bookkeeping of what they hold, when it would draw
  // them the same way (parameters and shaders). Never called for a failed load.
  virtual void adopt(Pass& previous) { static_cast<void>(previous); }
  // Once the GPU has finished every recorded frame: a pass that counts on the GPU
  // replaces its report messages with the final counts.
  virtual void collect(FrameReport& report) { static_cast<void>(report); }
};

using PassFactory = std::unique_ptr<Pass> (*)(const fg::PlanPass& pass);

}  // namespace antumbra::fgvk
