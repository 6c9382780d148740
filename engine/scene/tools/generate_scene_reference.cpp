// Build step: writes the JSON Schema of scene files and docs/scenes.md from the scene
// format's table (scene_format.hpp). The build keeps them under <build>/generated;
// tests/scene checks the committed data/schema/scene.schema.json and docs/scenes.md against
// them, and `make reference` copies them into the tree. Apart from the graph reference's
// generator so that it needs only antumbra_scene, not the passes.
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "antumbra/scene/scene_format.hpp"

namespace {

bool write_file(const char* path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::fprintf(stderr, "antumbra_generate_scene_reference: cannot write %s\n", path);
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr,
                 "usage: antumbra_generate_scene_reference <scene.schema.json> <scenes.md>\n");
    return 2;
  }
  try {
    const bool ok = write_file(argv[1], antumbra::scene::scene_schema().dump(2) + "\n") &&
                    write_file(argv[2], antumbra::scene::scene_reference_markdown());
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antumbra_generate_scene_reference: %s\n", e.what());
    return 1;
  }
}
