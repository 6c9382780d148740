#pragma once
// glTF materials, textures, samplers and images to scene::Material / scene::Texture
// (docs/technique.md, "Materials"). Images are decoded once per ImageCache; an image
// that is missing, corrupt or too large leaves its slot empty with a warning, so the
// material falls back to its factors. A texture index that names nothing is an error.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/scene/image_cache.hpp"
#include "gltf_accessors.hpp"

namespace antumbra::scene::detail {

struct GltfMaterialInput {
  const tinygltf::Model& model;
  std::string path;  // the glTF file, for cache keys and messages
  // The encoded bytes tinygltf read for each image (empty where it could not).
  const std::vector<std::vector<std::uint8_t>>& image_bytes;
  ImageCache& cache;
  ImageLimits limits;
};

// Appends the file's materials (in file order) and the textures they use.
bool convert_materials(const GltfMaterialInput& input, std::vector<Material>& materials,
                       std::vector<Texture>& textures, GltfIssue& issue,
                       std::vector<GltfIssue>& warnings);

}  // namespace antumbra::scene::detail
