#include "antumbra/editor/recovery_file.hpp"

#include "antumbra/editor/atomic_file.hpp"

namespace antumbra::editor {

RecoveryFile::RecoveryFile(const std::filesystem::path& document, Clock::duration interval)
    : document_(document), path_(path_for(document)), interval_(interval) {
}

std::filesystem::path RecoveryFile::path_for(const std::filesystem::path& document) {
  std::filesystem::path path = document;
  path += ".recovery";
  return path;
}

bool RecoveryFile::write_if_due(Clock::time_point now, bool dirty, std::uint64_t revision,
                                const std::function<std::string()>& text) {
  if (path_.empty()) return false;
  if (!dirty) {
    // Back at the saved state (e.g. by undo): the document itself is the recovery.
    if (written_revision_) remove();
    return false;
  }
  if (written_revision_ == revision) return false;
  if (last_write_ && now - *last_write_ < interval_) return false;
  write_file_atomically(path_, text());
  last_write_ = now;
  written_revision_ = revision;
  return true;
}

void RecoveryFile::remove() {
  if (!path_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  last_write_.reset();
  written_revision_.reset();
}

bool RecoveryFile::exists() const {
  std::error_code ec;
  return !path_.empty() && std::filesystem::is_regular_file(path_, ec);
}

bool RecoveryFile::newer_than_document() const {
  if (!exists()) return false;
  std::error_code ec;
  const auto document_time = std::filesystem::last_write_time(document_, ec);
  if (ec) return true;
  const auto recovery_time = std::filesystem::last_write_time(path_, ec);
  return !ec && recovery_time > document_time;
}

}  // namespace antumbra::editor
