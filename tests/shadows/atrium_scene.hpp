#pragma once
// The atrium (data/scenes/atrium.json) as every shadow test loads it: a failed load throws
// with the loader's diagnostics, so a broken scene file fails the test that needed it.

#include <stdexcept>
#include <string>

#include "antumbra/scene/scene_file.hpp"

namespace antumbra::test {

inline scene::Scene atrium_scene() {
  auto loaded =
      scene::load_scene_file(std::string(ANTUMBRA_TEST_SOURCE_DIR) + "/data/scenes/atrium.json");
  if (!loaded.ok()) throw std::runtime_error(loaded.diagnostics().to_text());
  return std::move(loaded.value());
}

}  // namespace antumbra::test
