#pragma once
// glTF 2.0 import (.gltf with external or embedded buffers, and .glb) through tinygltf.
// Every index, offset, stride, count and component type is checked before any byte is
// read, because tinygltf itself does not: a malformed file gives SC03x diagnostics,
// never a crash or an endless recursion. Images are decoded through an ImageCache
// (image_cache.hpp); one that cannot be used leaves its material's factor, with a warning.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

struct GltfImport {
  // One mesh per triangle primitive per node of the default scene (scene 0 when the
  // file names none). Vertices are in the primitive's local space; `transform` is the
  // node's world matrix; `material` indexes `materials`.
  std::vector<Mesh> meshes;
  // glTF materials in file order (factors, textures, alpha mode, double-sidedness;
  // alphaMode BLEND with alpha < 1 -> translucent), then one default material used by
  // primitives without a material.
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what the materials' slots index
  // The first perspective camera met in the default scene's node tree (depth first), in
  // world space; none when the file has none. `far` is 0 where the file leaves it
  // infinite.
  std::optional<Camera> camera;
  // KHR_lights_punctual lights placed by the default scene's nodes, in world space and
  // engine units (docs/technique.md section 6, "Lights from glTF"); several may be
  // directional. Invalid ones are skipped with warning SC045.
  std::vector<PointLight> lights;
};

struct GltfLimits {
  std::size_t max_triangles = 10'000'000;
  std::size_t max_node_visits = 100'000;  // bounds instancing blow-ups
  ImageLimits images;
  // Buffer and image URIs may name files outside the glTF's folder (absolute, or climbing
  // out through ".."): a warning (SC046) instead of an error (docs/robustness.md, "Paths").
  bool allow_outside_paths = false;
};

// Diagnostics carry file = `path` and a JSON Pointer into the glTF (e.g. /accessors/3),
// without line numbers.
// `cache` shares decoded images across loads; without one, this load has its own.
base::Result<GltfImport> load_gltf(const std::string& path, const GltfLimits& limits = {},
                                   ImageCache* cache = nullptr);

}  // namespace antumbra::scene
