#pragma once
// Shared support for GPU tests: a fixture that creates a Context with validation and
// synchronization validation on, skips when no Vulkan device exists, and fails the
// test when the validation layer reported any error. Other suites include this file
// (target_include_directories on tests/engine).

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "antumbra/gpu/context.hpp"
#include "device_requirement.hpp"

namespace antumbra::gpu::testing {

inline ContextOptions validation_options(std::string device = "auto") {
  ContextOptions options;
  options.app_name = "antumbra-tests";
  options.validation = true;
  options.sync_validation = true;
  options.device = std::move(device);
  return options;
}

inline std::string format_validation_messages(const Context& context) {
  std::ostringstream out;
  for (const auto& message : context.validation_messages()) {
    out << "\n  [" << message.id_name << "] " << message.text;
  }
  return out.str();
}

// Non-fatal: reports every kept message when errors were counted.
inline void expect_no_validation_errors(const Context& context) {
  EXPECT_EQ(context.validation_error_count(), 0u)
      << "validation errors:" << format_validation_messages(context);
}

// A fresh directory under the system temp dir, removed at destruction.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("antumbra-test-" + std::to_string(random()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

class GpuTest : public ::testing::Test {
 protected:
  // Override to pick another device or options.
  virtual ContextOptions options() const { return validation_options(); }

  void SetUp() override {
    try {
      context_ = std::make_unique<Context>(options());
    } catch (const NoVulkanDeviceError& error) {
      report_missing_device(error.what());
      GTEST_SKIP() << "no Vulkan device: " << error.what();
    }
  }
  void TearDown() override {
    if (!context_) return;
    context_->wait_idle();
    expect_no_validation_errors(*context_);
    context_.reset();
  }
  Context& ctx() { return *context_; }

  std::unique_ptr<Context> context_;
};

}  // namespace antumbra::gpu::testing
