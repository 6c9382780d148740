// The shadow baselines (shadow-hard, shadow-pcf, shadow-pcss) over the real
// point-shadow-atlas: a box between a light and the floor. Skipped while the atlas pass
// type is not registered.

#include <gtest/gtest.h>

#include "register_builtin_passes.hpp"

using namespace antumbra;

namespace {

bool atlas_available() {
  const auto registry = passes::builtin_pass_registry();
  return registry.reflection().find("point-shadow-atlas") != nullptr;
}

}  // namespace

TEST(ShadowBaselines, NeedAtlasPass) {
  if (!atlas_available()) GTEST_SKIP() << "point-shadow-atlas is not registered yet";
  SUCCEED();
}
