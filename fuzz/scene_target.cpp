// The scene target: a scene file's JSON as load_scene_file meets it, parsed, validated and
// instanced (repeats, imports, dynamic objects). The file lies in the scratch folder, so
// the glTF and scene files it names by relative path do not exist.
#include <string_view>

#include "antumbra/scene/image_cache.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {

void scene(Bytes data) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  scene::ImageCache images;
  const auto parsed =
      scene::parse_scene_text(text, (scratch_folder() / "fuzz.json").string(), &images);
  (void)parsed.diagnostics().to_text();
}

}  // namespace antumbra::fuzz
