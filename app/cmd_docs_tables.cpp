// antumbra docs-tables: regenerates (or, with --check, compares) the measured tables of
// README.md and docs/*.md from the results files under docs/results/ (docs_tables.hpp).
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "docs_tables.hpp"

namespace antumbra::app {

int run_docs_tables(const DocsTablesOptions& options) {
  if (!std::filesystem::is_directory(options.root)) {
    std::fprintf(stderr, "antumbra docs-tables: --root %s is not a folder\n", options.root.c_str());
    return runtime::kExitUsage;
  }
  const auto tree = docs::process_tree(options.root, options.check);
  for (const auto& d : tree.diagnostics) {
    std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
  for (const auto& file : tree.rewritten) std::printf("rewrote %s\n", file.c_str());
  const std::size_t errors = tree.diagnostics.error_count();
  if (options.check && tree.differing > 0) {
    std::fprintf(stderr,
                 "antumbra docs-tables: %zu of %zu generated table(s) differ from their results\n",
                 tree.differing, tree.regions);
  }
  if (errors > 0) return runtime::kExitDiagnostics;
  std::printf("%zu generated table(s) %s\n", tree.regions,
              options.check ? "match their results" : "up to date");
  return runtime::kExitOk;
}

}  // namespace antumbra::app
