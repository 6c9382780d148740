#include "common/lighting_reflection.hpp"
#include "common/ports.hpp"
#include "shadow_reference_pass.hpp"

namespace antumbra::passes {

fg::PassDesc ShadowReferencePass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "shadow-reference";
  desc.description =
      "Ground truth for the quality tests: the lighting of deferred-lighting / tiled-lighting "
      "with each point or spot light a sphere of radius `size` whose visibility is averaged "
      "over `samples` hard shadow-map tests from points spread over the sphere (spherical "
      "Fibonacci set), and the directional sun a disc of angular radius `size` degrees "
      "averaged over `samples` directions (Fibonacci disc), each with its own orthographic "
      "map around the visible receivers. Translucent casters tint instead of blocking: each "
      "sample's visibility is 0 behind an opaque caster, else the product of the tints of "
      "the panes in between, so shadows are coloured; a pane does not tint its own lit "
      "surface. With visibility `rays` each sample is a ray through a BVH of the scene's "
      "triangles instead of a map (sphere lights then sampled evenly over the solid angle "
      "they subtend), with no bias or texel size. Slow, offline, deterministic; "
      "samplesPerFrame spreads the samples over frames.";
  desc.ports = lighting_ports();
  desc.ports.back().description = "Linear HDR radiance with reference soft shadows.";
  desc.ports.push_back({.name = port::kPenumbraCount,
                        .direction = PortDirection::output,
                        .access = Access::storage_write,
                        .stage = Stage::compute,
                        .formats = {Format::r32f},
                        .optional = true,
                        .size_group = "screen",
                        .description =
                            "Per pixel, the number of lights whose samples disagree: the fraction "
                            "no opaque caster blocks, or the fraction nothing blocks or tints, is "
                            "strictly between 0.02 and 0.98 (>= 1: penumbra, >= 2: overlapping "
                            "penumbrae; a pane's uniform coloured shadow is no penumbra)."});
  desc.params = param_table().descs();
  return desc;
}

namespace {

// How each sample's visibility is found, and over how many frames (rays, progressive).
fg::ParamTable<ShadowReferenceParams> add_visibility_params(
    fg::ParamTable<ShadowReferenceParams> table) {
  table
      .choice(
          {.name = "visibility",
           .type = fg::ParamType::enumeration,
           .default_value = "shadowMaps",
           .choices = {"shadowMaps", "rays"},
           .description = "How each sample's visibility is found. shadowMaps: a hard test against "
                          "cube faces rendered from the sample point (faceSize, nearPlane, the "
                          "biases and normalOffset apply). rays: a ray from the pixel to the "
                          "sample point through a BVH of the scene's triangles, with no map, bias "
                          "or texel size (rayOffset applies); the same casters block, cut and "
                          "tint."},
          &ShadowReferenceParams::visibility, {0u, 1u})
      .add({.name = "rayOffset",
            .type = fg::ParamType::number,
            .default_value = 0.002,
            .min = 0.0,
            .max = 1.0,
            .description = "visibility rays: metres along the receiver's normal the rays "
                           "start from (above the depth buffer's reconstruction error)."},
           &ShadowReferenceParams::ray_offset)
      .add({.name = "samplesPerFrame",
            .type = fg::ParamType::integer,
            .default_value = 0,
            .min = 0.0,
            .max = 4096.0,
            .description =
                "Samples per light a frame takes, light batch after light batch, until "
                "`samples` are in (0: all of them in the frame the view, lights or geometry "
                "change). Until then the output is the average of the samples so far, "
                "without the lights of batches not begun, and note SHR002 says how far it "
                "is; the finished image is the same as with 0."},
           &ShadowReferenceParams::samples_per_frame);
  return table;
}

}  // namespace

const fg::ParamTable<ShadowReferenceParams>& ShadowReferencePass::param_table() {
  static const auto kTable =
      add_visibility_params(
          fg::ParamTable<ShadowReferenceParams>()
              .add({.name = "samples",
                    .type = fg::ParamType::integer,
                    .default_value = 256,
                    .min = 16.0,
                    .max = 4096.0,
                    .description = "Shadow-map samples per light (points on its sphere; the sun: "
                                   "directions over its disc)."},
                   &ShadowReferenceParams::samples)
              .add({.name = "faceSize",
                    .type = fg::ParamType::integer,
                    .default_value = 512,
                    .min = 32.0,
                    .max = 4096.0,
                    .description = "Texels per side of each sample's cube faces."},
                   &ShadowReferenceParams::face_size)
              .add({.name = "lightsPerBatch",
                    .type = fg::ParamType::integer,
                    .default_value = 16,
                    .min = 1.0,
                    .max = 64.0,
                    .description =
                        "Lights whose faces are rendered together (6 depth layers each)."},
                   &ShadowReferenceParams::lights_per_batch)
              .choice(
                  {.name = "weighting",
                   .type = fg::ParamType::enumeration,
                   .default_value = "projected",
                   .choices = {"projected", "uniform"},
                   .description =
                       "projected: samples weighted by cos / distance^2 towards the receiver "
                       "(the visible fraction of the solid angle of the light's disc); uniform: "
                       "plain average of the sphere samples."},
                  &ShadowReferenceParams::weighting, {0u, 1u})
              .add({.name = "nearPlane",
                    .type = fg::ParamType::number,
                    .default_value = 0.02,
                    .min = 0.001,
                    .max = 1.0,
                    .description = "Near plane of every sample's faces in metres."},
                   &ShadowReferenceParams::near_plane)
              .add({.name = "normalOffset",
                    .type = fg::ParamType::number,
                    .default_value = 1.0,
                    .min = 0.0,
                    .max = 8.0,
                    .description = "Receiver offset along its normal, in face texels."},
                   &ShadowReferenceParams::normal_offset)
              .add({.name = "depthBias",
                    .type = fg::ParamType::number,
                    .default_value = 0.0,
                    .min = 0.0,
                    .max = 0.1,
                    .description = "Constant bias of the depth comparison (face depth units)."},
                   &ShadowReferenceParams::depth_bias)
              .add({.name = "rasterBias",
                    .type = fg::ParamType::number,
                    .default_value = 1.0,
                    .min = 0.0,
                    .max = 1000.0,
                    .description = "Constant raster depth bias of the face rendering."},
                   &ShadowReferenceParams::raster_bias)
              .add({.name = "slopeBias",
                    .type = fg::ParamType::number,
                    .default_value = 1.0,
                    .min = 0.0,
                    .max = 16.0,
                    .description = "Slope-scaled raster depth bias of the face rendering."},
                   &ShadowReferenceParams::slope_bias)
              .add({.name = "cullFaces",
                    .type = fg::ParamType::boolean,
                    .default_value = true,
                    .description =
                        "Skip faces whose frustum misses the camera's (never changes the image)."},
                   &ShadowReferenceParams::cull_faces))
          .include(&ShadowReferenceParams::lighting, lighting_param_table());
  return kTable;
}

}  // namespace antumbra::passes
