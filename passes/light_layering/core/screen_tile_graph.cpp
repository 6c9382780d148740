// Screen-tile conflict graph: lights conflict when their dilated footprints reach a
// common screen tile.
#include <algorithm>
#include <cmath>
#include <limits>

#include "antumbra/layering/conflict_graph.hpp"
#include "graph_internal.hpp"

namespace antumbra::layering {

using detail::kMaxCellCoord;

// The bounds of the tile ranges of the lights on screen.
struct GraphBuilder::TileExtent {
  glm::ivec2 lo{std::numeric_limits<int>::max()};
  glm::ivec2 hi{std::numeric_limits<int>::min()};
  double span_sum = 0.0;  // width + height of every light's range, in tiles
  std::uint32_t on_screen = 0;
};

// Lights are binned into squares of `bin` tiles: two lights share a tile exactly when
// their tile ranges overlap, so the bins only accelerate the search.
struct GraphBuilder::TileBins {
  glm::ivec2 lo;     // the first tile of bin (0, 0)
  int bin = 1;       // tiles per bin side
  glm::ivec2 count;  // bins per axis

  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(count.x) * static_cast<std::size_t>(count.y);
  }
  // The bins a tile range reaches, inclusive.
  [[nodiscard]] glm::ivec4 range_of(const glm::ivec4& r) const {
    return glm::ivec4((r.x - lo.x) / bin, (r.y - lo.y) / bin, (r.z - lo.x) / bin,
                      (r.w - lo.y) / bin);
  }
};

const ConflictGraph& GraphBuilder::build_screen_tile(std::span<const ScreenRect> rects,
                                                     const TileParams& params) {
  const auto n = static_cast<std::uint32_t>(rects.size());
  edges_.clear();
  const TileExtent extent = assign_tile_ranges(rects, params);
  if (extent.on_screen == 0) {
    finish_graph(n);
    return graph_;
  }
  // bin = 1 would be per-tile lists; bins near the mean footprint keep per-bin lists short
  // when footprints are large (hundreds of tiles each).
  TileBins bins;
  bins.lo = extent.lo;
  bins.bin = std::max(1, static_cast<int>(extent.span_sum / (2.0 * extent.on_screen)));
  bins.count = (extent.hi - extent.lo) / bins.bin + 1;
  bin_lights(bins);
  collect_tile_pairs(bins);
  finish_graph(n);
  return graph_;
}

// Inclusive tile range per light (x0, y0, x1, y1); x1 < x0 means off screen.
GraphBuilder::TileExtent GraphBuilder::assign_tile_ranges(std::span<const ScreenRect> rects,
                                                          const TileParams& params) {
  const auto n = static_cast<std::uint32_t>(rects.size());
  const float tile = static_cast<float>(std::max(params.tile_size, 1));
  const bool clamp = params.viewport.x > 0 && params.viewport.y > 0;
  const glm::ivec2 tiles_on_screen =
      (params.viewport + std::max(params.tile_size, 1) - 1) / std::max(params.tile_size, 1);
  tile_range_.resize(n);
  TileExtent extent;
  for (std::uint32_t i = 0; i < n; ++i) {
    glm::ivec4 r(0, 0, -1, -1);
    if (!rects[i].empty()) {
      const float d = std::max(params.dilation_px, 0.0f);
      auto to_tile = [&](float p) {
        return static_cast<int>(std::floor(std::clamp(p / tile, -kMaxCellCoord, kMaxCellCoord)));
      };
      // The max edge is exclusive: a rect ending exactly on a tile border stays out of it.
      r = glm::ivec4(to_tile(rects[i].min.x - d), to_tile(rects[i].min.y - d),
                     static_cast<int>(std::ceil((rects[i].max.x + d) / tile)) - 1,
                     static_cast<int>(std::ceil((rects[i].max.y + d) / tile)) - 1);
      if (clamp) {
        r = glm::ivec4(std::max(r.x, 0), std::max(r.y, 0), std::min(r.z, tiles_on_screen.x - 1),
                       std::min(r.w, tiles_on_screen.y - 1));
      }
    }
    if (r.z < r.x || r.w < r.y) r = glm::ivec4(0, 0, -1, -1);
    tile_range_[i] = r;
    if (r.z >= r.x) {
      extent.lo = glm::min(extent.lo, glm::ivec2(r.x, r.y));
      extent.hi = glm::max(extent.hi, glm::ivec2(r.z, r.w));
      extent.span_sum += static_cast<double>(r.z - r.x + 1) + static_cast<double>(r.w - r.y + 1);
      ++extent.on_screen;
    }
  }
  return extent;
}

// Counting sort of the on-screen lights into the bins their tile ranges reach.
void GraphBuilder::bin_lights(const TileBins& bins) {
  const auto n = static_cast<std::uint32_t>(tile_range_.size());
  const std::size_t bin_count = bins.size();
  bucket_start_.assign(bin_count + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (tile_range_[i].z < tile_range_[i].x) continue;
    const glm::ivec4 b = bins.range_of(tile_range_[i]);
    for (int y = b.y; y <= b.w; ++y)
      for (int x = b.x; x <= b.z; ++x)
        ++bucket_start_[static_cast<std::size_t>(y * bins.count.x + x) + 1];
  }
  for (std::size_t b = 0; b < bin_count; ++b) bucket_start_[b + 1] += bucket_start_[b];
  tile_lights_.resize(bucket_start_[bin_count]);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (tile_range_[i].z < tile_range_[i].x) continue;
    const glm::ivec4 b = bins.range_of(tile_range_[i]);
    for (int y = b.y; y <= b.w; ++y)
      for (int x = b.x; x <= b.z; ++x)
        tile_lights_[bucket_start_[static_cast<std::size_t>(y) * bins.count.x + x]++] = i;
  }
  for (std::size_t b = bin_count; b > 0; --b) bucket_start_[b] = bucket_start_[b - 1];
  bucket_start_[0] = 0;
}

// Pairs inside each bin. A pair is reported only from the bin holding its first shared
// tile: both ranges reach the bin, so that tile is never past the bin's end and the test
// is "not before the bin's start", with no division. Whether two footprints overlap is a
// coin toss to the branch predictor, so, as for the world grid, a vectorisable loop flags
// each pair of a light with the bin's later lights and a branch-free pass compacts them.
void GraphBuilder::collect_tile_pairs(const TileBins& bins) {
  for (int by = 0; by < bins.count.y; ++by) {
    for (int bx = 0; bx < bins.count.x; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * bins.count.x + bx;
      const std::uint32_t begin = bucket_start_[b];
      const std::uint32_t size = bucket_start_[b + 1] - begin;
      if (size < 2) continue;
      bin_x0_.resize(size);
      bin_y0_.resize(size);
      bin_x1_.resize(size);
      bin_y1_.resize(size);
      for (std::uint32_t k = 0; k < size; ++k) {
        const glm::ivec4 r = tile_range_[tile_lights_[begin + k]];
        bin_x0_[k] = r.x;
        bin_y0_[k] = r.y;
        bin_x1_[k] = r.z;
        bin_y1_[k] = r.w;
      }
      if (pair_hits_.size() < size) {
        pair_hits_.resize(size);
        candidates_.resize(size);
      }
      const glm::ivec2 start = bins.lo + glm::ivec2(bx, by) * bins.bin;
      for (std::uint32_t a = 0; a + 1 < size; ++a) collect_bin_pairs(begin, a, size, start);
    }
  }
}

// Light a of the bin (entries begin..) against the bin's later lights.
void GraphBuilder::collect_bin_pairs(std::uint32_t begin, std::uint32_t a, std::uint32_t size,
                                     glm::ivec2 start) {
  const int ax0 = bin_x0_[a];
  const int ay0 = bin_y0_[a];
  const int ax1 = bin_x1_[a];
  const int ay1 = bin_y1_[a];
  std::uint32_t* hits = pair_hits_.data();
  for (std::uint32_t k = a + 1; k < size; ++k) {
    const int ox0 = std::max(ax0, bin_x0_[k]);
    const int oy0 = std::max(ay0, bin_y0_[k]);
    const int ox1 = std::min(ax1, bin_x1_[k]);
    const int oy1 = std::min(ay1, bin_y1_[k]);
    hits[k] = static_cast<std::uint32_t>((ox0 <= ox1) & (oy0 <= oy1) & (ox0 >= start.x) &
                                         (oy0 >= start.y));
  }
  std::uint32_t count = 0;
  for (std::uint32_t k = a + 1; k < size; ++k) {
    candidates_[count] = k;
    count += hits[k];
  }
  for (std::uint32_t c = 0; c < count; ++c) {
    const std::uint32_t k = candidates_[c];
    const int w = std::min(ax1, bin_x1_[k]) - std::max(ax0, bin_x0_[k]) + 1;
    const int h = std::min(ay1, bin_y1_[k]) - std::max(ay0, bin_y0_[k]) + 1;
    edges_.push_back(
        Edge{tile_lights_[begin + a], tile_lights_[begin + k], static_cast<float>(w * h)});
  }
}

}  // namespace antumbra::layering
