// passes: the pass reference from the registry's reflection (no GPU needed).
#include <cstdio>
#include <iostream>

#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "commands.hpp"

namespace antumbra::app {

int run_passes(const PassesOptions& options) {
  const auto registry = runtime::pass_registry({});
  const fg::Registry& reflection = registry.reflection();
  if (options.type.empty()) {
    if (options.format == "json") {
      std::cout << fg::pass_reference_json(reflection).dump(2) << '\n';
    } else if (options.format == "markdown") {
      std::cout << fg::pass_reference_markdown(reflection);
    } else {
      std::cout << fg::pass_list_text(reflection);
    }
    return runtime::kExitOk;
  }
  const fg::PassDesc* desc = reflection.find(options.type);
  if (desc == nullptr) {
    std::fprintf(stderr,
                 "antumbra passes: unknown pass type '%s'%s (`antumbra passes` lists them)\n",
                 options.type.c_str(), fg::did_you_mean(options.type, reflection.types()).c_str());
    return runtime::kExitUsage;
  }
  if (options.format == "json") {
    std::cout << fg::pass_reference_json(*desc).dump(2) << '\n';
  } else if (options.format == "markdown") {
    std::cout << fg::pass_reference_markdown(*desc);
  } else {
    std::cout << fg::pass_reference_text(*desc);
  }
  return runtime::kExitOk;
}

}  // namespace antumbra::app
