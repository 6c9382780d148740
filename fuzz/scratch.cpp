// The scratch folder of the targets that read files from disk (targets.hpp).
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

#include "targets.hpp"

namespace antumbra::fuzz {
namespace {

std::filesystem::path make_scratch_folder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "antumbra-fuzz-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error("fuzz: cannot create a scratch folder under " + pattern);
  }
  return pattern;
}

// Removes the folder when the process ends normally (libFuzzer exits through exit()).
struct ScratchFolder {
  std::filesystem::path path = make_scratch_folder();
  ScratchFolder() = default;
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

const std::filesystem::path& scratch_folder() {
  static const ScratchFolder kFolder;  // created on first use, once per process
  return kFolder.path;
}

}  // namespace antumbra::fuzz
