#include "antumbra/gpu/free_list.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace antumbra::gpu {

FreeList::FreeList(std::uint64_t capacity) : capacity_(capacity), free_bytes_(capacity) {
  if (capacity > 0) ranges_.emplace(0, capacity);
}

std::optional<std::uint64_t> FreeList::allocate(std::uint64_t size, std::uint64_t alignment) {
  if (size == 0) size = 1;  // a zero-sized allocation still needs a distinct offset
  for (auto it = ranges_.begin(); it != ranges_.end(); ++it) {
    const std::uint64_t begin = it->first;
    const std::uint64_t end = it->first + it->second;
    const std::uint64_t aligned = align_up(begin, alignment);
    if (aligned >= end || end - aligned < size) continue;
    ranges_.erase(it);
    if (aligned > begin) ranges_.emplace(begin, aligned - begin);
    if (aligned + size < end) ranges_.emplace(aligned + size, end - (aligned + size));
    free_bytes_ -= size;
    return aligned;
  }
  return std::nullopt;
}

void FreeList::free(std::uint64_t offset, std::uint64_t size) {
  if (size == 0) size = 1;
  if (offset + size > capacity_) throw std::logic_error("FreeList::free: range outside block");
  const std::uint64_t freed = size;
  auto next = ranges_.lower_bound(offset);
  if (next != ranges_.end() && next->first < offset + size) {
    throw std::logic_error("FreeList::free: range overlaps free space");
  }
  if (next != ranges_.begin()) {
    auto prev = std::prev(next);
    if (prev->first + prev->second > offset) {
      throw std::logic_error("FreeList::free: range overlaps free space");
    }
    if (prev->first + prev->second == offset) {
      offset = prev->first;
      size += prev->second;
      ranges_.erase(prev);
    }
  }
  if (next != ranges_.end() && next->first == offset + size) {
    size += next->second;
    ranges_.erase(next);
  }
  ranges_.emplace(offset, size);
  free_bytes_ += freed;
}

std::uint64_t FreeList::largest_free_range() const {
  std::uint64_t largest = 0;
  for (const auto& [offset, size] : ranges_) largest = std::max(largest, size);
  return largest;
}

}  // namespace antumbra::gpu
