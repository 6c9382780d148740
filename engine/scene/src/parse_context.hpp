#pragma once
// State shared by the parts of the scene parser (scene_parser.cpp, object_parser.cpp).

#include <filesystem>
#include <string>

#include "antumbra/scene/scene.hpp"
#include "json_reader.hpp"

namespace antumbra::scene::detail {

struct ParseContext {
  JsonReader& reader;
  Scene& scene;
  std::filesystem::path base_dir;  // glTF paths are relative to the scene file
};

// Fills ctx.scene.meshes (and glTF materials) from the "objects" array.
void parse_objects(ParseContext& ctx, const Json& objects, const std::string& pointer);

}  // namespace antumbra::scene::detail
