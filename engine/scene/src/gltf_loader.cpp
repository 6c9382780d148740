// glTF import: loads with tinygltf, walks the default scene's node tree (guarding
// against cycles and instancing blow-ups), and turns triangle primitives into Meshes.
#include "antumbra/scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "gltf_accessors.hpp"
#include "gltf_lights.hpp"
#include "gltf_materials.hpp"

namespace antumbra::scene {
namespace {

using detail::GltfIssue;
using detail::GltfMaterialInput;
using detail::PunctualLights;

constexpr int kMaxNodeDepth = 1024;

// tinygltf hands over each image's encoded bytes (from its file, data URI or buffer
// view); they are kept and decoded afterwards, only for images a material uses, with
// our own checks (gltf_materials.cpp). Returning true keeps tinygltf going whatever
// the bytes are.
bool keep_image_bytes(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  auto& images = *static_cast<std::vector<std::vector<std::uint8_t>>*>(user);
  if (index < 0 || bytes == nullptr || size <= 0) return true;
  if (images.size() <= static_cast<std::size_t>(index)) {
    images.resize(static_cast<std::size_t>(index) + 1);
  }
  images[static_cast<std::size_t>(index)].assign(bytes, bytes + size);
  return true;
}

bool is_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && std::string_view(magic, 4) == "glTF";
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

class Importer {
 public:
  Importer(const GltfMaterialInput& materials, const PunctualLights& lights,
           const GltfLimits& limits, GltfImport& out)
      : materials_(materials),
        lights_(lights),
        model_(materials.model),
        limits_(limits),
        out_(out) {}

  // Returns false with `issue_` set on the first error.
  bool run();
  [[nodiscard]] const GltfIssue& issue() const { return issue_; }
  [[nodiscard]] const std::vector<GltfIssue>& warnings() const { return warnings_; }

 private:
  bool fail(const char* code, std::string message, std::string pointer) {
    issue_ = GltfIssue{code, std::move(message), std::move(pointer)};
    return false;
  }
  bool node_matrix(const tinygltf::Node& node, const std::string& p, glm::mat4& out);
  bool visit(int node, const std::string& referrer, const glm::mat4& parent, int depth);
  bool add_mesh(int mesh, const std::string& referrer, const glm::mat4& world);
  void add_camera(int camera, const glm::mat4& world);
  void place_lights();
  bool add_primitive(const tinygltf::Primitive& prim, const std::string& p, const std::string& name,
                     const glm::mat4& world);

  const GltfMaterialInput& materials_;
  const PunctualLights& lights_;
  const tinygltf::Model& model_;
  const GltfLimits& limits_;
  GltfImport& out_;
  GltfIssue issue_;
  std::vector<GltfIssue> warnings_;
  std::vector<bool> on_path_;
  std::size_t visits_ = 0;
  std::size_t triangles_ = 0;
  std::size_t primitives_done_ = 0;   // for progress
  std::size_t primitives_total_ = 0;  // in the file (instancing may visit more)
  // Lights met in the node tree, placed once the model's size is known.
  struct LightNode {
    int definition;
    glm::mat4 world;
    std::string name;
  };
  std::vector<LightNode> light_nodes_;
};

bool Importer::run() {
  for (const std::string& ext : model_.extensionsRequired) {
    // Material and texture extensions only refine shading we do not use; geometry
    // compression/quantisation would leave us reading encoded bytes as floats.
    if (ext.starts_with("KHR_materials_") || ext.starts_with("KHR_texture_") ||
        ext == "KHR_lights_punctual") {
      continue;
    }
    return fail(codes::scene::kGltfUnsupported, "required extension '" + ext + "' is not supported",
                "/extensionsRequired");
  }
  if (!detail::convert_materials(materials_, out_.materials, out_.textures, issue_, warnings_))
    return false;
  out_.materials.push_back(Material{.name = "default"});
  on_path_.assign(model_.nodes.size(), false);
  for (const tinygltf::Mesh& m : model_.meshes) primitives_total_ += m.primitives.size();
  if (model_.scenes.empty()) {
    return fail(codes::scene::kGltfNoGeometry,
                model_.defaultScene >= 0 ? "\"scene\" " + std::to_string(model_.defaultScene) +
                                               " names a scene, but the file has no scenes"
                                         : "the file has no scenes",
                model_.defaultScene >= 0 ? "/scene" : "");
  }
  const int scene = model_.defaultScene < 0 ? 0 : model_.defaultScene;
  if (static_cast<std::size_t>(scene) >= model_.scenes.size()) {
    return fail(codes::scene::kGltfBadReference,
                "scene " + std::to_string(scene) + " does not exist", "/scene");
  }
  const auto& roots = model_.scenes[static_cast<std::size_t>(scene)].nodes;
  const std::string sp = "/scenes/" + std::to_string(scene) + "/nodes";
  for (std::size_t i = 0; i < roots.size(); ++i) {
    if (!visit(roots[i], sp + "/" + std::to_string(i), glm::mat4(1.0f), 0)) return false;
  }
  if (out_.meshes.empty()) {
    return fail(codes::scene::kGltfNoGeometry,
                "scene " + std::to_string(scene) + " contains no triangles",
                "/scenes/" + std::to_string(scene));
  }
  place_lights();
  return true;
}

// Named after their node (Blender's object name), else the light, else the index; a
// light placed by several unnamed nodes gets "#2", "#3", ...
void Importer::place_lights() {
  Aabb box;
  for (const Mesh& mesh : out_.meshes) box.expand(mesh.bounds);
  const float diagonal = box.empty() ? 1.0f : glm::length(box.extent());
  std::unordered_set<std::string> taken;
  for (const LightNode& node : light_nodes_) {
    const auto& definition = *lights_.definitions[static_cast<std::size_t>(node.definition)];
    PointLight light = detail::place_punctual_light(definition, node.world, diagonal);
    std::string name = !node.name.empty()               ? node.name
                       : !definition.light.name.empty() ? definition.light.name
                                                        : "light" + std::to_string(node.definition);
    light.name = name;
    for (int copy = 2; !taken.insert(light.name).second; ++copy) {
      light.name = name + "#" + std::to_string(copy);
    }
    out_.lights.push_back(std::move(light));
  }
}

bool Importer::node_matrix(const tinygltf::Node& node, const std::string& p, glm::mat4& out) {
  out = glm::mat4(1.0f);
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) {
      return fail(codes::scene::kGltfParse, "node matrix needs 16 numbers", p + "/matrix");
    }
    for (int i = 0; i < 16; ++i) {  // column-major in glTF and glm alike
      out[i / 4][i % 4] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
    }
  } else {
    const auto& t = node.translation;
    const auto& r = node.rotation;
    const auto& s = node.scale;
    if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
        (!s.empty() && s.size() != 3)) {
      return fail(codes::scene::kGltfParse, "node translation/rotation/scale has the wrong arity",
                  p);
    }
    glm::mat4 m(1.0f);
    if (!t.empty()) m = glm::translate(m, glm::vec3(t[0], t[1], t[2]));
    // glTF quaternions are (x, y, z, w); glm's constructor takes w first.
    if (!r.empty()) {
      m *= glm::mat4_cast(
          glm::normalize(glm::quat(static_cast<float>(r[3]), static_cast<float>(r[0]),
                                   static_cast<float>(r[1]), static_cast<float>(r[2]))));
    }
    if (!s.empty()) m = glm::scale(m, glm::vec3(s[0], s[1], s[2]));
    out = m;
  }
  if (!finite(out)) return fail(codes::scene::kGltfNonFinite, "node transform is not finite", p);
  return true;
}

bool Importer::visit(int node, const std::string& referrer, const glm::mat4& parent, int depth) {
  if (node < 0 || static_cast<std::size_t>(node) >= model_.nodes.size()) {
    return fail(codes::scene::kGltfBadReference, "node " + std::to_string(node) + " does not exist",
                referrer);
  }
  const auto n = static_cast<std::size_t>(node);
  const std::string p = "/nodes/" + std::to_string(node);
  if (on_path_[n]) {
    return fail(codes::scene::kGltfNodeCycle,
                "node " + std::to_string(node) + " is its own ancestor (cycle in the node tree)",
                referrer);
  }
  if (++visits_ > limits_.max_node_visits || depth > kMaxNodeDepth) {
    return fail(codes::scene::kGltfTooLarge, "node tree is too deep or instanced too often", p);
  }
  glm::mat4 local;
  if (!node_matrix(model_.nodes[n], p, local)) return false;
  const glm::mat4 world = parent * local;
  const tinygltf::Node& nd = model_.nodes[n];
  if (nd.mesh >= 0 && !add_mesh(nd.mesh, p + "/mesh", world)) return false;
  if (nd.camera >= 0 && !out_.camera) add_camera(nd.camera, world);
  if (n < lights_.light_of_node.size()) {
    const int light = lights_.light_of_node[n];
    if (light >= 0 && lights_.definitions[static_cast<std::size_t>(light)]) {
      light_nodes_.push_back({light, world, nd.name});
    }
  }
  on_path_[n] = true;
  for (std::size_t i = 0; i < nd.children.size(); ++i) {
    if (!visit(nd.children[i], p + "/children/" + std::to_string(i), world, depth + 1))
      return false;
  }
  on_path_[n] = false;
  return true;
}

// glTF cameras look down their node's -Z with +Y up; orthographic ones are skipped.
void Importer::add_camera(int camera, const glm::mat4& world) {
  if (static_cast<std::size_t>(camera) >= model_.cameras.size()) {
    warnings_.push_back({codes::scene::kGltfBadReference,
                         "camera " + std::to_string(camera) + " does not exist; ignored",
                         "/cameras"});
    return;
  }
  const tinygltf::Camera& c = model_.cameras[static_cast<std::size_t>(camera)];
  if (c.type != "perspective") return;
  const double yfov = c.perspective.yfov;
  const glm::vec3 position(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const glm::vec3 forward(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  const glm::vec3 up(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
  if (!(yfov > 0.0 && yfov < 3.1) || glm::length(forward) < 1e-6f || glm::length(up) < 1e-6f) {
    return;
  }
  Camera out;
  out.position = position;
  out.target = position + glm::normalize(forward);
  out.up = glm::normalize(up);
  out.fov_y_degrees = static_cast<float>(glm::degrees(yfov));
  if (c.perspective.znear > 0.0) out.near = static_cast<float>(c.perspective.znear);
  // zfar absent (0) means infinite: the caller fits a far plane to the scene.
  out.far =
      c.perspective.zfar > c.perspective.znear ? static_cast<float>(c.perspective.zfar) : 0.0f;
  out_.camera = out;
}

bool Importer::add_mesh(int mesh, const std::string& referrer, const glm::mat4& world) {
  if (static_cast<std::size_t>(mesh) >= model_.meshes.size()) {
    return fail(codes::scene::kGltfBadReference, "mesh " + std::to_string(mesh) + " does not exist",
                referrer);
  }
  const tinygltf::Mesh& m = model_.meshes[static_cast<std::size_t>(mesh)];
  const std::string mp = "/meshes/" + std::to_string(mesh);
  for (std::size_t i = 0; i < m.primitives.size(); ++i) {
    // Built by appending: GCC 12 reports a false -Wrestrict on "literal" + std::string.
    std::string name = m.name.empty() ? std::string("mesh").append(std::to_string(mesh)) : m.name;
    if (m.primitives.size() > 1) name.append(".").append(std::to_string(i));
    if (!add_primitive(m.primitives[i], mp + "/primitives/" + std::to_string(i), name, world)) {
      return false;
    }
  }
  return true;
}

bool Importer::add_primitive(const tinygltf::Primitive& prim, const std::string& p,
                             const std::string& name, const glm::mat4& world) {
  Mesh mesh;
  mesh.name = name;
  const int material = prim.material;
  if (material >= static_cast<int>(model_.materials.size())) {
    return fail(codes::scene::kGltfBadReference,
                "material " + std::to_string(material) + " does not exist", p + "/material");
  }
  // Tangents matter only under a normal map, in that map's coordinate set.
  const TextureSlot& normal_map =
      out_.materials[static_cast<std::size_t>(material < 0 ? out_.materials.size() - 1 : material)]
          .normal_texture;
  const int tangent_set = normal_map.used() ? normal_map.texcoord : -1;
  if (!detail::build_primitive_mesh(model_, prim, p, tangent_set, mesh, issue_, warnings_)) {
    return false;
  }
  if (mesh.indices.empty()) return true;  // skipped (points/lines), with a warning
  triangles_ += mesh.triangle_count();
  ++primitives_done_;
  if (materials_.cache.reporting()) {
    materials_.cache.report(
        "building the meshes of " + std::filesystem::path(materials_.path).filename().string(),
        primitives_done_, std::max(primitives_done_, primitives_total_));
  }
  if (triangles_ > limits_.max_triangles) {
    return fail(codes::scene::kGltfTooLarge,
                "more than " + std::to_string(limits_.max_triangles) + " triangles", p);
  }
  mesh.material = material < 0 ? static_cast<int>(out_.materials.size()) - 1 : material;
  mesh.transform = world;
  mesh.update_bounds();
  out_.meshes.push_back(std::move(mesh));
  return true;
}

}  // namespace

base::Result<GltfImport> load_gltf(const std::string& path, const GltfLimits& limits,
                                   ImageCache* cache) {
  base::Diagnostics diagnostics;
  const auto report = [&](const char* code, base::Severity severity, std::string message,
                          std::string pointer) {
    diagnostics.add(
        base::Diagnostic{code, severity, std::move(message), path, std::move(pointer), 0, 0});
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    report(codes::scene::kGltfFileMissing, base::Severity::error, "file not found", "");
    return diagnostics;
  }
  std::vector<GltfIssue> schema_errors;
  std::vector<GltfIssue> schema_warnings;
  const nlohmann::json root = detail::check_gltf_schema(path, schema_errors, schema_warnings);
  detail::check_gltf_uris(root, limits.allow_outside_paths, schema_errors, schema_warnings);
  const PunctualLights lights = detail::read_punctual_lights(root, schema_warnings);
  for (const GltfIssue& w : schema_warnings) {
    report(w.code, base::Severity::warning, w.message, w.pointer);
  }
  if (!schema_errors.empty()) {
    for (const GltfIssue& e : schema_errors)
      report(e.code, base::Severity::error, e.message, e.pointer);
    return diagnostics;
  }
  ImageCache own_cache;
  ImageCache& images = cache != nullptr ? *cache : own_cache;
  images.report("reading " + std::filesystem::path(path).filename().string(), 0, 0);
  tinygltf::Model model;
  std::string error;
  std::string warning;
  bool loaded = false;
  std::vector<std::vector<std::uint8_t>> image_bytes;
  try {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_image_bytes, &image_bytes);
    loaded = is_binary(path) ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                             : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  } catch (const std::exception& e) {  // tinygltf/nlohmann on hostile input, bad_alloc
    error = e.what();
  }
  const auto trim = [](std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
  };
  // Missing image files are reported per image, with their pointer (gltf_materials.cpp).
  std::string kept;
  std::istringstream lines(warning);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("Failed to load external 'uri' for image")) kept += line + "\n";
  }
  if (!trim(kept).empty()) {
    report(codes::scene::kGltfWarning, base::Severity::warning, "tinygltf: " + trim(kept), "");
  }
  if (!loaded) {
    report(codes::scene::kGltfParse, base::Severity::error,
           "cannot load: " + (trim(error).empty() ? std::string("unknown error") : trim(error)),
           "");
    return diagnostics;
  }
  GltfImport out;
  image_bytes.resize(model.images.size());
  const GltfMaterialInput materials{model, path, image_bytes, images, limits.images};
  Importer importer(materials, lights, limits, out);
  const bool ok = importer.run();
  for (const GltfIssue& w : importer.warnings()) {
    report(w.code, base::Severity::warning, w.message, w.pointer);
  }
  if (!ok) {
    const GltfIssue& e = importer.issue();
    report(e.code, base::Severity::error, e.message, e.pointer);
    return diagnostics;
  }
  return base::Result<GltfImport>(std::move(out), std::move(diagnostics));
}

}  // namespace antumbra::scene
