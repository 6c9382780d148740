#include "antumbra/editor/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace antumbra::editor {
namespace {

std::string errno_text(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

// Unique per process and call, so that two saves (or two editors) never share a temporary.
std::filesystem::path temporary_path(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = target;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temp;
}

// Closes the descriptor and removes the temporary unless released.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    close();
    if (!released_) {
      std::error_code ignored;
      std::filesystem::remove(path_, ignored);
    }
  }
  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  bool close() {
    if (fd_ < 0) return true;
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc == 0;
  }
  void release() { released_ = true; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool released_ = false;
};

void write_all(int fd, std::string_view content, const std::filesystem::path& target) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw SaveError(target, errno_text("cannot write the temporary file"));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

// The rename is durable only once the directory entry is on disk too.
void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // best effort: some file systems refuse to open directories
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

SaveError::SaveError(const std::filesystem::path& file, const std::string& why)
    : std::runtime_error(file.string() + ": " + why), file_(file) {
}

void write_file_atomically(const std::filesystem::path& file, std::string_view content,
                           const AtomicWriteHooks& hooks) {
  // Through a symbolic link, replace the file it names, not the link.
  std::error_code ec;
  std::filesystem::path target = file;
  if (std::filesystem::is_symlink(file, ec)) {
    target = std::filesystem::canonical(file, ec);
    if (ec) throw SaveError(file, "cannot resolve the link: " + ec.message());
  }
  TemporaryFile temp(temporary_path(target));
  if (temp.fd() < 0)
    throw SaveError(target, errno_text("cannot create a temporary file beside it"));
  // The new file keeps the old one's permissions (a read-only-for-others scene stays so).
  struct stat old_stat {};
  if (::stat(target.c_str(), &old_stat) == 0) (void)::fchmod(temp.fd(), old_stat.st_mode & 07777);
  write_all(temp.fd(), content, target);
  if (::fsync(temp.fd()) != 0)
    throw SaveError(target, errno_text("cannot sync the temporary file"));
  if (!temp.close()) throw SaveError(target, errno_text("cannot close the temporary file"));
  if (hooks.before_rename) hooks.before_rename(temp.path());
  if (::rename(temp.path().c_str(), target.c_str()) != 0) {
    throw SaveError(target, errno_text("cannot replace the file"));
  }
  temp.release();
  sync_directory(target.parent_path());
}

}  // namespace antumbra::editor
