// The "zero validation errors" checks of this suite are only worth something when the
// sessions really run with synchronization validation: record a deliberate hazard
// (two transfer writes to one buffer without a barrier) on a session's device and
// expect the layer to report it.

#include <string>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/resources.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

class ValidationCanaryTest : public RenderTest {};

TEST_F(ValidationCanaryTest, SessionsReportSynchronizationHazards) {
  OPEN_SESSION(session, kSmall);
  gpu::Context& context = session->gpu();
  ASSERT_TRUE(context.validation_enabled());
  {
    gpu::Buffer buffer = gpu::Buffer::create(context, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                             gpu::MemoryUsage::gpu_only, "canary");
    context.submit_immediate([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 1u);
      vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 2u);  // WAW, no barrier
    });
  }
  context.wait_idle();
  EXPECT_GT(context.validation_error_count(), 0u)
      << "a write-after-write hazard went unreported: synchronization validation is off";
  bool hazard = false;
  for (const auto& message : context.validation_messages()) {
    hazard = hazard || message.id_name.find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos;
  }
  EXPECT_TRUE(hazard) << validation_report(context);
  context.reset_validation_counts();  // the hazard was the point; TearDown checks the rest
}
