#pragma once
// A glTF model opened as the whole scene (`render --scene model.glb`, `edit --scene
// model.glb`): a scene file that holds the model, the file's camera (or one framing the
// model) and a default light rig, kept beside the model as "<model file>.scene.json".
// Viewing never writes anything; the editor saves its edits (camera, lights) to that
// scene file, never into the glTF, and later opens of the model read them from it.

#include <filesystem>
#include <string>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/scene/image_cache.hpp"

namespace antumbra::scene {

// .gltf or .glb, in any letter case.
bool is_gltf_file(const std::filesystem::path& path);

// "<dir>/<model file name>.scene.json": where a model's scene settings live.
std::filesystem::path gltf_scene_file(const std::filesystem::path& model);

// The scene file's text for `model` (its diagnostics are the model's): version 1, the
// model as the one object (named "model": its lights become "model/<light>"), the model's
// camera or a framing one, a dim ambient and, when the model has no lights of its own
// (KHR_lights_punctual), a three-light rig (key, fill, rim) sized to the model's bounds. The text
// refers to the model by file name (the scene file lives beside it).
// `allow_outside_paths`: GltfLimits::allow_outside_paths of the model's load.
base::Result<std::string> gltf_scene_text(const std::filesystem::path& model,
                                          ImageCache* images = nullptr,
                                          bool allow_outside_paths = false);

}  // namespace antumbra::scene
