// Build step: writes the JSON Schema of graph files and the pass reference from the
// registered passes (docs/adding-a-pass.md, "Register it"). The build keeps them under
// <build>/generated; tests/builtin checks the committed data/schema/framegraph.schema.json
// and docs/passes.md against them, and `make reference` copies them into the tree.
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/fg/schema.hpp"
#include "register_builtin_passes.hpp"

namespace {

bool write_file(const char* path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::fprintf(stderr, "antumbra_generate_reference: cannot write %s\n", path);
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: antumbra_generate_reference <schema.json> <passes.md>\n");
    return 2;
  }
  try {
    const auto registry = antumbra::passes::builtin_pass_registry();
    const auto& reflection = registry.reflection();
    const bool ok = write_file(argv[1], antumbra::fg::generate_schema(reflection).dump(2) + "\n") &&
                    write_file(argv[2], antumbra::fg::pass_reference_markdown(reflection));
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antumbra_generate_reference: %s\n", e.what());
    return 1;
  }
}
