#pragma once
// Bounds-checked reading of glTF accessors. tinygltf parses the JSON and loads the
// buffers but trusts every index, offset, stride and count in the file; these readers
// check all of them before touching a byte, and read with memcpy (no alignment
// assumptions).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "antumbra/scene/scene.hpp"

#include <tiny_gltf.h>  // from /usr/include, a system directory: its warnings stay out

namespace antumbra::scene::detail {

// A problem found in the glTF: a code from base/diagnostic_codes.hpp (codes::scene), a message and
// a JSON Pointer into the glTF document.
struct GltfIssue {
  const char* code = nullptr;
  std::string message;
  std::string pointer;
};

// Fills `issue` and returns false, so that a reader can `return fail(issue, ...)`.
bool fail(GltfIssue& issue, const char* code, std::string message, std::string pointer);

// `referrer` is the pointer of the value holding the accessor index (for bad indices).
bool read_positions(const tinygltf::Model& model, int accessor, const std::string& referrer,
                    std::vector<glm::vec3>& out, GltfIssue& issue);
bool read_normals(const tinygltf::Model& model, int accessor, const std::string& referrer,
                  std::vector<glm::vec3>& out, GltfIssue& issue);
bool read_texcoords(const tinygltf::Model& model, int accessor, const std::string& referrer,
                    const char* what, std::vector<glm::vec2>& out, GltfIssue& issue);
bool read_tangents(const tinygltf::Model& model, int accessor, const std::string& referrer,
                   std::vector<glm::vec4>& out, GltfIssue& issue);
// Any of the three index component types; values are NOT range-checked here.
bool read_indices(const tinygltf::Model& model, int accessor, const std::string& referrer,
                  std::vector<std::uint32_t>& out, GltfIssue& issue);

// Turns one glTF primitive into `mesh` (local space): validated attributes, indices
// (generated when absent; strips and fans become lists), normals computed when missing,
// tangents read or, where `tangent_set` >= 0 (a normal map samples that coordinate
// set) and the file has none, generated. Points and lines leave `mesh` empty and add a
// warning.
bool build_primitive_mesh(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                          const std::string& pointer, int tangent_set, Mesh& mesh, GltfIssue& issue,
                          std::vector<GltfIssue>& warnings);

// Per-vertex tangents from the triangles' texture-coordinate gradients in set
// `set`, orthogonalised against the normals (w: bitangent sign).
void generate_tangents(Mesh& mesh, int set);

// Type checks of the glTF JSON (gltf_schema.cpp), run before tinygltf, which ignores
// wrongly typed properties. Geometry-relevant problems go to `errors`. Returns the
// parsed JSON (discarded when it does not parse: tinygltf reports that).
nlohmann::json check_gltf_schema(const std::string& path, std::vector<GltfIssue>& errors,
                                 std::vector<GltfIssue>& warnings);
// Every buffer and image URI that names a file (not a data: URI) names one in the glTF's
// own folder or below it (docs/robustness.md, "Paths"): an absolute path or one that climbs
// out through ".." is an error (SC046) at its pointer, or a warning when `allow_outside`.
// Run before tinygltf, which opens whatever a URI names.
void check_gltf_uris(const nlohmann::json& root, bool allow_outside, std::vector<GltfIssue>& errors,
                     std::vector<GltfIssue>& warnings);

}  // namespace antumbra::scene::detail
