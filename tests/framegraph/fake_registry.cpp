#include "fake_registry.hpp"

namespace antumbra::fg::testing {
namespace {

PortDesc port(std::string name, PortDirection direction, Access access, Stage stage,
              std::vector<Format> formats, std::string description = {}) {
  PortDesc p;
  p.name = std::move(name);
  p.direction = direction;
  p.access = access;
  p.stage = stage;
  p.formats = std::move(formats);
  p.description = std::move(description);
  return p;
}

ParamDesc number(std::string name, double def, double lo, double hi, std::string description = {}) {
  ParamDesc p;
  p.name = std::move(name);
  p.type = ParamType::number;
  p.default_value = def;
  p.min = lo;
  p.max = hi;
  p.description = std::move(description);
  return p;
}

ParamDesc integer(std::string name, int def, int lo, int hi) {
  ParamDesc p = number(std::move(name), def, lo, hi);
  p.type = ParamType::integer;
  p.default_value = def;
  return p;
}

constexpr auto kIn = PortDirection::input;
constexpr auto kOut = PortDirection::output;

// The built-in deferred chain they are modelled on: G-buffer, lighting, tone mapping.
void add_deferred_passes(Registry& registry) {
  PassDesc gbuffer{
      "gbuffer", "Rasterises the scene into depth, normals and albedo.", {}, {}, false};
  gbuffer.ports = {
      port("depth", kOut, Access::depth_attachment, Stage::graphics, {Format::d32f, Format::d16},
           "scene depth"),
      port("normal", kOut, Access::color_attachment, Stage::graphics, {Format::rgba16f},
           "view-space normals"),
      port("albedo", kOut, Access::color_attachment, Stage::graphics, {Format::rgba8},
           "base colour"),
  };
  for (auto& p : gbuffer.ports) p.size_group = "gbuffer";
  ParamDesc cull;
  cull.name = "cullBackfaces";
  cull.type = ParamType::boolean;
  cull.default_value = true;
  gbuffer.params = {cull};
  registry.add(std::move(gbuffer));

  PassDesc lighting{"deferred-lighting", "Shades the G-buffer.", {}, {}, false};
  lighting.ports = {
      port("depth", kIn, Access::sampled, Stage::fragment, {Format::d32f, Format::d16}),
      port("normal", kIn, Access::sampled, Stage::fragment, {Format::rgba16f}),
      port("albedo", kIn, Access::sampled, Stage::fragment, {Format::rgba8}),
      port("lights", kIn, Access::storage_read, Stage::fragment, {}),
      port("hdr", kOut, Access::color_attachment, Stage::graphics,
           {Format::rgba16f, Format::rgba32f}),
  };
  lighting.ports[3].kind = ResourceKind::buffer;
  lighting.ports[3].optional = true;
  lighting.params = {number("exposure", 1.0, 0.0, 16.0, "linear exposure multiplier"),
                     number("ambient", 0.03, 0.0, 1.0, "constant ambient term")};
  registry.add(std::move(lighting));

  PassDesc tonemap{"tonemap", "Maps HDR to display range.", {}, {}, false};
  tonemap.ports = {
      port("hdr", kIn, Access::sampled, Stage::fragment, {Format::rgba16f, Format::rgba32f}),
      port("ldr", kOut, Access::color_attachment, Stage::graphics,
           {Format::rgba8, Format::rgba8_srgb}),
  };
  ParamDesc op;
  op.name = "operator";
  op.type = ParamType::enumeration;
  op.default_value = "aces";
  op.choices = {"aces", "reinhard", "linear"};
  op.description = "tone curve";
  tonemap.params = {op, number("exposure", 1.0, 0.0, 16.0)};
  registry.add(std::move(tonemap));
}

// Image-to-image passes: optional inputs (a generator), fan-out to two outputs.
void add_image_passes(Registry& registry) {
  PassDesc blur{"blur", "Separable compute blur.", {}, {}, false};
  blur.ports = {port("src", kIn, Access::sampled, Stage::compute, {}),
                port("dst", kOut, Access::storage_write, Stage::compute, {})};
  blur.params = {integer("radius", 4, 1, 32)};
  registry.add(std::move(blur));

  PassDesc composite{"composite", "Blends two images.", {}, {}, false};
  composite.ports = {port("a", kIn, Access::sampled, Stage::fragment, {}),
                     port("b", kIn, Access::sampled, Stage::fragment, {}),
                     port("out", kOut, Access::color_attachment, Stage::graphics, {})};
  composite.ports[0].optional = true;  // with no inputs it is a generator
  composite.ports[1].optional = true;
  registry.add(std::move(composite));

  PassDesc split{"split", "Writes two copies of an image.", {}, {}, false};
  split.ports = {port("src", kIn, Access::sampled, Stage::fragment, {}),
                 port("a", kOut, Access::color_attachment, Stage::graphics, {}),
                 port("b", kOut, Access::color_attachment, Stage::graphics, {})};
  registry.add(std::move(split));
}

// The shapes the layer-count and buffer checks need: a layered depth output, a buffer
// output.
void add_shadow_and_light_passes(Registry& registry) {
  PassDesc atlas{"shadow-atlas", "Renders point-light faces into a layered atlas.", {}, {}, false};
  atlas.ports = {
      port("atlas", kOut, Access::depth_attachment, Stage::graphics, {Format::d16, Format::d32f})};
  atlas.ports[0].min_layers = 6;
  atlas.ports[0].max_layers = 0;
  atlas.params = {integer("faceSize", 512, 64, 4096)};
  registry.add(std::move(atlas));

  PassDesc lights{"light-list", "Writes the light buffer.", {}, {}, false};
  lights.ports = {port("lights", kOut, Access::storage_write, Stage::compute, {})};
  lights.ports[0].kind = ResourceKind::buffer;
  ParamDesc label;
  label.name = "label";
  label.type = ParamType::string;
  label.default_value = "lights";
  lights.params = {label};
  registry.add(std::move(lights));
}

// Culling keeps it for its side effects alone: it writes no resource.
void add_side_effect_passes(Registry& registry) {
  PassDesc readback{"readback", "Copies an image to the host.", {}, {}, true};
  readback.ports = {port("src", kIn, Access::transfer_src, Stage::transfer, {})};
  registry.add(std::move(readback));
}

}  // namespace

Registry make_fake_registry() {
  Registry registry;
  add_deferred_passes(registry);
  add_image_passes(registry);
  add_shadow_and_light_passes(registry);
  add_side_effect_passes(registry);
  return registry;
}

}  // namespace antumbra::fg::testing
