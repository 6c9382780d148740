#pragma once
// Saving without ever leaving a half-written file: the content goes to a temporary file
// in the target's directory (same file system, so the rename is atomic), is flushed and
// fsync'd, and only then renamed over the target. A failure at any step leaves the old
// file as it was and removes the temporary.

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace antumbra::editor {

// A save that failed (runtime I/O failure, not bad user input): says which file and why.
class SaveError : public std::runtime_error {
 public:
  SaveError(const std::filesystem::path& file, const std::string& why);
  [[nodiscard]] const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
};

struct AtomicWriteHooks {
  // Test seam: called with the temporary's path after it is complete and synced, just
  // before the rename. Throwing from it stands in for a crash or a full disk there.
  std::function<void(const std::filesystem::path& temporary)> before_rename;
};

// Writes `content` to `target` atomically; throws SaveError when it cannot.
void write_file_atomically(const std::filesystem::path& target, std::string_view content,
                           const AtomicWriteHooks& hooks = {});

}  // namespace antumbra::editor
