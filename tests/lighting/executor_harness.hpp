#pragma once
// An executor over the built-in registry plus test-only pass types (synthetic producers
// of resources whose real passes are tested elsewhere), with validation + sync
// validation on; a test fails on any validation error (checked at TearDown).

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fgvk/executor.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/frame_loop.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "common/gpu_scene.hpp"
#include "device_requirement.hpp"
#include "register_builtin_passes.hpp"
#include "render_test_support.hpp"

namespace antumbra::lighting_testing {

using TestPassTypes = std::vector<std::pair<fg::PassDesc, fgvk::PassFactory>>;

class ExecutorTest : public render_testing::RenderTest {
 protected:
  // False (and the test skipped by the caller's `if (!open(...)) GTEST_SKIP()`) without a
  // Vulkan device.
  bool open(scene::Scene scene, const TestPassTypes& extra) {
    gpu::ContextOptions options;
    options.validation = true;
    try {
      gpu_ = std::make_unique<gpu::Context>(options);
    } catch (const gpu::NoVulkanDeviceError& error) {
      gpu::testing::report_missing_device(error.what());
      skip_reason_ = std::string("no Vulkan device: ") + error.what();
      return false;
    }
    const auto shader_root = render_testing::source_dir() / "passes";
    shaders_ = std::make_unique<gpu::ShaderCompiler>(gpu::ShaderCompilerOptions{{shader_root}});
    registry_ = std::make_unique<fgvk::PassRegistry>(passes::builtin_pass_registry());
    for (const auto& [desc, factory] : extra) registry_->add(desc, factory);
    executor_ = std::make_unique<fgvk::Executor>(*gpu_, *shaders_, *registry_,
                                                 std::vector<std::filesystem::path>{shader_root});
    frames_ = std::make_unique<gpu::FrameLoop>(*gpu_);
    scene_ = std::move(scene);
    gpu_scene_ = std::make_unique<passes::GpuScene>(*gpu_, scene_, frames_->frames_in_flight());
    return true;
  }

  void TearDown() override {
    if (gpu_) {
      gpu_->wait_idle();
      EXPECT_EQ(gpu_->validation_error_count(), 0u) << render_testing::validation_report(*gpu_);
    }
    gpu_scene_.reset();
    frames_.reset();
    executor_.reset();
    RenderTest::TearDown();
  }

  // Compiles and loads the graph (throws with its diagnostics when invalid), renders one
  // frame and reads back `resource`.
  gpu::HostImage render(const std::string& graph_text, VkExtent2D viewport,
                        const std::string& resource = "hdr") {
    fg::CompileOptions options;
    options.viewport = {viewport.width, viewport.height};
    options.footprint = executor_->footprint_fn();
    auto plan = fg::compile_text(graph_text, "test.json", registry_->reflection(), options);
    if (!plan.ok()) throw std::runtime_error(plan.diagnostics().to_text());
    executor_->load(std::move(plan.value()));
    VkCommandBuffer cmd = frames_->begin_frame();
    const auto frame =
        gpu_scene_->update(cmd, frames_->slot(), scene_, viewport, frames_->frame_number());
    executor_->record(cmd, frame);
    frames_->end_frame();
    frames_->wait_all();
    return gpu::read_image(*gpu_, *executor_->gpu_image(resource),
                           executor_->image(resource)->layout);
  }

  std::unique_ptr<gpu::Context> gpu_;
  std::unique_ptr<gpu::ShaderCompiler> shaders_;
  std::unique_ptr<fgvk::PassRegistry> registry_;
  std::unique_ptr<fgvk::Executor> executor_;
  std::unique_ptr<gpu::FrameLoop> frames_;
  scene::Scene scene_;
  std::unique_ptr<passes::GpuScene> gpu_scene_;
};

}  // namespace antumbra::lighting_testing
