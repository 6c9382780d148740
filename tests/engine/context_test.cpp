#include <gtest/gtest.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/resources.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, ContextWithValidationHasRequiredFeatures) {
  EXPECT_TRUE(ctx().validation_enabled());
  EXPECT_NE(ctx().device(), VK_NULL_HANDLE);
  EXPECT_NE(ctx().queue(), VK_NULL_HANDLE);
  EXPECT_GE(ctx().properties().apiVersion, VK_API_VERSION_1_2);
  EXPECT_GE(ctx().api_version(), VK_API_VERSION_1_2);
  EXPECT_FALSE(ctx().device_name().empty());
  EXPECT_NE(ctx().ext().cmd_push_descriptor_set, nullptr);
  EXPECT_FALSE(ctx().devices().empty());
}

// Contexts alive at once share the binding of the Vulkan 1.3 commands (vk_commands.hpp):
// one on a device used as 1.2 beside one on a 1.3 device is refused, with the reason.
TEST_F(GpuTest, AContextOfTheOtherVulkanVersionIsRefusedWhileOneLives) {
  if (ctx().api_version() < VK_API_VERSION_1_3) {
    GTEST_SKIP() << "the device is used as Vulkan 1.2 (ANTUMBRA_VULKAN_API or RenderDoc)";
  }
  ContextOptions options = testing::validation_options();
  options.max_api_version = VK_API_VERSION_1_2;
  try {
    const Context other(options);
    ADD_FAILURE() << "a Vulkan 1.2 Context was created beside a 1.3 one";
  } catch (const DeviceSelectionError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot be used while a Context on a Vulkan 1.3"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(GpuTest, SubmitsSignalTheTimeline) {
  const std::uint64_t before = ctx().last_submitted_value();
  ctx().submit_immediate([](VkCommandBuffer) {});
  EXPECT_EQ(ctx().last_submitted_value(), before + 1);
  EXPECT_GE(ctx().completed_value(), before + 1);
}

// The test hook of docs/robustness.md, "Device loss": the chosen submission fails as on a
// lost device, and so does every later one.
TEST_F(GpuTest, AnInjectedDeviceLossFailsThatSubmissionAndEveryLaterOne) {
  ContextOptions options = testing::validation_options();
  options.lose_device_at_submission = 2;
  Context lossy(options);
  lossy.submit_immediate([](VkCommandBuffer) {});
  EXPECT_FALSE(lossy.device_lost());
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      lossy.submit_immediate([](VkCommandBuffer) {});
      ADD_FAILURE() << "submission " << attempt + 2 << " reached the queue";
    } catch (const VulkanError& e) {
      EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
      EXPECT_NE(std::string(e.what()).find("device loss injected at submission 2"),
                std::string::npos)
          << e.what();
    }
    EXPECT_TRUE(lossy.device_lost());
  }
  EXPECT_EQ(lossy.validation_error_count(), 0u);
}

TEST_F(GpuTest, ValidationErrorsAreCounted) {
  // A deliberate misuse proves the counter works (and is then reset for TearDown).
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;  // VUID-VkBufferCreateInfo-size-00912
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  const VkResult result = vkCreateBuffer(ctx().device(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS && buffer) vkDestroyBuffer(ctx().device(), buffer, nullptr);
  EXPECT_GE(ctx().validation_error_count(), 1u);
  EXPECT_FALSE(ctx().validation_messages().empty());
  ctx().reset_validation_counts();
}

TEST_F(GpuTest, SynchronizationValidationIsOn) {
  // Two transfer writes to one buffer with no barrier between them: a WAW hazard that
  // only synchronization validation reports.
  Buffer buffer = Buffer::create(ctx(), 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 MemoryUsage::gpu_only, "test.hazard");
  ctx().submit_immediate([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, buffer, 0, 256, 1u);
    vkCmdFillBuffer(cmd, buffer, 0, 256, 2u);
  });
  bool hazard = false;
  for (const auto& message : ctx().validation_messages()) {
    hazard = hazard || message.id_name.find("SYNC-HAZARD") != std::string::npos;
  }
  EXPECT_TRUE(hazard) << testing::format_validation_messages(ctx());
  ctx().reset_validation_counts();
}

TEST(DeviceSelection, CpuSelectsLavapipe) {
  try {
    Context context(testing::validation_options("cpu"));
    EXPECT_TRUE(context.is_cpu());
    context.wait_idle();
    testing::expect_no_validation_errors(context);
  } catch (const NoVulkanDeviceError& error) {
    testing::report_missing_device(error.what());
    GTEST_SKIP() << error.what();
  } catch (const DeviceSelectionError& error) {
    testing::report_missing_device(std::string("no CPU device (lavapipe): ") + error.what());
    GTEST_SKIP() << "no CPU device here: " << error.what();
  }
}

TEST(DeviceSelection, UnknownNameListsDevices) {
  try {
    Context context(testing::validation_options("nonexistent-name"));
    FAIL() << "expected DeviceSelectionError";
  } catch (const NoVulkanDeviceError& error) {
    testing::report_missing_device(error.what());
    GTEST_SKIP() << error.what();
  } catch (const DeviceSelectionError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("nonexistent-name"), std::string::npos) << message;
    EXPECT_NE(message.find("[0] "), std::string::npos) << message;
    EXPECT_NE(message.find("Vulkan 1."), std::string::npos) << message;
  }
}

TEST(DeviceSelection, IndexOutOfRange) {
  try {
    Context context(testing::validation_options("99"));
    FAIL() << "expected DeviceSelectionError";
  } catch (const NoVulkanDeviceError& error) {
    testing::report_missing_device(error.what());
    GTEST_SKIP() << error.what();
  } catch (const DeviceSelectionError& error) {
    EXPECT_NE(std::string(error.what()).find("out of range"), std::string::npos) << error.what();
  }
}

TEST(DeviceSelection, IndexZeroAndNameSubstringWork) {
  try {
    Context by_index(testing::validation_options("0"));
    const std::string& name = by_index.device_name();
    Context by_name(testing::validation_options(name.substr(0, 4)));
    EXPECT_FALSE(by_name.device_name().empty());
  } catch (const NoVulkanDeviceError& error) {
    testing::report_missing_device(error.what());
    GTEST_SKIP() << error.what();
  }
}

}  // namespace
}  // namespace antumbra::gpu
