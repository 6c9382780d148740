#include "antumbra/editor/json_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/editor/json_text.hpp"

namespace antumbra::editor {

base::Result<std::string> read_text_file(const std::filesystem::path& file) {
  std::error_code ec;
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  const int reason = errno;
  if (!in || std::filesystem::is_directory(file, ec)) {
    base::Diagnostics diagnostics;
    const std::string why = std::filesystem::is_directory(file, ec) ? "it is a directory"
                            : reason != 0                           ? std::strerror(reason)
                                                                    : "unknown reason";
    diagnostics.add({codes::graph::kFileUnreadable, base::Severity::error,
                     "cannot open the file: " + why, file.string(), "", 0, 0});
    return diagnostics;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

JsonFile::JsonFile(const std::filesystem::path& path, base::JsonDocument document, std::string text)
    : path_(path),
      base_(std::move(document)),
      base_text_(std::move(text)),
      root_(base_.root()),
      recovery_(path) {
  recovery_available_ = recovery_.newer_than_document();
  history_.clear(true);
}

std::string JsonFile::to_text() const {
  return preserve_format(base_, base_text_, root_);
}

void JsonFile::save_as(const std::filesystem::path& path) {
  const std::string text = to_text();
  write_file_atomically(path, text, save_hooks_);
  auto reparsed = base::parse_json(text, path.string());
  if (!reparsed.ok()) throw std::logic_error("editor: the saved text does not parse");
  recovery_.remove();
  if (path != path_) recovery_ = RecoveryFile(path, recovery_.interval());
  path_ = path;
  base_ = std::move(reparsed.value());
  base_text_ = text;
  history_.mark_saved();
  recovery_available_ = false;
}

bool JsonFile::autosave_if_due(RecoveryFile::Clock::time_point now) {
  return recovery_.write_if_due(now, dirty(), revision(), [this] { return to_text(); });
}

base::Result<std::string> JsonFile::read_recovery_text() const {
  if (!recovery_.exists()) {
    base::Diagnostics diagnostics;
    diagnostics.add({codes::editor::kNoRecovery, base::Severity::error, "there is no recovery file",
                     recovery_.path().string(), "", 0, 0});
    return diagnostics;
  }
  return read_text_file(recovery_.path());
}

base::Result<base::JsonDocument> JsonFile::read_recovery() const {
  auto text = read_recovery_text();
  if (!text.ok()) return text.diagnostics();
  return base::parse_json(text.value(), recovery_.path().string());
}

void JsonFile::replace_content(base::Json root) {
  // The file on disk stays the base: the new content is unsaved changes to it.
  root_ = std::move(root);
  history_.clear(false);
  recovery_available_ = false;
}

void JsonFile::close() {
  recovery_.remove();
  recovery_available_ = false;
}

}  // namespace antumbra::editor
