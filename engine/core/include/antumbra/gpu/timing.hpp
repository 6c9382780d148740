#pragma once
// GPU timing with timestamp queries, one query pool region per frame in flight.
// Results are read without stalling: a slot's queries are read back when the slot is
// reused (FrameLoop::begin_frame has waited for it by then), without
// VK_QUERY_RESULT_WAIT_BIT and with availability checked per query.

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::gpu {

struct ScopeTiming {
  std::string name;
  double gpu_ms = 0.0;
  std::uint32_t depth = 0;  // nesting level, 0 for outermost scopes
};

class GpuTimer {
 public:
  GpuTimer(Context& context, std::uint32_t frames_in_flight, std::uint32_t max_scopes = 128);

  // At the start of the slot's command buffer (after FrameLoop::begin_frame): collects
  // the results the slot holds from its previous frame, then resets its queries.
  void begin_frame(VkCommandBuffer cmd, std::uint32_t slot);
  // Returns a scope id for end_scope; scopes beyond max_scopes are ignored (id ~0u).
  std::uint32_t begin_scope(VkCommandBuffer cmd, std::string_view name);
  void end_scope(VkCommandBuffer cmd, std::uint32_t scope);

  // The newest frame whose every scope was available, in begin order.
  [[nodiscard]] const std::vector<ScopeTiming>& last_results() const { return last_results_; }
  [[nodiscard]] std::uint64_t completed_frames() const { return completed_frames_; }
  [[nodiscard]] bool supported() const { return supported_; }

  // RAII scope.
  class Scope {
   public:
    Scope(GpuTimer& timer, VkCommandBuffer cmd, std::string_view name)
        : timer_(timer), cmd_(cmd), id_(timer.begin_scope(cmd, name)) {}
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    ~Scope() { timer_.end_scope(cmd_, id_); }

   private:
    GpuTimer& timer_;
    VkCommandBuffer cmd_;
    std::uint32_t id_;
  };

 private:
  struct SlotScopes {
    std::vector<std::string> names;
    std::vector<std::uint32_t> depths;
    bool pending = false;  // queries written, not yet read
  };
  void collect(std::uint32_t slot);

  Context& context_;
  QueryPool pool_;
  std::uint32_t max_scopes_;
  std::uint32_t slot_ = 0;
  std::uint32_t depth_ = 0;
  double period_ns_ = 1.0;
  std::uint64_t valid_mask_ = ~0ull;
  bool supported_ = true;
  std::vector<SlotScopes> slots_;
  std::vector<ScopeTiming> last_results_;
  std::uint64_t completed_frames_ = 0;
};

// Opens a nested GpuTimer scope for every label it is told of (Context::set_label_listener):
// the steps inside a pass (a shadow pass's cull, raster and resolve) timed without the pass
// knowing. Scopes carry the label's name; a step recorded several times in a frame (once
// per chunk) gives one scope each.
class LabelScopes final : public LabelListener {
 public:
  explicit LabelScopes(GpuTimer& timer) : timer_(timer) {}
  void begin(VkCommandBuffer cmd, std::string_view name) override {
    open_.push_back(timer_.begin_scope(cmd, name));
  }
  void end(VkCommandBuffer cmd) override {
    if (open_.empty()) return;  // a label opened before the listener was set
    timer_.end_scope(cmd, open_.back());
    open_.pop_back();
  }

 private:
  GpuTimer& timer_;
  std::vector<std::uint32_t> open_;
};

// Wall-clock stopwatch for CPU stages.
class CpuTimer {
 public:
  CpuTimer() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  [[nodiscard]] double elapsed_ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace antumbra::gpu
