#include "antumbra/scene/gltf_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>

#include <nlohmann/json.hpp>

#include "antumbra/scene/gltf_loader.hpp"

namespace antumbra::scene {
namespace {

nlohmann::json vec3(const glm::vec3& v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

}  // namespace

bool is_gltf_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

std::filesystem::path gltf_scene_file(const std::filesystem::path& model) {
  return model.parent_path() / (model.filename().string() + ".scene.json");
}

base::Result<std::string> gltf_scene_text(const std::filesystem::path& model, ImageCache* images,
                                          bool allow_outside_paths) {
  GltfLimits limits;
  limits.allow_outside_paths = allow_outside_paths;
  auto imported = load_gltf(model.string(), limits, images);
  if (!imported.ok()) return imported.diagnostics();
  Aabb box;
  for (const Mesh& mesh : imported->meshes) box.expand(mesh.bounds);
  const glm::vec3 extent = box.extent();
  if (box.empty() || !std::isfinite(extent.x + extent.y + extent.z)) {
    box = Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)};  // nothing to frame: a unit box
  }
  const glm::vec3 size = box.extent();
  const float radius = std::max(0.5f * glm::length(size), 1e-3f);
  const glm::vec3 centre = box.center();
  Camera camera = imported->camera ? *imported->camera : framing_camera(box.min, box.max);
  const float distance = glm::length(camera.position - centre);
  if (camera.far <= camera.near) camera.far = (distance + radius) * 4.0f;
  nlohmann::json doc;
  doc["version"] = 1;
  doc["name"] = model.filename().string();
  doc["description"] = "A view of " + model.filename().string() +
                       " (generated; edits are saved here, the model is never rewritten)";
  doc["camera"] = {
      {"position", vec3(camera.position)}, {"target", vec3(camera.target)}, {"up", vec3(camera.up)},
      {"fovY", camera.fov_y_degrees},      {"near", camera.near},           {"far", camera.far}};
  doc["ambient"] = vec3(glm::vec3(0.04f));
  doc["objects"] =
      nlohmann::json::array({{{"name", "model"}, {"gltf", model.filename().string()}}});
  // Key, fill and rim two radii from the model's centre. The intensity cancels the
  // lights' falloff (1 / (d^2 + 1), lights.glsl) at the centre, so that a white surface
  // facing the key comes out near 1 whatever the model's size; the fill and the rim add
  // a third and a half of that.
  struct Rig {
    const char* name;
    glm::vec3 direction;
    float intensity;
    glm::vec3 colour;
  };
  const Rig rig[] = {{"key", {0.6f, 1.0f, 0.8f}, 1.0f, {1.0f, 0.96f, 0.9f}},
                     {"fill", {-1.0f, 0.4f, 0.6f}, 0.35f, {0.8f, 0.88f, 1.0f}},
                     {"rim", {0.2f, 0.8f, -1.0f}, 0.5f, {1.0f, 1.0f, 1.0f}}};
  nlohmann::json lights = nlohmann::json::array();
  // The file's own lights (KHR_lights_punctual) come in through the object, named
  // "model/<light>"; the rig only stands in for them when there are none.
  for (const Rig& r :
       imported->lights.empty() ? std::span<const Rig>(rig) : std::span<const Rig>()) {
    const glm::vec3 at = centre + glm::normalize(r.direction) * radius * 2.0f;
    const float d = glm::length(at - centre);
    lights.push_back({{"name", r.name},
                      {"position", vec3(at)},
                      {"color", vec3(r.colour)},
                      {"intensity", r.intensity * (d * d + 1.0f)},
                      {"range", d * 3.0f},
                      {"size", radius * 0.05f}});
  }
  doc["lights"] = lights;
  return base::Result<std::string>(doc.dump(2) + "\n", imported.diagnostics());
}

}  // namespace antumbra::scene
