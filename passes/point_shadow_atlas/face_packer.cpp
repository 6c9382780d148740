#include "face_packer.hpp"

#include <algorithm>
#include <bit>
#include <cassert>

namespace antumbra::passes {

void FacePacker::reset(std::uint32_t layers, std::uint32_t layer_size, std::uint32_t records,
                       bool share) {
  assert(layers <= kMaxAtlasLayers);
  layer_size_ = layer_size;
  share_ = share;
  layers_.assign(layers, Layer{});
  records_.assign(records, Record{});
}

std::optional<FacePlace> FacePacker::place_of(std::uint32_t record) const {
  if (record >= records_.size() || !records_[record].placed) return std::nullopt;
  return records_[record].place;
}

std::uint32_t FacePacker::size_of(std::uint32_t record) const {
  return record < records_.size() && records_[record].placed ? records_[record].size : 0u;
}

void FacePacker::release(std::uint32_t record) {
  if (record >= records_.size() || !records_[record].placed) return;
  Record& r = records_[record];
  Layer& layer = layers_[r.place.layer];
  const std::uint32_t per_side = cells_per_side(layer.size);
  layer.cells[r.place.cell.y * per_side + r.place.cell.x] = false;
  if (--layer.used == 0) layer = Layer{};
  r = Record{};
}

std::uint32_t FacePacker::smallest(std::uint32_t layer_size) {
  return std::max(1u, (layer_size + kMaxFaceCells - 1) / kMaxFaceCells);
}

bool FacePacker::valid_size(std::uint32_t size, std::uint32_t layer_size) {
  if (size == layer_size) return size > 0;
  return size > 0 && size < layer_size && std::has_single_bit(size) && size >= smallest(layer_size);
}

std::optional<FacePlace> FacePacker::place(std::uint32_t record, std::uint32_t size) {
  assert(record < records_.size() && !records_[record].placed);
  if (!valid_size(size, layer_size_)) return std::nullopt;
  const std::uint32_t per_side = cells_per_side(size);
  const auto take = [&](std::uint32_t index, Layer& layer) -> std::optional<FacePlace> {
    const auto free = std::find(layer.cells.begin(), layer.cells.end(), false);
    if (free == layer.cells.end()) return std::nullopt;
    *free = true;
    ++layer.used;
    const auto cell = static_cast<std::uint32_t>(free - layer.cells.begin());
    const FacePlace place{.layer = index, .cell = {cell % per_side, cell / per_side}};
    records_[record] = {.placed = true, .place = place, .size = size};
    return place;
  };
  for (std::uint32_t i = 0; i < layers_.size(); ++i) {
    if (layers_[i].size != size || layers_[i].used == per_side * per_side) continue;
    if (auto place = take(i, layers_[i])) return place;
  }
  for (std::uint32_t i = 0; i < layers_.size(); ++i) {
    if (layers_[i].size != 0) continue;
    layers_[i].size = size;
    layers_[i].cells.assign(std::size_t{per_side} * per_side, false);
    return take(i, layers_[i]);
  }
  return std::nullopt;
}

PackerStats FacePacker::stats(std::uint32_t records) const {
  PackerStats s;
  for (const Layer& layer : layers_) s.layers_used += layer.used > 0 ? 1u : 0u;
  const std::size_t end = std::min<std::size_t>(records, records_.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (records_[i].placed) s.texels += std::uint64_t{records_[i].size} * records_[i].size;
  }
  return s;
}

}  // namespace antumbra::passes
