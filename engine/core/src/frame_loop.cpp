#include "antumbra/gpu/frame_loop.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace antumbra::gpu {

FrameLoop::FrameLoop(Context& context, std::uint32_t frames_in_flight) : context_(context) {
  if (frames_in_flight == 0) throw std::invalid_argument("FrameLoop: frames_in_flight == 0");
  slots_.resize(frames_in_flight);
  for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
    Slot& slot = slots_[i];
    slot.pool = create_command_pool(context, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                    "frame" + std::to_string(i) + ".pool");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = slot.pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(context.device(), &alloc, &slot.cmd),
          "vkAllocateCommandBuffers");
    context.set_name(slot.cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, "frame" + std::to_string(i) + ".cmd");
  }
  slot_ = frames_in_flight - 1;  // the first begin_frame() advances to slot 0
}

FrameLoop::~FrameLoop() {
  // The pools are destroyed deferred, but their command buffers must not be pending
  // when the pool goes: wait for our own submissions first.
  try {
    wait_all();
  } catch (...) {
    // Destructors do not throw; a lost device is reported by the next call anyway.
  }
}

void FrameLoop::wait_all() const {
  std::uint64_t newest = 0;
  for (const Slot& slot : slots_) newest = std::max(newest, slot.timeline_value);
  if (newest > 0) context_.wait_for(newest);
}

void FrameLoop::begin_host_frame() {
  if (recording_) throw std::logic_error("FrameLoop::begin_host_frame: previous frame not ended");
  slot_ = (slot_ + 1) % frames_in_flight();
  const Slot& slot = slots_[slot_];
  if (slot.timeline_value > 0) context_.wait_for(slot.timeline_value);
  context_.collect_garbage();
  recording_ = true;
  host_frame_ = true;
}

std::uint64_t FrameLoop::end_host_frame() {
  if (!recording_ || !host_frame_) throw std::logic_error("FrameLoop::end_host_frame: none begun");
  recording_ = false;
  host_frame_ = false;
  slots_[slot_].timeline_value = context_.reserve_host_submission();
  ++frame_number_;
  return slots_[slot_].timeline_value;
}

VkCommandBuffer FrameLoop::begin_frame() {
  if (recording_) throw std::logic_error("FrameLoop::begin_frame: previous frame not ended");
  slot_ = (slot_ + 1) % frames_in_flight();
  Slot& slot = slots_[slot_];
  if (slot.timeline_value > 0) context_.wait_for(slot.timeline_value);
  context_.collect_garbage();
  check(vkResetCommandPool(context_.device(), slot.pool, 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(slot.cmd, &begin), "vkBeginCommandBuffer");
  recording_ = true;
  return slot.cmd;
}

std::uint64_t FrameLoop::end_frame(const SubmitExtras& extras) {
  if (!recording_ || host_frame_) throw std::logic_error("FrameLoop::end_frame: no frame begun");
  Slot& slot = slots_[slot_];
  recording_ = false;
  check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer");
  slot.timeline_value = context_.submit(slot.cmd, extras);
  ++frame_number_;
  return slot.timeline_value;
}

void FrameLoop::abandon_frame() {
  if (!recording_) return;
  recording_ = false;
  if (host_frame_) {
    host_frame_ = false;  // the host's buffer is the host's to reset
    return;
  }
  // Ended so the pool reset finds it executable or invalid, never recording; the result
  // does not matter, as the buffer is never submitted.
  static_cast<void>(vkEndCommandBuffer(slots_[slot_].cmd));
}

}  // namespace antumbra::gpu
