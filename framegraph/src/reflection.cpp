// Names and properties of formats, accesses and stages; lookups on PassDesc.
#include "antumbra/fg/reflection.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace antumbra::fg {
namespace {

struct FormatInfo {
  Format format;
  std::string_view name;
  std::uint32_t bytes;
};

// One table, so names, sizes and the list of formats cannot drift apart.
constexpr std::array<FormatInfo, 20> kFormats{{
    {Format::undefined, "undefined", 0},
    {Format::r8, "r8", 1},
    {Format::rg8, "rg8", 2},
    {Format::rgba8, "rgba8", 4},
    {Format::rgba8_srgb, "rgba8_srgb", 4},
    {Format::bgra8, "bgra8", 4},
    {Format::bgra8_srgb, "bgra8_srgb", 4},
    {Format::r16f, "r16f", 2},
    {Format::rg16f, "rg16f", 4},
    {Format::rgba16f, "rgba16f", 8},
    {Format::r32f, "r32f", 4},
    {Format::rg32f, "rg32f", 8},
    {Format::rgba32f, "rgba32f", 16},
    {Format::r32ui, "r32ui", 4},
    {Format::rg32ui, "rg32ui", 8},
    {Format::rgba32ui, "rgba32ui", 16},
    {Format::r11g11b10f, "r11g11b10f", 4},
    {Format::d16, "d16", 2},
    {Format::d32f, "d32f", 4},
    {Format::d24s8, "d24s8", 4},
}};

const FormatInfo& info(Format format) {
  const auto index = static_cast<std::size_t>(format);
  return index < kFormats.size() ? kFormats[index] : kFormats[0];
}

}  // namespace

std::string_view to_string(Format format) {
  return info(format).name;
}

std::optional<Format> parse_format(std::string_view name) {
  for (const auto& f : kFormats) {
    if (f.format != Format::undefined && f.name == name) return f.format;
  }
  return std::nullopt;
}

const std::vector<Format>& all_formats() {
  static const std::vector<Format> kAll = [] {
    std::vector<Format> out;
    for (const auto& f : kFormats) {
      if (f.format != Format::undefined) out.push_back(f.format);
    }
    return out;
  }();
  return kAll;
}

bool is_depth_format(Format format) {
  return format == Format::d16 || format == Format::d32f || format == Format::d24s8;
}

std::uint32_t bytes_per_texel(Format format) {
  return info(format).bytes;
}

std::string_view to_string(ResourceKind kind) {
  return kind == ResourceKind::image ? "image" : "buffer";
}

namespace {

// One row per relation, in enumerator order: the phrase of references and messages, and
// the key of the JSON reference.
struct RelationWords {
  std::string_view phrase;
  std::string_view key;
};
constexpr std::array<RelationWords, 5> kSizeRelations{{
    {"same size as", "same"},
    {"same size as, or half of,", "sameOrHalf"},
    {"an integer fraction of", "fraction"},
    {"an exact integer fraction of", "exactFraction"},
    {"an exact fraction (1 or even) of", "exactFractionEven"},
}};
constexpr std::array<RelationWords, 2> kLayerRelations{{
    {"as many layers as", "same"},
    {"at least as many layers as", "atLeast"},
}};

}  // namespace

std::string_view to_string(SizeRelation relation) {
  return kSizeRelations.at(static_cast<std::size_t>(relation)).phrase;
}

std::string_view to_string(LayerRelation relation) {
  return kLayerRelations.at(static_cast<std::size_t>(relation)).phrase;
}

std::string_view json_key(SizeRelation relation) {
  return kSizeRelations.at(static_cast<std::size_t>(relation)).key;
}

std::string_view json_key(LayerRelation relation) {
  return kLayerRelations.at(static_cast<std::size_t>(relation)).key;
}

std::string describe_size_contract(const PortDesc& port) {
  if (!port.size_of) return {};
  return std::string(to_string(port.size_of->relation)) + " `" + port.size_of->port + "`";
}

std::string describe_layer_contract(const PortDesc& port) {
  if (!port.layers_of) return {};
  return std::string(to_string(port.layers_of->relation)) + " `" + port.layers_of->port + "`";
}

std::string_view to_string(Access access) {
  switch (access) {
    case Access::none:
      return "none";
    case Access::sampled:
      return "sampled";
    case Access::storage_read:
      return "storage_read";
    case Access::storage_write:
      return "storage_write";
    case Access::storage_read_write:
      return "storage_read_write";
    case Access::color_attachment:
      return "color_attachment";
    case Access::depth_attachment:
      return "depth_attachment";
    case Access::depth_read:
      return "depth_read";
    case Access::uniform_read:
      return "uniform_read";
    case Access::transfer_src:
      return "transfer_src";
    case Access::transfer_dst:
      return "transfer_dst";
  }
  return "none";
}

bool is_write(Access access) {
  switch (access) {
    case Access::storage_write:
    case Access::storage_read_write:
    case Access::color_attachment:
    case Access::depth_attachment:
    case Access::transfer_dst:
      return true;
    default:
      return false;
  }
}

bool is_read(Access access) {
  switch (access) {
    case Access::sampled:
    case Access::storage_read:
    case Access::storage_read_write:
    case Access::depth_read:
    case Access::uniform_read:
    case Access::transfer_src:
      return true;
    default:
      return false;
  }
}

std::string_view to_string(Stage stage) {
  switch (stage) {
    case Stage::none:
      return "none";
    case Stage::vertex:
      return "vertex";
    case Stage::fragment:
      return "fragment";
    case Stage::compute:
      return "compute";
    case Stage::graphics:
      return "graphics";
    case Stage::transfer:
      return "transfer";
    case Stage::host:
      return "host";
    case Stage::shader:
      return "shader";
  }
  return "none";
}

std::string_view to_string(ParamType type) {
  switch (type) {
    case ParamType::boolean:
      return "boolean";
    case ParamType::integer:
      return "integer";
    case ParamType::number:
      return "number";
    case ParamType::enumeration:
      return "enumeration";
    case ParamType::string:
      return "string";
  }
  return "number";
}

PortUse PassDesc::use_of(const PortDesc& port, const Json& values, Format format) const {
  if (port_use != nullptr) {
    if (auto use = port_use(port, values, format)) return *use;
  }
  return {port.access, port.stage};
}

const PortDesc* PassDesc::find_port(std::string_view name) const {
  auto it =
      std::find_if(ports.begin(), ports.end(), [&](const PortDesc& p) { return p.name == name; });
  return it == ports.end() ? nullptr : &*it;
}

const ParamDesc* PassDesc::find_param(std::string_view name) const {
  auto it = std::find_if(params.begin(), params.end(),
                         [&](const ParamDesc& p) { return p.name == name; });
  return it == params.end() ? nullptr : &*it;
}

}  // namespace antumbra::fg
