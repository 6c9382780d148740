#pragma once
// The JSON scene format (version 1) and its loader. Problems in the file come back as
// located diagnostics (codes in base/diagnostic_codes.hpp, codes::scene), never as exceptions or
// crashes.
//
// Format summary (every key not listed is an error, with a "did you mean"):
//   version   (required) integer, 1
//   name      string
//   camera    (required) {position, target (required vec3), up [0,1,0], fovY 60 (0,180),
//             near 0.1 (> 0), far 200 (> near)}
//   ambient   vec3 >= 0, default [0,0,0]
//   materials {name: {albedo [0.8]*3, roughness 0.5, metallic 0, translucent false,
//             transmittance [r,g,b,a] in [0,1] (default albedo with a = 0.5)}}
//             the implicit material "default" (index 0) may be redefined
//   objects   [{primitive: box|plane|cylinder|sphere|arch, <shape keys>} |
//              {gltf: "path relative to this file (.gltf/.glb)"} |
//              {scene: "another scene file, relative to this file"}]
//             common keys: name, position, rotation (degrees about X, then Y, then Z),
//             scale (number or vec3, > 0), material, repeat ({count, offset} or an array
//             of up to 3 of them: copies on a grid, each offset in world space)
//             box {size}, plane {size: [x, z]}, cylinder {radius, height, segments},
//             sphere {radius, segments, rings}, arch {width, height, depth, pierWidth,
//             crown, style: round|pointed, segments}
//             scene: its meshes, its materials (named "<path>#<name>") and its point and
//             spot lights (named "<object name>/<light>[i,j]", ranges scaled with the
//             object; its camera, ambient and sun are not imported); a file may not
//             instance itself, directly or through others
//   lights    [{name (required, unique), type "point", position (required), color [1,1,1],
//             intensity 1, range 10 (> 0), size 0.2 (>= 0), castsShadows true}]
//             Scene::lights holds these first, in file order, then instanced scenes' lights.
//   dynamic   [NAME | {object: NAME, motion: {offset [0,0,0], spin 0 (degrees per
//             period), period 240 (frames, > 0)}}]: objects (by "name", or
//             "<primitive>#<index>" when unnamed) that may move after loading; their
//             meshes are uploaded apart and drawn over cached static shadow faces. A
//             motion swings and turns them as a function of the frame index.

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

// Reads, parses and validates a scene file; glTF paths resolve against its folder. A
// .gltf or .glb path opens the model as the whole scene (gltf_scene.hpp).
// `images` shares decoded textures across loads (reloads); without it each load
// decodes its own.
base::Result<Scene> load_scene_file(const std::string& path, ImageCache* images = nullptr);
// Validates an already parsed document; glTF paths resolve against document.file()'s folder.
base::Result<Scene> parse_scene(const base::JsonDocument& document, ImageCache* images = nullptr);
// Convenience for tests and the editor: parse JSON text reported as coming from `file`.
base::Result<Scene> parse_scene_text(std::string_view text, const std::string& file,
                                     ImageCache* images = nullptr);

}  // namespace antumbra::scene
