#pragma once
// What a pass type publishes about itself: ports and parameters. Validation, the
// JSON Schema, the editor's property panels and the barrier plan all derive from
// this, so a pass never has to say the same thing twice.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

// Formats a graph resource can have. Names in JSON are given by to_string().
enum class Format : std::uint8_t {
  undefined,
  r8,
  rg8,
  rgba8,
  rgba8_srgb,
  bgra8,
  bgra8_srgb,
  r16f,
  rg16f,
  rgba16f,
  r32f,
  rg32f,
  rgba32f,
  r32ui,
  rg32ui,
  rgba32ui,
  r11g11b10f,
  d16,
  d32f,
  d24s8,
};

std::string_view to_string(Format format);
std::optional<Format> parse_format(std::string_view name);
const std::vector<Format>& all_formats();
bool is_depth_format(Format format);
std::uint32_t bytes_per_texel(Format format);

enum class ResourceKind : std::uint8_t { image, buffer };
std::string_view to_string(ResourceKind kind);

// How a pass touches a resource through a port.
enum class Access : std::uint8_t {
  none,                // not yet touched (initial state)
  sampled,             // read through a sampler
  storage_read,        // imageLoad / readonly SSBO
  storage_write,       // imageStore / writeonly SSBO; previous contents not needed
  storage_read_write,  // read-modify-write
  color_attachment,    // written as a colour attachment
  depth_attachment,    // depth written (and tested)
  depth_read,          // depth tested, not written
  uniform_read,        // uniform buffer
  // Copied from: by a pass, or after the frame by the host (the output: `render`'s
  // read-back, the editor's blit into its own swapchain image, which it presents).
  transfer_src,
  transfer_dst,
};
std::string_view to_string(Access access);
bool is_write(Access access);
bool is_read(Access access);

// Where in the pipeline the access happens, for the barrier plan.
// `shader`: any shader stage, for a port whose reader (fragment or compute) is chosen at
// run time from what the graph binds.
enum class Stage : std::uint8_t {
  none,
  vertex,
  fragment,
  compute,
  graphics,
  transfer,
  host,
  shader
};
std::string_view to_string(Stage stage);

enum class PortDirection : std::uint8_t { input, output };

// A port's name as a compile-time constant. A pass names its ports through such constants
// in its description and in its runtime, and the runtime's binding lookups
// (fgvk::PassBindings) accept nothing else, so a misspelt port is a build error instead
// of an unbound resource at run time (docs/adding-a-pass.md).
class PortId {
 public:
  constexpr explicit PortId(std::string_view name) : name_(name) {}
  [[nodiscard]] constexpr std::string_view name() const { return name_; }
  // So that a description can say `.name = port::kDepth`.
  operator std::string() const { return std::string(name_); }  // NOLINT(*-explicit-*)
  friend constexpr bool operator==(PortId a, PortId b) { return a.name_ == b.name_; }

 private:
  std::string_view name_;
};

// How the image bound to a port must relate to the image bound to another port of the same
// pass: what a description would otherwise say in words ("same resolution as the output",
// "the atlas size divided by an integer factor"), declared so that the compiler checks it
// (FG092, located at this port's binding, naming both resources and their sizes) and
// docs/passes.md prints it from the same declaration. A contract whose other port is
// unbound holds trivially (docs/architecture.md, section 3).
enum class SizeRelation : std::uint8_t {
  same,                // equal extents
  same_or_half,        // equal, or half on both axes (floor(other / 2))
  fraction,            // floor(other / n) on both axes for one integer n >= 1
  exact_fraction,      // other / n exactly, one integer n >= 1 on both axes
  exact_fraction_even  // other / n exactly, n = 1 or even
};
std::string_view to_string(SizeRelation relation);  // "same size as", for messages
std::string_view json_key(SizeRelation relation);   // "same", for the JSON reference

struct SizeContract {
  std::string port;  // the other port, of the same pass
  SizeRelation relation = SizeRelation::same;
};

enum class LayerRelation : std::uint8_t {
  same,     // as many array layers as the other port's image
  at_least  // at least as many
};
std::string_view to_string(LayerRelation relation);
std::string_view json_key(LayerRelation relation);

struct LayerContract {
  std::string port;
  LayerRelation relation = LayerRelation::same;
};

struct PortDesc {
  std::string name;
  PortDirection direction = PortDirection::input;
  ResourceKind kind = ResourceKind::image;
  Access access = Access::sampled;
  Stage stage = Stage::fragment;
  std::vector<Format> formats;  // accepted formats; empty = any
  std::uint32_t min_layers = 1;
  std::uint32_t max_layers = 1;  // 0 = unlimited
  bool optional = false;
  // Ports in the same group must have equal sizes (attachments rendered together).
  std::string size_group;
  // This port's image against another port's (see SizeContract, LayerContract).
  std::optional<SizeContract> size_of;
  std::optional<LayerContract> layers_of;
  std::string description;
};

// The contract as a phrase for references and messages, e.g. "same size as `shadow`",
// "at least `penumbra`'s layers"; empty when the port declares none.
std::string describe_size_contract(const PortDesc& port);
std::string describe_layer_contract(const PortDesc& port);

enum class ParamType : std::uint8_t { boolean, integer, number, enumeration, string };
std::string_view to_string(ParamType type);

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's noexcept move is reported.
struct ParamDesc {
  std::string name;
  ParamType type = ParamType::number;
  Json default_value;
  std::optional<double> min;
  std::optional<double> max;
  std::vector<std::string> choices;  // for enumeration
  std::string description;
};

struct GraphDesc;
struct Plan;
struct PlanPass;
struct PassInstanceDesc;

// What the compiler knows of the device it compiles for (RenderSession fills it; validate
// and plan compile for no device). Vulkan-free: what a pass may choose by.
struct DeviceTraits {
  std::string name;             // e.g. "NVIDIA H200", "llvmpipe (LLVM 15.0.6, 256 bits)"
  bool cpu = false;             // a CPU implementation (lavapipe)
  std::uint32_t vendor_id = 0;  // PCI vendor (0x10DE NVIDIA)
};

// Replaces parameters whose value is chosen for the device or the graph around the pass
// (an "auto" value) before anything else is compiled, so that the barriers follow the
// choice. `device` is null when compiling for no device. Returns one line per choice made,
// saying what and why (reported as notes, FG076).
// Passes write it against their typed parameters (ParamTable::resolve).
using ParamResolveFn = std::function<std::vector<std::string>(
    PassInstanceDesc& pass, const GraphDesc& graph, const DeviceTraits* device)>;

// A check that spans passes and so cannot be expressed by one port or parameter (for
// example: a layer cap larger than the layer storage downstream can hold). Runs on
// the compiled plan; reports located diagnostics through graph.document.
// Passes write it against their typed parameters (ParamTable::check).
using PassCheck = std::function<void(const PlanPass& pass, const Plan& plan, const GraphDesc& graph,
                                     Diagnostics& diagnostics)>;

// How a pass touches a port under given parameters, where a parameter changes it (a
// compute path that fills a depth attachment by copies instead of rendering it). The
// barrier plan and the resource's usage follow what this returns.
struct PortUse {
  Access access = Access::none;
  Stage stage = Stage::none;
};
// `params` holds every parameter, defaults filled in; `format` is the bound resource's
// (undefined for a buffer or an unbound port). Nothing: the port's declared use.
// Passes write it against their typed parameters (ParamTable::port_use).
using PortUseFn =
    std::function<std::optional<PortUse>(const PortDesc& port, const Json& params, Format format)>;

struct PassDesc {
  std::string type;  // registry name, e.g. "gbuffer"
  std::string description;
  std::vector<PortDesc> ports;
  std::vector<ParamDesc> params;
  bool side_effects = false;  // never culled (e.g. writes to the host)
  PassCheck check = nullptr;
  PortUseFn port_use = nullptr;
  ParamResolveFn resolve = nullptr;

  // The port's access and stage under parameter `values` and the bound resource's format
  // (port_use, else as declared).
  [[nodiscard]] PortUse use_of(const PortDesc& port, const Json& values,
                               Format format = Format::undefined) const;
  [[nodiscard]] const PortDesc* find_port(std::string_view name) const;
  [[nodiscard]] const ParamDesc* find_param(std::string_view name) const;
};

}  // namespace antumbra::fg
