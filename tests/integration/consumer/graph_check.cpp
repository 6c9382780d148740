// Links Antumbra::framegraph alone (tests/integration/install_test.sh): the Vulkan-free graph
// core an engine runs in its offline checks. It fills a registry with its own pass type,
// compiles one good graph and one with a typo, and prints what the compiler says.
#include <cstdio>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/registry.hpp"

namespace fg = antumbra::fg;

namespace {

// The host's own pass type: an optional image in, an image out, one integer parameter.
fg::PassDesc smooth_pass() {
  fg::PassDesc desc;
  desc.type = "smooth";
  desc.description = "A host's blur.";
  fg::PortDesc in;
  in.name = "src";
  in.optional = true;
  in.formats = {fg::Format::rgba16f};
  fg::PortDesc out;
  out.name = "dst";
  out.direction = fg::PortDirection::output;
  out.access = fg::Access::color_attachment;
  out.stage = fg::Stage::graphics;
  out.formats = {fg::Format::rgba16f};
  desc.ports = {in, out};
  fg::ParamDesc radius;
  radius.name = "radius";
  radius.type = fg::ParamType::integer;
  radius.default_value = 2;
  radius.min = 1;
  radius.max = 8;
  desc.params = {radius};
  return desc;
}

// Two passes of the host's type: the first fills `a`, the second smooths it into `b`.
// `radius_key` is the parameter's name as the graph spells it.
std::string graph_text(const char* radius_key) {
  return std::string(R"({
  "version": 1,
  "name": "host",
  "resources": {
    "a": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "b": { "kind": "image", "format": "rgba16f", "size": "viewport/2" }
  },
  "passes": [
    { "name": "fill", "type": "smooth", "out": { "dst": "a" } },
    { "name": "blur", "type": "smooth", "params": { ")") +
         radius_key + R"(": 4 }, "in": { "src": "a" }, "out": { "dst": "b" } }
  ],
  "output": "b"
}
)";
}

void print(const fg::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) std::printf("%s\n", fg::format_text(d).c_str());
}

}  // namespace

int main() {
  fg::Registry registry;
  registry.add(smooth_pass());

  const auto good = fg::compile_text(graph_text("radius"), "host.json", registry);
  print(good.diagnostics());
  if (!good.ok() || good.value().passes.size() != 2) {
    std::printf("FAIL: the good graph did not compile to two passes\n");
    return 1;
  }
  std::printf("host.json: %zu passes, %zu resources\n", good.value().passes.size(),
              good.value().resources.size());

  const auto typo = fg::compile_text(graph_text("radus"), "typo.json", registry);
  print(typo.diagnostics());
  const auto* unknown = typo.diagnostics().find("FG031");
  if (typo.ok() || unknown == nullptr || unknown->line != 10) {
    std::printf("FAIL: expected FG031 at typo.json:10 for the misspelt parameter\n");
    return 1;
  }
  std::printf("PASS: graph core\n");
  return 0;
}
