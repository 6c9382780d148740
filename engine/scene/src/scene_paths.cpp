// The paths a scene file names ("gltf", "scene") stay in its folder unless the loader
// allows outside paths (docs/robustness.md, "Paths"). The glTF's own URIs get the same
// rule in gltf_schema.cpp.
#include "antumbra/base/diagnostic_codes.hpp"
#include "outside_path.hpp"
#include "parse_context.hpp"

namespace antumbra::scene::detail {

std::string outside_reason(const std::filesystem::path& path) {
  if (path.has_root_path()) return "an absolute path";
  const std::filesystem::path normal = path.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..") return "a path that climbs out through '..'";
  return {};
}

bool path_allowed(ParseContext& ctx, const std::string& relative, const std::string& pointer) {
  const std::string why = outside_reason(relative);
  if (why.empty()) return true;
  std::string message = "'" + relative + "' is " + why;
  if (ctx.options.allow_outside_paths) {
    message += ", outside the scene file's folder; read because outside paths are allowed";
    ctx.reader.warning(codes::scene::kGltfPathOutside, std::move(message), pointer);
    return true;
  }
  message +=
      ", outside the scene file's folder: refused (a file names only what lies beside it or "
      "below; --allow-outside-paths, or SceneFileOptions::allow_outside_paths, allows it)";
  ctx.reader.error(codes::scene::kGltfPathOutside, std::move(message), pointer);
  return false;
}

}  // namespace antumbra::scene::detail
