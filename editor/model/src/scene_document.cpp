// Loading, undo/redo and recovery of the scene document. The edits themselves are in
// scene_edits.cpp, saving and the recovery file in json_file.cpp.
#include "antumbra/editor/scene_document.hpp"

#include <algorithm>

#include "antumbra/scene/gltf_scene.hpp"

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "light_json.hpp"

namespace antumbra::editor {
namespace {

// Lights the scene's objects import (glTF lights, instanced scenes' lights), read by the
// engine's parser; only files with such objects pay for the load.
std::vector<scene::PointLight> imported_lights_of(const base::JsonDocument& document,
                                                  scene::ImageCache* images,
                                                  const scene::SceneFileOptions& options,
                                                  base::Diagnostics& diagnostics) {
  const auto objects = document.root().find("objects");
  if (objects == document.root().end() || !objects->is_array()) return {};
  const bool imports = std::any_of(objects->begin(), objects->end(), [](const base::Json& o) {
    return o.is_object() && (o.contains("gltf") || o.contains("scene"));
  });
  if (!imports) return {};
  auto parsed = scene::parse_scene(document, images, options);
  if (parsed.ok()) return parsed->imported_lights;
  // Without them, overrides would read as lights lacking a position: say why first.
  for (const base::Diagnostic& d : parsed.diagnostics()) {
    if (d.severity == base::Severity::error) diagnostics.add(d);
  }
  return {};
}

// What the editor needs before it can edit a scene safely; the lights come back read.
std::vector<scene::PointLight> check_scene(const base::JsonDocument& document,
                                           const std::vector<scene::PointLight>& imported,
                                           std::vector<LightOrigin>& origins,
                                           base::Diagnostics& diagnostics) {
  const base::Json& root = document.root();
  if (!root.is_object()) {
    diagnostics.add(document.make(codes::editor::kNotAnObject, base::Severity::error,
                                  "a scene file must hold a JSON object", ""));
    return {};
  }
  // A newer format may give known keys new meanings: editing it could corrupt it.
  if (const auto it = root.find("version");
      it != root.end() && it->is_number() && it->get<double>() > scene::kSceneFormatVersion) {
    diagnostics.add(document.make(codes::editor::kNewerVersion, base::Severity::error,
                                  "scene format version " + it->dump() +
                                      " is newer than this editor supports (" +
                                      std::to_string(scene::kSceneFormatVersion) + ")",
                                  "/version"));
    return {};
  }
  return detail::read_lights(root, &document, diagnostics, imported, &origins);
}

}  // namespace

base::Result<SceneDocument> SceneDocument::load(const std::filesystem::path& file,
                                                scene::ImageCache* images,
                                                const scene::SceneFileOptions& options) {
  auto text = read_text_file(file);
  if (!text.ok()) return text.diagnostics();
  return parse(text.value(), file, images, options);
}

base::Result<SceneDocument> SceneDocument::open(const std::filesystem::path& file,
                                                scene::ImageCache* images,
                                                const scene::SceneFileOptions& options) {
  if (!scene::is_gltf_file(file)) return load(file, images, options);
  const std::filesystem::path settings = scene::gltf_scene_file(file);
  std::error_code ec;
  if (std::filesystem::is_regular_file(settings, ec)) return load(settings, images, options);
  auto text = scene::gltf_scene_text(file, images, options.allow_outside_paths);
  if (!text.ok()) return text.diagnostics();
  auto doc = parse(text.value(), settings, images, options);
  // The model's own warnings (missing textures, skipped lights), located in the glTF.
  if (doc.ok()) {
    for (const base::Diagnostic& d : text.diagnostics()) doc.diagnostics().add(d);
  }
  return doc;
}

base::Result<SceneDocument> SceneDocument::parse(std::string_view text,
                                                 const std::filesystem::path& file,
                                                 scene::ImageCache* images,
                                                 const scene::SceneFileOptions& options) {
  auto document = base::parse_json(text, file.string());
  if (!document.ok()) return document.diagnostics();
  base::Diagnostics diagnostics;
  std::vector<scene::PointLight> imported =
      imported_lights_of(document.value(), images, options, diagnostics);
  std::vector<LightOrigin> origins;
  std::vector<scene::PointLight> lights =
      check_scene(document.value(), imported, origins, diagnostics);
  if (diagnostics.has_errors()) return diagnostics;
  SceneDocument doc;
  doc.file_ = JsonFile(file, std::move(document.value()), std::string(text));
  doc.lights_ = std::move(lights);
  doc.origins_ = std::move(origins);
  doc.imported_ = std::move(imported);
  doc.file_options_ = options;
  return base::Result<SceneDocument>(std::move(doc), std::move(diagnostics));
}

int SceneDocument::find_light(std::string_view name) const {
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    if (lights_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

void SceneDocument::select(int index) {
  selected_ = index >= 0 && static_cast<std::size_t>(index) < lights_.size() ? index : -1;
}

LightOrigin SceneDocument::origin(std::size_t light) const {
  return light < origins_.size() ? origins_[light] : LightOrigin::own;
}

std::size_t SceneDocument::file_light_count() const {
  return static_cast<std::size_t>(std::count_if(
      origins_.begin(), origins_.end(), [](LightOrigin o) { return o != LightOrigin::imported; }));
}

void SceneDocument::refresh() {
  base::Diagnostics ignored;  // edits are validated before they are made
  lights_ = detail::read_lights(file_.root(), nullptr, ignored, imported_, &origins_);
  select(selected_);
}

EditResult SceneDocument::run(Command command) {
  const int focus = command.focus_after;
  file_.apply(std::move(command));
  refresh();
  select(focus);
  return {true, true, {}};
}

void SceneDocument::after_history(const Command* command, bool undone) {
  refresh();
  if (command != nullptr) select(undone ? command->focus_before : command->focus_after);
}

bool SceneDocument::undo() {
  const Command* command = file_.undo();
  after_history(command, true);
  return command != nullptr;
}

bool SceneDocument::redo() {
  const Command* command = file_.redo();
  after_history(command, false);
  return command != nullptr;
}

base::Diagnostics SceneDocument::validate() const {
  return scene::parse_scene_text(to_text(), file().string(), nullptr, file_options_).diagnostics();
}

base::Diagnostics SceneDocument::recover() {
  auto document = file_.read_recovery();
  if (!document.ok()) return document.diagnostics();
  base::Diagnostics diagnostics;
  std::vector<LightOrigin> origins;
  (void)check_scene(document.value(), imported_, origins, diagnostics);
  if (diagnostics.has_errors()) return diagnostics;
  file_.replace_content(document->root());
  selected_ = -1;
  refresh();
  return diagnostics;
}

}  // namespace antumbra::editor
