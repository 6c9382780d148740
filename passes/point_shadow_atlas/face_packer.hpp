#pragma once
// Where the atlas's face records keep their texels (docs/technique.md, "Packed faces"),
// Vulkan-free: each face is a square of its light's face size in one atlas layer, and faces
// smaller than a layer share layers. A layer holds squares of one size only, on a grid
// (its size class, taken when its first square is placed and given up when its last one
// goes), so finding room is a scan of that class's layers and nothing fragments inside
// a layer. A record keeps its square from frame to frame while its size holds, so the
// faces cached there stay valid; the planner decides sizes (and gives a light smaller
// squares when the atlas is full).

#include <cstdint>
#include <optional>
#include <vector>

#include "common/shadow_data.hpp"

namespace antumbra::passes {

struct PackerStats {
  std::uint32_t layers_used = 0;  // layers holding at least one square
  std::uint64_t texels = 0;       // texels of the squares placed
};

class FacePacker {
 public:
  // An empty atlas of `layers` layers of `layer_size`^2 texels, and `records` records;
  // `share` off: one square per layer, at its origin (a rasteriser that cannot keep a face
  // inside its square).
  void reset(std::uint32_t layers, std::uint32_t layer_size, std::uint32_t records,
             bool share = true);
  [[nodiscard]] bool shares() const { return share_; }

  // The square record `record` holds, if any, and its size.
  [[nodiscard]] std::optional<FacePlace> place_of(std::uint32_t record) const;
  [[nodiscard]] std::uint32_t size_of(std::uint32_t record) const;
  // Gives up the record's square (no-op without one).
  void release(std::uint32_t record);
  // A square of `size` texels (a power of two up to the layer size, or the layer size
  // itself) for a record that holds none: the lowest free cell of the lowest layer of that
  // size class, else the lowest empty layer; nullopt when the atlas has no room.
  std::optional<FacePlace> place(std::uint32_t record, std::uint32_t size);

  // Squares of `size` one layer holds.
  [[nodiscard]] std::uint32_t squares_per_layer(std::uint32_t size) const {
    return cells_per_side(size) * cells_per_side(size);
  }

  // The smallest square a layer of `layer_size` can hold (cells are named in
  // ANTUMBRA_FACE_CELL_BITS bits per side), and whether `size` is one the packer takes.
  [[nodiscard]] static std::uint32_t smallest(std::uint32_t layer_size);
  [[nodiscard]] static bool valid_size(std::uint32_t size, std::uint32_t layer_size);

  // Of records [0, records) (no others hold a square: a planner's records past the last
  // light's are released).
  [[nodiscard]] PackerStats stats(std::uint32_t records = ~0u) const;
  [[nodiscard]] std::uint32_t layer_size() const { return layer_size_; }
  [[nodiscard]] std::uint32_t records() const {
    return static_cast<std::uint32_t>(records_.size());
  }

 private:
  [[nodiscard]] std::uint32_t cells_per_side(std::uint32_t size) const {
    return share_ ? layer_size_ / size : 1u;
  }
  struct Layer {
    std::uint32_t size = 0;  // the class: its squares' size; 0 while empty
    std::uint32_t used = 0;  // squares placed
    std::vector<bool> cells;
  };
  struct Record {
    bool placed = false;
    FacePlace place;
    std::uint32_t size = 0;
  };
  std::uint32_t layer_size_ = 0;
  bool share_ = true;
  std::vector<Layer> layers_;
  std::vector<Record> records_;
};

}  // namespace antumbra::passes
