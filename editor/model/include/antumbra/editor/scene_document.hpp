#pragma once
// The scene file the editor is working on. The JSON itself is the model: every key the
// editor does not know stays where it was, and the lights are derived records that the
// views read. Each edit is one undoable command; saving is atomic; a recovery file
// keeps unsaved work safe from crashes.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/json_file.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/scene/scene.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::editor {

// Any subset of one light's editable fields, applied as one command.
struct LightChanges {
  std::optional<std::string> name;
  std::optional<scene::LightType> type;
  std::optional<glm::vec3> position;
  std::optional<glm::vec3> color;
  std::optional<float> intensity;
  std::optional<float> range;
  std::optional<float> size;
  std::optional<bool> casts_shadows;
  std::optional<glm::vec3> direction;  // spot and directional; normalised when written
  std::optional<float> spot_outer;     // spot cone half-angles in degrees (scene "angle",
  std::optional<float> spot_inner;     // "innerAngle"): 0 < outer <= 90, 0 <= inner <= outer
};

// Where a light of SceneDocument::lights() comes from: an entry of the scene file, an
// entry overriding a light an object imports (a glTF's KHR_lights_punctual light or a
// light of an instanced scene, named "<object>/<light>"), or such a light as imported.
enum class LightOrigin { own, override, imported };

class SceneDocument {
 public:
  // Defaults for add_light (a point light a little above the floor, like the atrium's).
  static constexpr glm::vec3 kNewLightPosition{0.0f, 2.0f, 0.0f};
  static constexpr float kNewLightRange = 4.0f;
  static constexpr float kNewLightIntensity = 10.0f;
  static constexpr float kNewLightSize = 0.2f;
  static constexpr glm::vec3 kNewLightDirection{0.0f, -1.0f, 0.0f};  // spot and sun: down

  // Bad files (unreadable, bad JSON, lights the editor cannot read) come back as
  // diagnostics with file and line:column. recovery_available() tells whether a newer
  // recovery file was found beside the file.
  // `images` (optional) is the load's shared state: decoded images kept for the caller's
  // own load of the scene, and its progress sink for long loads. `options` (what the file
  // may make the loader read) stays with the document for every later parse of it.
  static base::Result<SceneDocument> load(const std::filesystem::path& file,
                                          scene::ImageCache* images = nullptr,
                                          const scene::SceneFileOptions& options = {});
  // load(), except that a .gltf or .glb opens the model as the whole scene: its scene
  // file beside it when saved before, else a generated one (scene/gltf_scene.hpp), not
  // written until saved. Edits never touch the model.
  static base::Result<SceneDocument> open(const std::filesystem::path& file,
                                          scene::ImageCache* images = nullptr,
                                          const scene::SceneFileOptions& options = {});
  static base::Result<SceneDocument> parse(std::string_view text, const std::filesystem::path& file,
                                           scene::ImageCache* images = nullptr,
                                           const scene::SceneFileOptions& options = {});

  // The options it was loaded with: every parse of its text uses them.
  [[nodiscard]] const scene::SceneFileOptions& file_options() const { return file_options_; }

  [[nodiscard]] const std::filesystem::path& file() const { return file_.path(); }
  [[nodiscard]] const base::Json& json() const { return file_.root(); }
  // The engine's lights, in its order: the file's entries (overrides applied), then the
  // imported lights no entry overrides.
  [[nodiscard]] const std::vector<scene::PointLight>& lights() const { return lights_; }
  [[nodiscard]] LightOrigin origin(std::size_t light) const;
  // The lights the scene's objects import, as they come (read with the engine's parser
  // when the document is opened). Edits to them are saved as overrides in the scene file;
  // deleting an override reverts the light.
  [[nodiscard]] const std::vector<scene::PointLight>& imported_lights() const { return imported_; }
  [[nodiscard]] int find_light(std::string_view name) const;  // -1 when absent

  // Selection is view state: it is not undoable and does not make the document dirty.
  [[nodiscard]] int selected() const { return selected_; }
  void select(int index);  // -1 (or any index out of range) selects nothing

  // Edits: each is one undoable command; a refused one changes nothing.
  EditResult apply(std::size_t light, const LightChanges& changes, std::string description = {});
  EditResult set_name(std::size_t light, std::string name);
  EditResult set_type(std::size_t light, scene::LightType type);
  EditResult set_position(std::size_t light, glm::vec3 position);
  EditResult set_color(std::size_t light, glm::vec3 color);
  EditResult set_intensity(std::size_t light, float intensity);
  EditResult set_range(std::size_t light, float range);
  EditResult set_size(std::size_t light, float size);
  EditResult set_casts_shadows(std::size_t light, bool casts);
  EditResult set_direction(std::size_t light, glm::vec3 direction);
  EditResult set_spot_angles(std::size_t light, float outer, float inner);
  // Adds at the end with a unique name ("light1", "light2", ...) and selects it.
  EditResult add_light(scene::LightType type = scene::LightType::point,
                       glm::vec3 position = kNewLightPosition);
  // Inserts a copy ("<name> copy") right after the light (after the file's lights for an
  // imported one) and selects it.
  EditResult duplicate_light(std::size_t light);
  EditResult delete_light(std::size_t light);

  bool undo();
  bool redo();
  [[nodiscard]] bool can_undo() const { return file_.history().can_undo(); }
  [[nodiscard]] bool can_redo() const { return file_.history().can_redo(); }
  [[nodiscard]] const EditHistory& history() const { return file_.history(); }
  // A drag is one gesture: every edit between begin and end is one undo step.
  void begin_gesture() { file_.history().begin_gesture(); }
  void end_gesture() { file_.history().end_gesture(); }

  [[nodiscard]] bool dirty() const { return file_.dirty(); }
  // Changes with every edit, undo, redo and recovery: views cache on it.
  [[nodiscard]] std::uint64_t revision() const { return file_.revision(); }

  // The file's text: the loaded formatting kept where only values changed, else the
  // canonical 2-space layout (see json_text.hpp).
  [[nodiscard]] std::string to_text() const { return file_.to_text(); }
  // The engine's scene parser run over to_text(): what the renderer would report.
  [[nodiscard]] base::Diagnostics validate() const;

  // Atomic save; throws SaveError (and stays dirty) when it fails. Removes the recovery file.
  void save() { file_.save_as(file_.path()); }
  void save_as(const std::filesystem::path& file) { file_.save_as(file); }
  [[nodiscard]] AtomicWriteHooks& save_hooks() { return file_.save_hooks(); }

  // Crash recovery. autosave_if_due writes <file>.recovery at most every interval while
  // dirty; recover() replaces the content with the recovery file's (dirty, no undo
  // history; diagnostics and no change when it cannot be read); close() is the clean end
  // of an editing session and removes the file.
  [[nodiscard]] bool recovery_available() const { return file_.recovery_available(); }
  bool autosave_if_due(RecoveryFile::Clock::time_point now) { return file_.autosave_if_due(now); }
  base::Diagnostics recover();
  void close() { file_.close(); }
  [[nodiscard]] RecoveryFile& recovery() { return file_.recovery(); }

 private:
  SceneDocument() = default;
  EditResult check_light(std::size_t light) const;
  [[nodiscard]] std::size_t file_light_count() const;  // entries of /lights
  [[nodiscard]] Command insert_light(base::Json entry, std::string description,
                                     int focus_before) const;
  EditResult run(Command command);
  void refresh();
  void after_history(const Command* command, bool undone);
  [[nodiscard]] std::string unique_name(std::string_view base) const;
  [[nodiscard]] bool name_taken(std::string_view name) const;
  [[nodiscard]] std::string label(std::string_view verb, std::size_t light) const;

  JsonFile file_;
  std::vector<scene::PointLight> lights_;
  std::vector<LightOrigin> origins_;  // parallel to lights_
  std::vector<scene::PointLight> imported_;
  scene::SceneFileOptions file_options_;
  int selected_ = -1;
};

}  // namespace antumbra::editor
