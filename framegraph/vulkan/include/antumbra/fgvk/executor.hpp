#pragma once
// Maps a compiled plan onto Vulkan: realises resources (aliased transients placed in
// one heap at the planned offsets), creates the pass objects, and each frame records
// the planned barriers as synchronization2 barriers around every pass, with a
// debug label and a timestamp scope per pass.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/fgvk/pass_registry.hpp"
#include "antumbra/fgvk/vk_sync.hpp"

namespace antumbra::gpu {
class Buffer;
class Image;
}  // namespace antumbra::gpu

namespace antumbra::fgvk {

// The state a host's image is in before the frame, or is to be left in after it
// (docs/integration.md, "The host's images"): raw synchronization2 values, since only the
// host knows what its own passes and presentation do.
struct HostImageState {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // UNDEFINED before: contents dropped
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// A host's image bound to a graph resource declared "import": true.
struct ImportedImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;        // all layers (2D, or 2D array when layers > 1)
  VkImageView array_view = VK_NULL_HANDLE;  // 2D array view; null: `view`
  VkFormat format = VK_FORMAT_UNDEFINED;    // must be the resource's format
  VkExtent2D extent{};                      // must be the resource's extent
  std::uint32_t layers = 1;
  VkImageUsageFlags usage = 0;  // what the image was created with: must cover the graph's use
  HostImageState before;        // where the host leaves it before the frame
  HostImageState after;         // where the frame leaves it for the host
};

// Empty when `image` can stand for `resource`; else what differs (format, extent, layers,
// missing usage bits, a null handle), in words, for a diagnostic at the resource.
std::string import_mismatch(const fg::PlanResource& resource, const ImportedImage& image);

// Hooks around each recorded pass (GPU timestamps, CPU timing); optional.
class PassObserver {
 public:
  virtual ~PassObserver() = default;
  virtual void begin_pass(VkCommandBuffer cmd, const fg::PlanPass& pass) = 0;
  virtual void end_pass(VkCommandBuffer cmd, const fg::PlanPass& pass) = 0;
};

class Executor {
 public:
  // `shader_dirs`: the folders a pass's shader files are searched in, in order (the built-in
  // passes/ folder first, then a host's; PrepareContext::shader_dirs).
  Executor(gpu::Context& gpu, gpu::ShaderCompiler& shaders, const PassRegistry& registry,
           std::vector<std::filesystem::path> shader_dirs,
           VkPipelineCache pipeline_cache = VK_NULL_HANDLE);
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;
  ~Executor();

  // Real memory footprints on this device, for fg::CompileOptions::footprint, so the
  // aliasing plan's offsets are valid for the images actually created.
  [[nodiscard]] fg::FootprintFn footprint_fn() const;

  // Realises `plan`. All-or-nothing: on an exception the previous plan stays live
  // and its objects untouched. Resources of the live plan whose description did not
  // change (fg::same_realisation) move to the new plan with their contents.
  void load(fg::Plan plan);
  // How many resources the last load() took over from the plan before it.
  [[nodiscard]] std::size_t kept_resources() const;
  [[nodiscard]] bool loaded() const { return state_ != nullptr; }
  [[nodiscard]] const fg::Plan& plan() const;

  // Records one frame of the plan into `cmd`. Passes add their findings to `report`
  // (cleared first) when one is given. Each barrier records the source the plan names;
  // with checks_sources() a planned source that is not the state the executor left the
  // resource in throws std::logic_error. On an exception the frame is not to be
  // submitted: the tracked states return to where the frame began.
  void record(VkCommandBuffer cmd, const FrameResources& frame, PassObserver* observer = nullptr,
              FrameReport* report = nullptr);
  // Whether record() checks each planned source against the tracked state: in debug
  // builds, and whenever the context has validation on (every GPU test, --validation).
  [[nodiscard]] bool checks_sources() const { return check_sources_; }
  // After the GPU has finished the recorded frames: every pass's final counts
  // (Pass::collect) into `report`.
  void collect(FrameReport& report);

  // Binds the host's image to imported resource `resource`, for this plan and any loaded
  // later that imports the same name; rebind each frame for a swapchain image. The
  // caller checks it first (import_mismatch). record() throws std::logic_error while a
  // used import is unbound.
  void bind_import(const std::string& resource, const ImportedImage& image);
  [[nodiscard]] const ImportedImage* bound_import(std::string_view resource) const;
  // Forgets the host's image of `resource` (one of an old size, after a resize).
  void unbind_import(std::string_view resource);
  // Throws std::logic_error naming the first imported resource the plan uses with no
  // image bound (record() calls it before recording anything).
  void require_imports() const;

  // The realised image of a resource, with its current layout; nullptr if none.
  [[nodiscard]] const BoundImage* image(std::string_view resource) const;
  // The realised image itself (for read-back); nullptr if none.
  [[nodiscard]] const gpu::Image* gpu_image(std::string_view resource) const;
  // The realised buffer of a resource (for read-back: every graph buffer is a transfer
  // source); nullptr if none.
  [[nodiscard]] const gpu::Buffer* gpu_buffer(std::string_view resource) const;
  // Bytes of device memory the plan's resources use (heap + individual allocations).
  [[nodiscard]] std::uint64_t resource_bytes() const;
  // Every shader file the passes read (for file watching).
  [[nodiscard]] std::vector<std::string> shader_files() const;
  // The passes (names, in execution order) that read any of `files` (reload summaries).
  [[nodiscard]] std::vector<std::string> passes_reading(
      const std::vector<std::string>& files) const;

 private:
  struct State;
  // The live resource named `resource` (image(), gpu_image(), gpu_buffer()), or null.
  [[nodiscard]] const struct RealisedResource* realised(std::string_view resource) const;
  // Index of the live resource `resource` may take over, or -1.
  [[nodiscard]] int live_match(const fg::PlanResource& resource) const;
  // The steps of load(), in order; each works on the state being built.
  void create_transient_heap(State& state) const;
  std::vector<int> realise_resources(State& state) const;
  void create_passes(State& state) const;
  void prepare_passes(State& state);
  void adopt_predecessors(State& state) const;
  void hand_over_kept_resources(State& state, const std::vector<int>& kept);
  void check_source(const fg::PlanBarrier& barrier, std::string_view before) const;
  // `before`: the pass the barriers precede, for messages (empty: the final barriers).
  void record_barriers(VkCommandBuffer cmd, const std::vector<fg::PlanBarrier>& barriers,
                       std::string_view before);
  void restore_frame_start();
  void apply_imports(State& state) const;
  // The source and target a barrier records (the host's states for imports).
  [[nodiscard]] SyncState source_of(const fg::PlanBarrier& barrier) const;
  [[nodiscard]] SyncState target_of(const fg::PlanBarrier& barrier) const;

  gpu::Context& gpu_;
  gpu::ShaderCompiler& shaders_;
  const PassRegistry& registry_;
  std::vector<std::filesystem::path> shader_dirs_;
  VkPipelineCache pipeline_cache_;
  bool check_sources_ = false;
  std::unique_ptr<State> state_;
  std::map<std::string, ImportedImage, std::less<>> imports_;
  Samplers samplers_;
  struct OwnedSamplers;
  std::unique_ptr<OwnedSamplers> owned_samplers_;
};

}  // namespace antumbra::fgvk
