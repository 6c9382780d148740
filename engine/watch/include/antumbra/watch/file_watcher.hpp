#pragma once
// Notices when watched files change, by polling their modification time and size
// (portable, no inotify dependency, and cheap for the few dozen files of a graph, its
// scene and its shaders). Vulkan-free, so it is tested without a device.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace antumbra::watch {

class FileWatcher {
 public:
  // Starts watching `path` (again); its current state is the baseline.
  void add(const std::filesystem::path& path);
  // Replaces the watched set, keeping the baselines of paths already watched so a
  // change between two calls is not lost.
  void set(const std::vector<std::filesystem::path>& paths);
  // The watched files that changed (appeared, vanished, or new time or size) since
  // the last poll or add, in path order. Each change is reported once.
  std::vector<std::filesystem::path> poll();
  [[nodiscard]] std::size_t size() const { return files_.size(); }

 private:
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type time{};
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const std::filesystem::path& path);
  std::map<std::filesystem::path, Stamp> files_;
};

}  // namespace antumbra::watch
