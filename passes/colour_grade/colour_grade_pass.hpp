#pragma once
// Pass type "colour-grade": an HDR -> HDR grade (exposure, tint, saturation, contrast)
// between the lighting and tonemap. Reflection in colour_grade_desc.cpp, runtime in
// colour_grade_pass.cpp, the shader beside them.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

// The defaults are the identity: a graph gains the pass without its picture changing.
struct ColourGradeParams {
  float exposure = 0.0f;  // EV stops
  float saturation = 1.0f;
  float contrast = 1.0f;
  float tint_red = 1.0f;
  float tint_green = 1.0f;
  float tint_blue = 1.0f;
};

class ColourGradePass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<ColourGradeParams>& param_table();
  explicit ColourGradePass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  ColourGradeParams params_;
  ComputePipeline pipeline_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
