#pragma once
// Crash insurance: while a document has unsaved changes its text is written (atomically)
// to `<file>.recovery` at most every `interval`, so a crash loses at most that much work.
// A clean save, a close or an undo back to the saved state removes the file.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace antumbra::editor {

class RecoveryFile {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::seconds kDefaultInterval{5};

  RecoveryFile() = default;
  explicit RecoveryFile(const std::filesystem::path& document,
                        Clock::duration interval = kDefaultInterval);

  [[nodiscard]] static std::filesystem::path path_for(const std::filesystem::path& document);
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] Clock::duration interval() const { return interval_; }
  void set_interval(Clock::duration interval) { interval_ = interval; }

  // Writes `text()` when the document is dirty, changed since the last write (by
  // `revision`) and the last write is at least `interval` old; removes the file when the
  // document is clean. Returns true when it wrote. Throws SaveError when writing fails.
  bool write_if_due(Clock::time_point now, bool dirty, std::uint64_t revision,
                    const std::function<std::string()>& text);
  // Deletes the file (a missing one is fine) and forgets the last write.
  void remove();
  [[nodiscard]] bool exists() const;
  // True when the recovery file exists and is newer than the document (or the document
  // is gone): then it holds edits the document does not.
  [[nodiscard]] bool newer_than_document() const;

 private:
  std::filesystem::path document_;
  std::filesystem::path path_;
  Clock::duration interval_ = kDefaultInterval;
  std::optional<Clock::time_point> last_write_;
  std::optional<std::uint64_t> written_revision_;
};

}  // namespace antumbra::editor
