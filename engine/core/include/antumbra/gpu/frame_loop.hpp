#pragma once
// Frames in flight on the context's single timeline semaphore. begin_frame() waits
// until the slot's previous submission has finished (the timeline value end_frame()
// returned for it), resets the slot's command pool and returns a recording primary
// command buffer; end_frame() submits it, signalling the next timeline value.

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::gpu {

class FrameLoop {
 public:
  static constexpr std::uint32_t kDefaultFramesInFlight = 2;

  explicit FrameLoop(Context& context, std::uint32_t frames_in_flight = kDefaultFramesInFlight);
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;
  ~FrameLoop();  // waits for this loop's submissions

  // Also runs Context::collect_garbage(). Throws std::logic_error when a frame is open.
  VkCommandBuffer begin_frame();
  // Ends recording and submits; extra semaphores (swapchain acquire/present) optional.
  // Returns the timeline value this frame signals.
  std::uint64_t end_frame(const SubmitExtras& extras = {});
  // A frame recorded into a command buffer the host owns and submits (docs/integration.md,
  // "The frame"): waits for the slot and collects garbage as begin_frame() does, but
  // neither begins nor submits a command buffer. end_host_frame() reserves the timeline
  // value the host's submission must signal on Context::timeline(), and returns it.
  void begin_host_frame();
  std::uint64_t end_host_frame();
  // Drops the frame being recorded without submitting it (recording threw midway): the
  // slot's pool is reset when it is next begun. No-op when no frame is open.
  void abandon_frame();

  [[nodiscard]] std::uint32_t frames_in_flight() const {
    return static_cast<std::uint32_t>(slots_.size());
  }
  // Slot of the frame being recorded (or last recorded): index for per-frame resources.
  [[nodiscard]] std::uint32_t slot() const { return slot_; }
  // Frames submitted so far.
  [[nodiscard]] std::uint64_t frame_number() const { return frame_number_; }
  [[nodiscard]] bool recording() const { return recording_; }
  [[nodiscard]] VkCommandBuffer command_buffer() const { return slots_[slot_].cmd; }
  void wait_all() const;  // every submitted frame has finished on the GPU

 private:
  struct Slot {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    std::uint64_t timeline_value = 0;  // signalled when the slot's last frame is done
  };

  Context& context_;
  std::vector<Slot> slots_;
  std::uint32_t slot_ = 0;
  std::uint64_t frame_number_ = 0;
  bool recording_ = false;
  bool host_frame_ = false;  // the frame being recorded is in the host's command buffer
};

}  // namespace antumbra::gpu
