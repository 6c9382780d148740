#include "gltf_materials.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::scene::detail {
namespace {

constexpr int kWrapClamp = 33071;
constexpr int kWrapMirror = 33648;
constexpr int kFilterNearest = 9728;

TextureWrap wrap_of(int mode) {
  if (mode == kWrapClamp) return TextureWrap::clamp;
  if (mode == kWrapMirror) return TextureWrap::mirror;
  return TextureWrap::repeat;
}

std::string index_pointer(const std::string& base, std::size_t i) {
  return base + "/" + std::to_string(i);
}

// Percent-decoding of a relative URI ("my%20texture.png").
std::string decode_uri(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

class MaterialConverter {
 public:
  MaterialConverter(const GltfMaterialInput& input, std::vector<Texture>& textures,
                    GltfIssue& issue, std::vector<GltfIssue>& warnings)
      : in_(input), model_(input.model), textures_(textures), issue_(issue), warnings_(warnings) {
    images_.resize(model_.images.size());
  }

  bool convert(const tinygltf::Material& m, std::size_t index, Material& out);

 private:
  bool fail(const char* code, std::string message, std::string pointer) {
    issue_ = GltfIssue{code, std::move(message), std::move(pointer)};
    return false;
  }
  void warn(const char* code, std::string message, std::string pointer) {
    warnings_.push_back(GltfIssue{code, std::move(message), std::move(pointer)});
  }
  // Fills `slot` from a texture reference at `pointer`; false on an error.
  bool slot(int texture, int texcoord, const tinygltf::ExtensionMap& extensions, bool srgb,
            const std::string& pointer, TextureSlot& out);
  // The scene texture for glTF texture `t` in this colour space, or nullopt (warned).
  bool texture(int t, bool srgb, const std::string& referrer, std::optional<int>& out);
  std::shared_ptr<const ImageData> image(int source);
  void transform(const tinygltf::ExtensionMap& extensions, const std::string& pointer,
                 TextureSlot& out);

  const GltfMaterialInput& in_;
  const tinygltf::Model& model_;
  std::vector<Texture>& textures_;
  GltfIssue& issue_;
  std::vector<GltfIssue>& warnings_;
  struct ImageState {
    bool tried = false;
    std::shared_ptr<const ImageData> data;
  };
  std::vector<ImageState> images_;
  std::size_t decoded_ = 0;   // images tried, for progress
  std::uint64_t pixels_ = 0;  // of the images this file's materials hold (max_total_pixels)
  std::map<std::tuple<int, int, bool>, int> texture_ids_;  // (image, sampler, srgb)
};

std::shared_ptr<const ImageData> MaterialConverter::image(int source) {
  ImageState& state = images_[static_cast<std::size_t>(source)];
  if (state.tried) return state.data;
  state.tried = true;
  const tinygltf::Image& img = model_.images[static_cast<std::size_t>(source)];
  const std::string pointer = index_pointer("/images", static_cast<std::size_t>(source));
  const auto& bytes = in_.image_bytes[static_cast<std::size_t>(source)];
  const bool external = !img.uri.empty() && !img.uri.starts_with("data:");
  const std::filesystem::path file =
      std::filesystem::path(in_.path).parent_path() / decode_uri(img.uri);
  if (bytes.empty()) {
    std::error_code ec;
    if (external && !std::filesystem::is_regular_file(file, ec)) {
      warn(codes::scene::kGltfImage,
           "image file '" + img.uri + "' not found (looked for " + file.string() +
               "); the material's factors are used instead",
           pointer + "/uri");
    } else {
      warn(codes::scene::kGltfImage,
           "image has no data" + std::string(external ? " (the file is empty or unreadable)" : "") +
               "; the material's factors are used instead",
           pointer);
    }
    return nullptr;
  }
  const std::string name = external ? file.string() : in_.path + "#" + pointer;
  std::string key =
      external ? file_version_key(file.string()) : file_version_key(in_.path) + "#" + pointer;
  // What is left of the file's budget bounds this image too, so that ten thousand images
  // each under the per-image limit cannot add up to more than the budget.
  ImageLimits limits = in_.limits;
  const std::uint64_t left = limits.max_total_pixels - std::min(limits.max_total_pixels, pixels_);
  const bool budget_binds = left < limits.max_pixels;
  limits.max_pixels = std::min(limits.max_pixels, left);
  const auto decode = [&] { return decode_image(bytes, name, limits); };
  DecodedImage result = key.empty() ? decode() : in_.cache.get(key, decode);
  if (const auto* held = std::get_if<std::shared_ptr<const ImageData>>(&result);
      held != nullptr && std::uint64_t{(*held)->width} * (*held)->height > left) {
    result = std::string("its pixels are past what is left of the budget");  // a cache hit
  }
  if (auto* refusal = std::get_if<std::string>(&result); refusal != nullptr && budget_binds) {
    *refusal += " (the images of one glTF file may hold " +
                std::to_string(in_.limits.max_total_pixels) + " pixels in all; " +
                std::to_string(pixels_) + " are taken)";
  }
  ++decoded_;
  if (in_.cache.reporting()) {
    in_.cache.report(
        "decoding the images of " + std::filesystem::path(in_.path).filename().string(), decoded_,
        images_.size());
  }
  if (const auto* error = std::get_if<std::string>(&result)) {
    warn(codes::scene::kGltfImage,
         "image " + (external ? "'" + img.uri + "' " : std::string()) +
             "cannot be used: " + *error + "; the material's factors are used instead",
         external ? pointer + "/uri" : pointer);
    return nullptr;
  }
  state.data = std::get<std::shared_ptr<const ImageData>>(result);
  pixels_ += std::uint64_t{state.data->width} * state.data->height;
  return state.data;
}

bool MaterialConverter::texture(int t, bool srgb, const std::string& referrer,
                                std::optional<int>& out) {
  out.reset();
  if (t < 0 || static_cast<std::size_t>(t) >= model_.textures.size()) {
    return fail(codes::scene::kGltfBadReference,
                "texture " + std::to_string(t) + " does not exist (the file has " +
                    std::to_string(model_.textures.size()) + ")",
                referrer);
  }
  const tinygltf::Texture& tex = model_.textures[static_cast<std::size_t>(t)];
  const std::string tp = index_pointer("/textures", static_cast<std::size_t>(t));
  if (tex.source < 0) {
    std::string what = "the texture has no source image";
    for (const auto& [name, value] : tex.extensions) {
      what = "its image is only given through " + name + ", which is not supported";
    }
    warn(codes::scene::kGltfImage, what + "; the material's factors are used instead", tp);
    return true;
  }
  if (static_cast<std::size_t>(tex.source) >= model_.images.size()) {
    return fail(codes::scene::kGltfBadReference,
                "image " + std::to_string(tex.source) + " does not exist", tp + "/source");
  }
  if (tex.sampler >= 0 && static_cast<std::size_t>(tex.sampler) >= model_.samplers.size()) {
    return fail(codes::scene::kGltfBadReference,
                "sampler " + std::to_string(tex.sampler) + " does not exist", tp + "/sampler");
  }
  const auto key = std::make_tuple(tex.source, tex.sampler, srgb);
  if (const auto it = texture_ids_.find(key); it != texture_ids_.end()) {
    out = it->second;
    return true;
  }
  auto data = image(tex.source);
  if (!data) return true;
  Texture texture_out;
  texture_out.image = std::move(data);
  texture_out.srgb = srgb;
  if (tex.sampler >= 0) {
    const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(tex.sampler)];
    texture_out.wrap_u = wrap_of(s.wrapS);
    texture_out.wrap_v = wrap_of(s.wrapT);
    texture_out.nearest = s.magFilter == kFilterNearest;
  }
  const int id = static_cast<int>(textures_.size());
  textures_.push_back(std::move(texture_out));
  texture_ids_.emplace(key, id);
  out = id;
  return true;
}

void MaterialConverter::transform(const tinygltf::ExtensionMap& extensions,
                                  const std::string& pointer, TextureSlot& out) {
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end() || !it->second.IsObject()) return;
  const tinygltf::Value& v = it->second;
  const std::string tp = pointer + "/extensions/KHR_texture_transform";
  const auto vec2 = [&](const char* key, glm::vec2& target) {
    if (!v.Has(key)) return;
    const tinygltf::Value& a = v.Get(key);
    if (!a.IsArray() || a.ArrayLen() != 2 || !a.Get(0).IsNumber() || !a.Get(1).IsNumber() ||
        !std::isfinite(a.Get(0).GetNumberAsDouble()) ||
        !std::isfinite(a.Get(1).GetNumberAsDouble())) {
      warn(codes::scene::kGltfMaterial, std::string("expected two finite numbers; ignored"),
           tp + "/" + key);
      return;
    }
    target = glm::vec2(a.Get(0).GetNumberAsDouble(), a.Get(1).GetNumberAsDouble());
  };
  vec2("offset", out.offset);
  vec2("scale", out.scale);
  if (v.Has("rotation")) {
    const tinygltf::Value& r = v.Get("rotation");
    if (r.IsNumber() && std::isfinite(r.GetNumberAsDouble())) {
      out.rotation = static_cast<float>(r.GetNumberAsDouble());
    } else {
      warn(codes::scene::kGltfMaterial, "expected a finite number; ignored", tp + "/rotation");
    }
  }
  if (v.Has("texCoord")) {
    const tinygltf::Value& c = v.Get("texCoord");
    if (c.IsInt()) out.texcoord = c.Get<int>();
  }
}

bool MaterialConverter::slot(int texture_index, int texcoord,
                             const tinygltf::ExtensionMap& extensions, bool srgb,
                             const std::string& pointer, TextureSlot& out) {
  out = TextureSlot{};
  if (texture_index < 0) return true;  // absent
  out.texcoord = texcoord;
  transform(extensions, pointer, out);
  if (out.texcoord != 0 && out.texcoord != 1) {
    warn(codes::scene::kGltfMaterial,
         "texture coordinate set " + std::to_string(out.texcoord) +
             " is not supported (sets 0 and 1 are); the texture is ignored",
         pointer + "/texCoord");
    out = TextureSlot{};
    return true;
  }
  std::optional<int> id;
  if (!texture(texture_index, srgb, pointer + "/index", id)) return false;
  if (!id) {
    out = TextureSlot{};
    return true;
  }
  out.texture = *id;
  return true;
}

float finite_or(double value, float fallback) {
  return std::isfinite(value) ? static_cast<float>(value) : fallback;
}

bool MaterialConverter::convert(const tinygltf::Material& m, std::size_t index, Material& out) {
  const std::string p = index_pointer("/materials", index);
  out.name = m.name.empty() ? "material" + std::to_string(index) : m.name;
  glm::vec4 base(1.0f);
  const auto& f = m.pbrMetallicRoughness.baseColorFactor;
  if (f.size() == 4 && std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); })) {
    base = glm::clamp(glm::vec4(f[0], f[1], f[2], f[3]), 0.0f, 1.0f);
  }
  const auto clamp01 = [](double v, float fallback) {
    return std::isfinite(v) ? std::clamp(static_cast<float>(v), 0.0f, 1.0f) : fallback;
  };
  out.albedo = glm::vec3(base);
  out.alpha = base.a;
  out.metallic = clamp01(m.pbrMetallicRoughness.metallicFactor, 1.0f);
  out.roughness = clamp01(m.pbrMetallicRoughness.roughnessFactor, 1.0f);
  if (m.alphaMode == "MASK") {
    out.alpha_mode = AlphaMode::mask;
  } else if (m.alphaMode == "BLEND") {
    out.alpha_mode = AlphaMode::blend;
  } else if (!m.alphaMode.empty() && m.alphaMode != "OPAQUE") {
    warn(codes::scene::kGltfMaterial,
         "alphaMode '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND; OPAQUE is used",
         p + "/alphaMode");
  }
  if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0.0) {
    warn(codes::scene::kGltfMaterial, "alphaCutoff must be a number >= 0; 0.5 is used",
         p + "/alphaCutoff");
  } else {
    out.alpha_cutoff = static_cast<float>(m.alphaCutoff);
  }
  out.double_sided = m.doubleSided;
  out.translucent = out.alpha_mode == AlphaMode::blend && base.a < 1.0f;
  out.transmittance = base;
  const auto& e = m.emissiveFactor;
  if (e.size() == 3) {
    out.emissive =
        glm::max(glm::vec3(finite_or(e[0], 0.0f), finite_or(e[1], 0.0f), finite_or(e[2], 0.0f)),
                 glm::vec3(0.0f));
  }
  if (const auto it = m.extensions.find("KHR_materials_emissive_strength");
      it != m.extensions.end() && it->second.Has("emissiveStrength")) {
    const tinygltf::Value& s = it->second.Get("emissiveStrength");
    if (s.IsNumber() && std::isfinite(s.GetNumberAsDouble()) && s.GetNumberAsDouble() >= 0.0) {
      out.emissive *= static_cast<float>(s.GetNumberAsDouble());
    }
  }
  out.normal_scale = finite_or(m.normalTexture.scale, 1.0f);
  out.occlusion_strength = std::clamp(finite_or(m.occlusionTexture.strength, 1.0f), 0.0f, 1.0f);
  const auto& pbr = m.pbrMetallicRoughness;
  return slot(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
              pbr.baseColorTexture.extensions, true, p + "/pbrMetallicRoughness/baseColorTexture",
              out.base_color_texture) &&
         slot(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
              pbr.metallicRoughnessTexture.extensions, false,
              p + "/pbrMetallicRoughness/metallicRoughnessTexture",
              out.metallic_roughness_texture) &&
         slot(m.normalTexture.index, m.normalTexture.texCoord, m.normalTexture.extensions, false,
              p + "/normalTexture", out.normal_texture) &&
         slot(m.occlusionTexture.index, m.occlusionTexture.texCoord, m.occlusionTexture.extensions,
              false, p + "/occlusionTexture", out.occlusion_texture) &&
         slot(m.emissiveTexture.index, m.emissiveTexture.texCoord, m.emissiveTexture.extensions,
              true, p + "/emissiveTexture", out.emissive_texture);
}

}  // namespace

bool convert_materials(const GltfMaterialInput& input, std::vector<Material>& materials,
                       std::vector<Texture>& textures, GltfIssue& issue,
                       std::vector<GltfIssue>& warnings) {
  MaterialConverter converter(input, textures, issue, warnings);
  for (std::size_t i = 0; i < input.model.materials.size(); ++i) {
    Material material;
    if (!converter.convert(input.model.materials[i], i, material)) return false;
    materials.push_back(std::move(material));
  }
  return true;
}

}  // namespace antumbra::scene::detail
