#include "host_tint_pass.hpp"

#include <memory>

#include "antumbra/gpu/pipelines.hpp"
#include "shaders/host_tint/host_tint_interface.h"

namespace host_example {

namespace fg = antumbra::fg;
namespace fgvk = antumbra::fgvk;
namespace gpu = antumbra::gpu;
namespace passes = antumbra::passes;
namespace shared = antumbra::shared;

fg::PassDesc HostTintPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = kType;
  desc.description = "A host's pass type (tests/host_pass): a tinted copy of an image.";
  desc.ports = {
      {.name = port::kSource,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::rgba8, Format::rgba16f},
       .size_group = "screen",
       .description = "The image to tint."},
      {.name = port::kTinted,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba8},
       .size_group = "screen",
       .description = "The tinted copy."},
  };
  desc.params = param_table().descs();
  return desc;
}

const fg::ParamTable<HostTintParams>& HostTintPass::param_table() {
  const auto component = [](const char* name, double value, const char* what) {
    return fg::ParamDesc{.name = name,
                         .type = fg::ParamType::number,
                         .default_value = value,
                         .min = 0.0,
                         .max = 1.0,
                         .description = std::string("The tint's ") + what + " component."};
  };
  static const auto kTable =
      fg::ParamTable<HostTintParams>()
          .add(component("tintRed", 1.0, "red"), &HostTintParams::tint_red)
          .add(component("tintGreen", 0.5, "green"), &HostTintParams::tint_green)
          .add(component("tintBlue", 0.25, "blue"), &HostTintParams::tint_blue)
          .add({.name = "strength",
                .type = fg::ParamType::number,
                .default_value = 0.5,
                .min = 0.0,
                .max = 1.0,
                .description = "How much of the tint applies: 0 copies the image, 1 multiplies "
                               "it by the tint."},
               &HostTintParams::strength);
  return kTable;
}

HostTintPass::HostTintPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {
}

void HostTintPass::prepare(fgvk::PrepareContext& context) {
  constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
  shader_files_.clear();
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.combined_image_sampler(shared::kHostTintSource, kCompute)
      .storage_image(shared::kHostTintTarget, kCompute);
  // Searched in the session's shader folders: passes/ first, then the host's.
  const passes::Shader shader = passes::load_shader(context, kShader, shader_files_);
  pipeline_ =
      passes::build_compute_pipeline(context, shader, bindings, sizeof(shared::HostTintPush));
}

void HostTintPass::execute(fgvk::ExecuteContext& context) {
  const auto& source = context.bindings.required_image(port::kSource);
  const auto& tinted = context.bindings.required_image(port::kTinted);
  const VkCommandBuffer cmd = context.cmd;
  const shared::HostTintPush constants{
      {params_.tint_red, params_.tint_green, params_.tint_blue, params_.strength}};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline);
  gpu::PushDescriptors()
      .combined_image_sampler(shared::kHostTintSource, source.view, context.samplers.nearest_clamp,
                              source.layout)
      .storage_image(shared::kHostTintTarget, tinted.view, tinted.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout);
  vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants,
                     &constants);
  passes::dispatch_groups(cmd, tinted.extent, ANTUMBRA_IMAGE_GROUP);
}

namespace {

std::unique_ptr<fgvk::Pass> make_host_tint(const fg::PlanPass& pass) {
  return std::make_unique<HostTintPass>(pass);
}

}  // namespace

void register_host_passes(fgvk::PassRegistry& registry) {
  registry.add(HostTintPass::describe(), &make_host_tint);
}

}  // namespace host_example
