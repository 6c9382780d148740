#pragma once
// Debug views selectable with `render --output`: pass types "layer-view" (lights
// coloured by their shadow layer), "penumbra-view" (penumbra widths in false colour)
// "atlas-view" (shadow faces tiled into a grid) and "cascade-view" (which cascade of
// the sun's shadow map each pixel reads). Reflection in
// debug_views_desc.cpp, runtime in debug_views_pass.cpp, shaders beside them. Each
// writes one rgba8 storage image, so a graph declares them without side effects and
// the compiler culls them unless their image is the output.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

struct LayerViewParams {
  bool dominant = false;  // weighting: attenuation or dominant
  float dim = 0.35f;
  float stripe_width = 4.0f;
  float no_layer_grey = 0.5f;
};

class LayerViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<LayerViewParams>& param_table();
  explicit LayerViewPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  LayerViewParams params_;
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

struct PenumbraViewParams {
  float max_width = 0.25f;
};

class PenumbraViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<PenumbraViewParams>& param_table();
  explicit PenumbraViewPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  PenumbraViewParams params_;
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

struct AtlasViewParams {
  std::uint32_t first_face = 0;
  std::uint32_t faces = 24;
  std::uint32_t columns = 0;  // 0: chosen from the view's aspect
  bool pool = false;          // a paged atlas's layers as they lie, pages tinted by owner
};

class AtlasViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<AtlasViewParams>& param_table();
  explicit AtlasViewPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  AtlasViewParams params_;
  bool linearise_ = false;
  bool page_tables_ = false;  // `pageTables` bound (with shadowData): faces through their tables
  bool pool_view_ = false;    // `pool` over a paged atlas: its layers, pages by owner
  ComputePipeline compute_;
  ComputePipeline owners_pipeline_;  // atlas_pool_owners.comp
  gpu::Buffer owners_;               // per pool page (kAtlasViewOwners)
  void record_owners(fgvk::ExecuteContext& context, std::uint32_t layers, std::uint32_t side);
  std::vector<std::string> shader_files_;
};

struct CascadeViewParams {
  bool show_shadow = true;
  float dim = 0.4f;
};

class CascadeViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<CascadeViewParams>& param_table();
  explicit CascadeViewPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  CascadeViewParams params_;
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
