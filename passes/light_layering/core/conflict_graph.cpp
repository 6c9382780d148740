#include "antumbra/layering/conflict_graph.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace antumbra::layering {
namespace {

// Cell spans larger than this per axis make a light "big": it is tested against every
// other light instead of being inserted into hundreds of cells (e.g. a huge area light).
constexpr int kMaxCellSpan = 6;
// Keeps floor(p / cell) inside int range for absurd coordinates.
constexpr float kMaxCellCoord = 1.0e6f;

// A light with a non-positive or NaN range lights nothing and conflicts with nobody. The
// grid and the brute-force reference share this predicate so that they agree exactly.
bool lights_something(const LightSphere& light) {
  return light.range > 0.0f;
}

bool spheres_conflict(const LightSphere& a, const LightSphere& b) {
  if (!lights_something(a) || !lights_something(b)) return false;
  const glm::vec3 d = a.position - b.position;
  const float reach = a.range + b.range;
  return glm::dot(d, d) < reach * reach;
}

int cell_coord(float p, float inv_cell) {
  return static_cast<int>(std::floor(std::clamp(p * inv_cell, -kMaxCellCoord, kMaxCellCoord)));
}

std::uint32_t hash_cell(glm::ivec3 c, std::uint32_t mask) {
  // Teschner et al. 2003 spatial hash primes.
  const auto h = (static_cast<std::uint32_t>(c.x) * 73856093u) ^
                 (static_cast<std::uint32_t>(c.y) * 19349663u) ^
                 (static_cast<std::uint32_t>(c.z) * 83492791u);
  return h & mask;
}

// Cell coordinates are clamped to +-kMaxCellCoord < 2^20, so 21 bits each pack into 64.
std::uint64_t cell_key(glm::ivec3 c) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 21) - 1;
  return ((static_cast<std::uint64_t>(c.x) & kMask) << 42) |
         ((static_cast<std::uint64_t>(c.y) & kMask) << 21) |
         (static_cast<std::uint64_t>(c.z) & kMask);
}

std::size_t bucket_count_for(std::size_t entries) {
  return std::bit_ceil(std::max<std::size_t>(entries * 2, 16));
}

// Inlined into the pair loops; sphere_overlap_volume is the public name.
inline float overlap_volume(glm::vec3 pa, float ra, glm::vec3 pb, float rb) {
  const float d = glm::length(pa - pb);
  if (!(ra > 0.0f) || !(rb > 0.0f) || d >= ra + rb) return 0.0f;
  const float r_min = std::min(ra, rb);
  if (d <= std::abs(ra - rb))
    return 4.0f / 3.0f * std::numbers::pi_v<float> * r_min * r_min * r_min;
  // Lens volume: pi (R+r-d)^2 (d^2 + 2d(R+r) - 3(R-r)^2) / (12 d).
  const float lens = ra + rb - d;
  const float diff = ra - rb;
  return std::numbers::pi_v<float> * lens * lens *
         (d * d + 2.0f * d * (ra + rb) - 3.0f * diff * diff) / (12.0f * d);
}

// Cell edge = 1.5 mean lit diameters: a typical sphere covers 1..2 cells per axis. The
// pair test is branch-free and cheap, so fewer, fuller cells win: at 1024 lights of mean
// degree 8 the build took 265 / 233 / 172 / 171 us for 0.75 / 1 / 1.5 / 2 diameters.
float grid_cell_size(std::span<const LightSphere> lights) {
  double range_sum = 0.0;
  std::uint32_t finite = 0;
  for (const LightSphere& l : lights) {
    if (lights_something(l) && std::isfinite(l.range)) {
      range_sum += l.range;
      ++finite;
    }
  }
  return finite > 0 ? static_cast<float>(3.0 * range_sum / finite) : 1.0f;
}

// Calls fn for every cell of the inclusive span lo..hi (none when hi < lo).
template <class Fn>
void for_each_cell(glm::ivec3 lo, glm::ivec3 hi, Fn&& fn) {
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) fn(glm::ivec3(x, y, z));
}

}  // namespace

float sphere_overlap_volume(glm::vec3 pa, float ra, glm::vec3 pb, float rb) {
  return overlap_volume(pa, ra, pb, rb);
}

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

const ConflictGraph& GraphBuilder::build_world_sphere(std::span<const LightSphere> lights) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  edges_.clear();
  big_lights_.clear();
  const float cell = grid_cell_size(lights);
  const float inv_cell = 1.0f / cell;
  const std::size_t entry_count = assign_cells(lights, inv_cell);
  const std::size_t buckets = sort_into_buckets(lights, entry_count);
  collect_cell_pairs(buckets);
  collect_big_light_pairs(lights);
  finish_graph(n);
  return graph_;
}

// Each light's span of grid cells; a light too big for the grid goes to big_lights_.
// Returns the number of (light, cell) entries.
std::size_t GraphBuilder::assign_cells(std::span<const LightSphere> lights, float inv_cell) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  cell_min_.resize(n);
  cell_max_.resize(n);
  std::size_t entry_count = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const LightSphere& l = lights[i];
    cell_min_[i] = glm::ivec3(0);
    cell_max_[i] = glm::ivec3(-1);  // empty span: not in the grid
    if (!lights_something(l)) continue;
    const glm::ivec3 lo(cell_coord(l.position.x - l.range, inv_cell),
                        cell_coord(l.position.y - l.range, inv_cell),
                        cell_coord(l.position.z - l.range, inv_cell));
    const glm::ivec3 hi(cell_coord(l.position.x + l.range, inv_cell),
                        cell_coord(l.position.y + l.range, inv_cell),
                        cell_coord(l.position.z + l.range, inv_cell));
    const glm::ivec3 span = hi - lo + 1;
    if (!std::isfinite(l.range) || span.x > kMaxCellSpan || span.y > kMaxCellSpan ||
        span.z > kMaxCellSpan) {
      big_lights_.push_back(i);
      continue;
    }
    cell_min_[i] = lo;
    cell_max_[i] = hi;
    entry_count += static_cast<std::size_t>(span.x * span.y * span.z);
  }
  return entry_count;
}

// Counting sort of (light, cell) entries into hash buckets: no per-cell allocation.
// Returns the number of buckets.
std::size_t GraphBuilder::sort_into_buckets(std::span<const LightSphere> lights,
                                            std::size_t entry_count) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  const std::size_t buckets = bucket_count_for(entry_count);
  const auto mask = static_cast<std::uint32_t>(buckets - 1);
  bucket_start_.assign(buckets + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    for_each_cell(cell_min_[i], cell_max_[i],
                  [&](glm::ivec3 c) { ++bucket_start_[hash_cell(c, mask) + 1]; });
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
  entries_.resize(entry_count);
  for (std::uint32_t i = 0; i < n; ++i) {
    const LightSphere& l = lights[i];
    for_each_cell(cell_min_[i], cell_max_[i], [&](glm::ivec3 c) {
      // first: bit k set when this is the light's first cell along axis k. Two lights that
      // share cell c have c as their first shared cell iff (first_a | first_b) == 7.
      const glm::ivec3 lo = cell_min_[i];
      const auto first = static_cast<std::uint32_t>((c.x == lo.x ? 1 : 0) | (c.y == lo.y ? 2 : 0) |
                                                    (c.z == lo.z ? 4 : 0));
      entries_[bucket_start_[hash_cell(c, mask)]++] =
          CellEntry{l.position, l.range, cell_key(c), i, first};
    });
  }
  // The fill advanced each start to the next bucket's start; shift back.
  for (std::size_t b = buckets; b > 0; --b) bucket_start_[b] = bucket_start_[b - 1];
  bucket_start_[0] = 0;
  return buckets;
}

void GraphBuilder::collect_cell_pairs(std::size_t buckets) {
  std::uint32_t largest_bucket = 0;
  for (std::size_t b = 0; b < buckets; ++b)
    largest_bucket = std::max(largest_bucket, bucket_start_[b + 1] - bucket_start_[b]);
  if (candidates_.size() < largest_bucket) candidates_.resize(largest_bucket);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::uint32_t end = bucket_start_[b + 1];
    for (std::uint32_t x = bucket_start_[b]; x < end; ++x) {
      const CellEntry& ex = entries_[x];
      // Branch-free filter into a candidate list: the tests fail or pass unpredictably, and
      // a mispredicted branch per pair cost more than the test itself. A pair passes when
      // both entries are the same cell (hash collisions share buckets), that cell is the
      // pair's first shared cell (so the pair is reported once) and the spheres intersect.
      std::uint32_t count = 0;
      for (std::uint32_t y = x + 1; y < end; ++y) {
        const CellEntry& ey = entries_[y];
        const glm::vec3 d = ex.position - ey.position;
        const float reach = ex.range + ey.range;
        const bool hit =
            (ex.key == ey.key) & ((ex.first | ey.first) == 7u) & (glm::dot(d, d) < reach * reach);
        candidates_[count] = y;
        count += hit ? 1u : 0u;
      }
      for (std::uint32_t k = 0; k < count; ++k) {
        const CellEntry& ey = entries_[candidates_[k]];
        edges_.push_back(
            Edge{ex.light, ey.light, overlap_volume(ex.position, ex.range, ey.position, ey.range)});
      }
    }
  }
}

// Big lights are tested against every other light.
void GraphBuilder::collect_big_light_pairs(std::span<const LightSphere> lights) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  for (std::size_t k = 0; k < big_lights_.size(); ++k) {
    const std::uint32_t i = big_lights_[k];
    for (std::uint32_t j = 0; j < n; ++j) {
      if (j == i) continue;
      // A pair of two big lights is found once, from the earlier one in big_lights_.
      if (std::find(big_lights_.begin(), big_lights_.begin() + static_cast<long>(k), j) !=
          big_lights_.begin() + static_cast<long>(k))
        continue;
      if (!spheres_conflict(lights[i], lights[j])) continue;
      const float w = std::isfinite(lights[i].range) && std::isfinite(lights[j].range)
                          ? overlap_volume(lights[i].position, lights[i].range, lights[j].position,
                                           lights[j].range)
                          : 1.0f;
      edges_.push_back(Edge{i, j, w});
    }
  }
}

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

void GraphBuilder::collect_tile_pairs(const TileBins& bins) {
  for (int by = 0; by < bins.count.y; ++by) {
    for (int bx = 0; bx < bins.count.x; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * bins.count.x + bx;
      for (std::uint32_t x = bucket_start_[b]; x < bucket_start_[b + 1]; ++x) {
        const glm::ivec4 ra = tile_range_[tile_lights_[x]];
        for (std::uint32_t y = x + 1; y < bucket_start_[b + 1]; ++y) {
          const glm::ivec4 rb = tile_range_[tile_lights_[y]];
          const glm::ivec4 o(std::max(ra.x, rb.x), std::max(ra.y, rb.y), std::min(ra.z, rb.z),
                             std::min(ra.w, rb.w));
          if (o.z < o.x || o.w < o.y) continue;
          // Report the pair only from the bin holding the first shared tile.
          if (bins.range_of(o).x != bx || bins.range_of(o).y != by) continue;
          edges_.push_back(Edge{tile_lights_[x], tile_lights_[y],
                                static_cast<float>((o.z - o.x + 1) * (o.w - o.y + 1))});
        }
      }
    }
  }
}

void GraphBuilder::finish_graph(std::size_t vertex_count) {
  const auto n = static_cast<std::uint32_t>(vertex_count);
  // Unsorted adjacency first, then a transpose pass, which emits every list in ascending
  // order without a sort (the graph is symmetric, so the transpose is the graph itself).
  scratch_offsets_.assign(n + 1, 0);
  for (const Edge& e : edges_) {
    ++scratch_offsets_[e.a + 1];
    ++scratch_offsets_[e.b + 1];
  }
  for (std::uint32_t v = 0; v < n; ++v) scratch_offsets_[v + 1] += scratch_offsets_[v];
  const std::size_t arcs = edges_.size() * 2;
  scratch_neighbours_.resize(arcs);
  scratch_weights_.resize(arcs);
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
  for (const Edge& e : edges_) {
    scratch_neighbours_[graph_.offsets[e.a]] = e.b;
    scratch_weights_[graph_.offsets[e.a]++] = e.weight;
    scratch_neighbours_[graph_.offsets[e.b]] = e.a;
    scratch_weights_[graph_.offsets[e.b]++] = e.weight;
  }
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
  graph_.neighbours.resize(arcs);
  graph_.weights.resize(arcs);
  for (std::uint32_t u = 0; u < n; ++u) {
    for (std::uint32_t k = scratch_offsets_[u]; k < scratch_offsets_[u + 1]; ++k) {
      const std::uint32_t v = scratch_neighbours_[k];
      graph_.neighbours[graph_.offsets[v]] = u;
      graph_.weights[graph_.offsets[v]++] = scratch_weights_[k];
    }
  }
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
}

ConflictGraph build_world_sphere_graph(std::span<const LightSphere> lights) {
  GraphBuilder builder;
  return builder.build_world_sphere(lights);
}

ConflictGraph build_screen_tile_graph(std::span<const ScreenRect> rects, const TileParams& params) {
  GraphBuilder builder;
  return builder.build_screen_tile(rects, params);
}

ConflictGraph build_world_sphere_graph_brute_force(std::span<const LightSphere> lights) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  const auto n = static_cast<std::uint32_t>(lights.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (spheres_conflict(lights[i], lights[j])) edges.emplace_back(i, j);
  return ConflictGraph::from_edges(n, edges);
}

std::optional<ScreenRect> project_sphere_rect(glm::vec3 centre, float radius, const glm::mat4& view,
                                              const glm::mat4& proj, glm::ivec2 viewport) {
  if (!(radius > 0.0f) || viewport.x <= 0 || viewport.y <= 0) return std::nullopt;
  const glm::vec4 c = view * glm::vec4(centre, 1.0f);
  const float depth = -c.z;  // distance in front of the camera plane
  const glm::vec2 size(viewport);
  if (depth + radius <= 0.0f) return std::nullopt;
  if (depth <= radius) return ScreenRect{glm::vec2(0.0f), size};
  // Tangent planes through the camera containing the other view axis: slope s = a / depth
  // solves (a - s*depth)^2 = r^2 (1 + s^2), i.e. s = (a*depth +- r*t) / (depth^2 - r^2).
  const float denom = depth * depth - radius * radius;
  auto axis_bounds = [&](float a, float scale, float shift, float extent) {
    const float t = std::sqrt(a * a + denom);
    const float s0 = (a * depth - radius * t) / denom;
    const float s1 = (a * depth + radius * t) / denom;
    const float p0 = (scale * s0 - shift + 1.0f) * 0.5f * extent;
    const float p1 = (scale * s1 - shift + 1.0f) * 0.5f * extent;
    return glm::vec2(std::min(p0, p1), std::max(p0, p1));
  };
  const glm::vec2 x = axis_bounds(c.x, proj[0][0], proj[2][0], size.x);
  const glm::vec2 y = axis_bounds(c.y, proj[1][1], proj[2][1], size.y);
  ScreenRect rect{glm::max(glm::vec2(x.x, y.x), glm::vec2(0.0f)),
                  glm::min(glm::vec2(x.y, y.y), size)};
  if (rect.empty()) return std::nullopt;
  return rect;
}

}  // namespace antumbra::layering
