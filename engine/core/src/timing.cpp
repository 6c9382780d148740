#include "antumbra/gpu/timing.hpp"

#include <string>

#include "antumbra/gpu/vk_commands.hpp"

namespace antumbra::gpu {

namespace {
constexpr std::uint32_t kNoScope = ~0u;
}

GpuTimer::GpuTimer(Context& context, std::uint32_t frames_in_flight, std::uint32_t max_scopes)
    : context_(context), max_scopes_(max_scopes), slots_(frames_in_flight) {
  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &family_count,
                                           families.data());
  const std::uint32_t valid_bits = families[context.queue_family()].timestampValidBits;
  supported_ = valid_bits > 0 && context.limits().timestampPeriod > 0.0f;
  valid_mask_ = valid_bits >= 64 ? ~0ull : ((1ull << valid_bits) - 1);
  period_ns_ = static_cast<double>(context.limits().timestampPeriod);
  if (supported_) {
    pool_ = create_timestamp_query_pool(context, frames_in_flight * max_scopes * 2, "gpu_timer");
  }
}

void GpuTimer::begin_frame(VkCommandBuffer cmd, std::uint32_t slot) {
  slot_ = slot;
  depth_ = 0;
  if (!supported_) return;
  collect(slot);
  SlotScopes& scopes = slots_[slot];
  scopes.names.clear();
  scopes.depths.clear();
  vkCmdResetQueryPool(cmd, pool_, slot * max_scopes_ * 2, max_scopes_ * 2);
}

std::uint32_t GpuTimer::begin_scope(VkCommandBuffer cmd, std::string_view name) {
  SlotScopes& scopes = slots_[slot_];
  if (!supported_ || scopes.names.size() >= max_scopes_) return kNoScope;
  const auto id = static_cast<std::uint32_t>(scopes.names.size());
  scopes.names.emplace_back(name);
  scopes.depths.push_back(depth_++);
  scopes.pending = true;
  cmd_write_timestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                       (slot_ * max_scopes_ + id) * 2);
  return id;
}

void GpuTimer::end_scope(VkCommandBuffer cmd, std::uint32_t scope) {
  if (depth_ > 0) --depth_;
  if (scope == kNoScope) return;
  cmd_write_timestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                       (slot_ * max_scopes_ + scope) * 2 + 1);
}

void GpuTimer::collect(std::uint32_t slot) {
  SlotScopes& scopes = slots_[slot];
  if (!scopes.pending || scopes.names.empty()) return;
  scopes.pending = false;
  const auto count = static_cast<std::uint32_t>(scopes.names.size()) * 2;
  // Pairs of (value, availability).
  std::vector<std::uint64_t> data(std::size_t{count} * 2);
  const VkResult result = vkGetQueryPoolResults(
      context_.device(), pool_, slot * max_scopes_ * 2, count, data.size() * sizeof(std::uint64_t),
      data.data(), 2 * sizeof(std::uint64_t),
      VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
  if (result == VK_NOT_READY) return;  // some query unavailable: keep the older frame
  check(result, "vkGetQueryPoolResults");
  std::vector<ScopeTiming> timings;
  timings.reserve(scopes.names.size());
  for (std::size_t i = 0; i < scopes.names.size(); ++i) {
    const std::uint64_t begin = data[i * 4 + 0] & valid_mask_;
    const std::uint64_t end = data[i * 4 + 2] & valid_mask_;
    if (data[i * 4 + 1] == 0 || data[i * 4 + 3] == 0) return;
    const double ticks = end >= begin ? static_cast<double>(end - begin) : 0.0;
    timings.push_back({scopes.names[i], ticks * period_ns_ * 1e-6, scopes.depths[i]});
  }
  last_results_ = std::move(timings);
  ++completed_frames_;
}

}  // namespace antumbra::gpu
