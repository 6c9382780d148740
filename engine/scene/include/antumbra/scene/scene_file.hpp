#pragma once
// The JSON scene format (version 1) and its loader. Problems in the file come back as
// located diagnostics (codes in base/diagnostic_codes.hpp, codes::scene), never as exceptions or
// crashes.
//
// The format's keys, types, defaults and ranges are declared once, in scene_format.hpp's
// table: the parser's key checks come from it, and so do docs/scenes.md and
// data/schema/scene.schema.json (every key not listed is an error, with a "did you mean").

#include <cstddef>
#include <string>
#include <string_view>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

inline constexpr int kSceneFormatVersion = 1;
// "repeat" may not expand one object into more copies than this.
inline constexpr int kMaxRepeatCopies = 4096;
// Scene instancing may not make a scene larger than this (copies of copies multiply).
inline constexpr std::size_t kMaxSceneTriangles = std::size_t{1} << 26;
// The most lights a scene may have, its own and those its objects bring: what the renderer's
// light buffer and shadow data hold (every one of them may cast its shadow). More are
// refused at the entry or object that passes the limit (SC028), before they are copied.
inline constexpr std::size_t kMaxSceneLights = 4096;

// What a scene file may make the loader read (docs/robustness.md, "Paths").
struct SceneFileOptions {
  // A "gltf" or "scene" path (and a glTF's buffer or image URI) that is absolute or climbs
  // out of its file's folder through "..": a warning (SC046) instead of an error. The
  // command line's --allow-outside-paths.
  bool allow_outside_paths = false;
};

// Reads, parses and validates a scene file; glTF paths resolve against its folder. A
// .gltf or .glb path opens the model as the whole scene (gltf_scene.hpp).
// `images` shares decoded textures across loads (reloads); without it each load
// decodes its own.
base::Result<Scene> load_scene_file(const std::string& path, ImageCache* images = nullptr,
                                    const SceneFileOptions& options = {});
// Validates an already parsed document; glTF paths resolve against document.file()'s folder.
base::Result<Scene> parse_scene(const base::JsonDocument& document, ImageCache* images = nullptr,
                                const SceneFileOptions& options = {});
// Convenience for tests and the editor: parse JSON text reported as coming from `file`.
base::Result<Scene> parse_scene_text(std::string_view text, const std::string& file,
                                     ImageCache* images = nullptr,
                                     const SceneFileOptions& options = {});

}  // namespace antumbra::scene
