#include "antumbra/watch/file_watcher.hpp"

namespace antumbra::watch {

FileWatcher::Stamp FileWatcher::stamp(const std::filesystem::path& path) {
  std::error_code ec;
  Stamp s;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(status)) return s;
  s.exists = true;
  s.time = std::filesystem::last_write_time(path, ec);
  s.size = std::filesystem::file_size(path, ec);
  if (ec) s = Stamp{};
  return s;
}

void FileWatcher::add(const std::filesystem::path& path) {
  files_[path] = stamp(path);
}

void FileWatcher::set(const std::vector<std::filesystem::path>& paths) {
  std::map<std::filesystem::path, Stamp> next;
  for (const auto& p : paths) {
    auto it = files_.find(p);
    next[p] = it != files_.end() ? it->second : stamp(p);
  }
  files_ = std::move(next);
}

std::vector<std::filesystem::path> FileWatcher::poll() {
  std::vector<std::filesystem::path> changed;
  for (auto& [path, old] : files_) {
    const Stamp now = stamp(path);
    if (!(now == old)) {
      changed.push_back(path);
      old = now;
    }
  }
  return changed;
}

}  // namespace antumbra::watch
