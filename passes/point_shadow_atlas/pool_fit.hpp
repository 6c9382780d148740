#pragma once
// How large a page pool's faces may be (docs/technique.md, "Page pool"): a pool too small
// for what the view needs draws every light's faces smaller until it holds them. Vulkan-free:
// the pass feeds it the GPU's counts (face_decision.hpp) as they come back, frames late.

#include <algorithm>
#include <cstdint>

#include "../interface/shared/page_tables.h"

namespace antumbra::passes {

// Pool pages reserved at the pool's end for `records` face records' fallback tiles
// (interface/shared/page_tables.h): a needed page without a place reads its face's tile.
[[nodiscard]] constexpr std::uint32_t pool_fallback_pages(std::uint32_t records) {
  return (records + ANTUMBRA_FALLBACK_TILES_PER_PAGE - 1) / ANTUMBRA_FALLBACK_TILES_PER_PAGE;
}

// The pool's counts of one frame (FaceDecisionStats::Pool).
struct PoolCounts {
  std::uint64_t frame = 0;    // the frame they count
  std::uint32_t pages = 0;    // in the pool
  std::uint32_t needed = 0;   // pages some visible pixel needs (held, taken or missing)
  std::uint32_t missing = 0;  // needed pages left without a place
};

// The frame being planned: its index, the largest face size the last frame gave a light
// and the atlas's face size.
struct PoolFrame {
  std::uint64_t index = 0;
  std::uint32_t largest = 0;
  std::uint32_t atlas = 0;
};

class PoolFit {
 public:
  // A frame whose needed pages went missing halves the cap (a face a quarter of the
  // pages) from the largest face drawn; kCalmFrames frames in a row whose needs would
  // still fit with faces twice as wide (four times the pages, a sixteenth to spare) double
  // it again, up to none. Counts of frames planned before the cap last changed are
  // ignored: they come back after the change and say nothing about it.
  static constexpr std::uint32_t kCalmFrames = 8;
  static constexpr std::uint32_t kSmallest = 128;  // one page: smaller saves no page

  void update(const PoolCounts& counts, const PoolFrame& now) {
    if (counts.frame < since_) return;
    const std::uint32_t current = cap_ == 0 ? std::min(now.largest, now.atlas) : cap_;
    if (counts.missing > 0) {
      calm_ = 0;
      const std::uint32_t halved = std::max(current / 2, kSmallest);
      if (halved < current) change(halved, now);
      return;
    }
    const bool room = std::uint64_t{counts.needed} * 4 * 16 <= std::uint64_t{counts.pages} * 15;
    calm_ = room && cap_ != 0 ? calm_ + 1 : 0;
    if (calm_ < kCalmFrames) return;
    calm_ = 0;
    change(cap_ * 2 >= now.atlas ? 0 : cap_ * 2, now);
  }
  // The largest face size the pool takes now; 0: the atlas's (no cap).
  [[nodiscard]] std::uint32_t cap() const { return cap_; }
  void reset() { *this = PoolFit{}; }

 private:
  void change(std::uint32_t cap, const PoolFrame& now) {
    cap_ = cap;
    since_ = now.index;
  }

  std::uint32_t cap_ = 0;
  std::uint32_t calm_ = 0;
  std::uint64_t since_ = 0;  // the first frame planned with the cap
};

}  // namespace antumbra::passes
