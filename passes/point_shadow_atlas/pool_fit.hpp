#pragma once
// How large a page pool's faces may be (docs/technique.md, "Page pool"): a pool too small
// for what the view needs draws every light's faces smaller until it holds them. Vulkan-free:
// the pass feeds it the GPU's counts (face_decision.hpp) as they come back.

#include <algorithm>
#include <cstdint>

namespace antumbra::passes {

// The pool's counts of one frame (FaceDecisionStats::Pool).
struct PoolCounts {
  std::uint32_t pages = 0;    // in the pool
  std::uint32_t needed = 0;   // pages some visible pixel needs (held, taken or missing)
  std::uint32_t missing = 0;  // needed pages left without a place
};

class PoolFit {
 public:
  // A frame whose needed pages went missing halves the cap (a face a quarter of the
  // pages); kCalmFrames frames in a row whose needs would still fit with faces twice as
  // wide (four times the pages, with a sixteenth to spare) double it again, up to none.
  static constexpr std::uint32_t kCalmFrames = 8;
  static constexpr std::uint32_t kSmallest = 128;  // one page: smaller saves no page

  void update(const PoolCounts& counts, std::uint32_t atlas_face) {
    const std::uint32_t current = cap_ == 0 ? atlas_face : cap_;
    if (counts.missing > 0) {
      calm_ = 0;
      cap_ = std::max(current / 2, std::min(kSmallest, atlas_face));
      return;
    }
    const bool room = std::uint64_t{counts.needed} * 4 * 16 <= std::uint64_t{counts.pages} * 15;
    calm_ = room && cap_ != 0 ? calm_ + 1 : 0;
    if (calm_ < kCalmFrames) return;
    calm_ = 0;
    cap_ = current * 2 >= atlas_face ? 0 : current * 2;
  }
  // The largest face size the pool takes now; 0: the atlas's (no cap).
  [[nodiscard]] std::uint32_t cap() const { return cap_; }
  void reset() { *this = PoolFit{}; }

 private:
  std::uint32_t cap_ = 0;
  std::uint32_t calm_ = 0;
};

}  // namespace antumbra::passes
