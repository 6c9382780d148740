#pragma once
// Where the program finds data/ and the pass shaders: ANTUMBRA_ROOT, else the first
// folder holding both data/ and passes/ going up from the working directory, then
// <executable's folder>/../share/antumbra (an installed program), then going up from the
// executable, then the source tree named by the build folder the executable lies in.
// Nothing is compiled in, so an installed prefix can move (docs/integration.md). A host
// program elsewhere passes DataPaths{Antumbra_DATA_DIR} (the package's config) itself.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace antumbra::runtime {

struct DataPaths {
  std::filesystem::path root;  // holds data/ and passes/
  [[nodiscard]] std::filesystem::path graphs() const { return root / "data" / "graphs"; }
  [[nodiscard]] std::filesystem::path scenes() const { return root / "data" / "scenes"; }
  [[nodiscard]] std::filesystem::path shaders() const { return root / "passes"; }
};

// Throws std::runtime_error naming the places searched when nothing fits.
// Throws DataPathsError when no root is found or ANTUMBRA_ROOT names the wrong folder:
// a setting to fix, so the command line exits 2 (usage), not 3.
class DataPathsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
DataPaths find_data_paths();

}  // namespace antumbra::runtime
