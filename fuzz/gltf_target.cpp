// The glTF target: the bytes written to a .glb (when they start with the binary magic) or
// .gltf file in the scratch folder and imported by load_gltf, as a scene file's import
// would: schema checks, tinygltf, accessors, materials and their images (data URIs and
// buffer views; relative URIs name files that do not exist).
#include <fstream>
#include <string_view>

#include "antumbra/scene/gltf_loader.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {

void gltf(Bytes data) {
  const bool binary =
      data.size() >= 4 && std::string_view(reinterpret_cast<const char*>(data.data()), 4) == "glTF";
  const auto path = scratch_folder() / (binary ? "fuzz.glb" : "fuzz.gltf");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data.data()),
              static_cast<std::streamsize>(data.size()));
    if (!out) __builtin_trap();  // the harness, not the input: the run means nothing
  }
  const auto imported = scene::load_gltf(path.string());
  (void)imported.diagnostics().to_text();
}

}  // namespace antumbra::fuzz
