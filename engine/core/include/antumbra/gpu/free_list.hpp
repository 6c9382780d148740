#pragma once
// The arithmetic of the sub-allocator, kept free of Vulkan so tests run without a
// device: a first-fit list of free ranges inside one block, coalesced on free.

#include <cstdint>
#include <map>
#include <optional>

namespace antumbra::gpu {

// Rounds value up to a multiple of alignment (a power of two, or any non-zero value).
constexpr std::uint64_t align_up(std::uint64_t value, std::uint64_t alignment) {
  if (alignment <= 1) return value;
  return (value + alignment - 1) / alignment * alignment;
}

class FreeList {
 public:
  explicit FreeList(std::uint64_t capacity);

  // First fit: the lowest offset where an aligned range of `size` fits. The padding in
  // front of an aligned allocation stays free. nullopt when nothing fits.
  std::optional<std::uint64_t> allocate(std::uint64_t size, std::uint64_t alignment);
  // Returns [offset, offset + size) to the list, merging with free neighbours.
  // Throws std::logic_error on a range that overlaps free space (double free).
  void free(std::uint64_t offset, std::uint64_t size);

  [[nodiscard]] std::uint64_t capacity() const { return capacity_; }
  [[nodiscard]] std::uint64_t free_bytes() const { return free_bytes_; }
  [[nodiscard]] std::uint64_t largest_free_range() const;
  [[nodiscard]] std::size_t free_range_count() const { return ranges_.size(); }
  [[nodiscard]] bool empty() const { return free_bytes_ == capacity_; }

 private:
  std::uint64_t capacity_;
  std::uint64_t free_bytes_;
  std::map<std::uint64_t, std::uint64_t> ranges_;  // offset -> size, disjoint, never adjacent
};

}  // namespace antumbra::gpu
