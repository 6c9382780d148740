#pragma once
// Generated glTF files for tests: a square quad with texture coordinates (and optionally
// lights or images), written next to its PNG images in a folder of the test's. Header-only;
// link PkgConfig::STB for the PNG writer.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <stb_image_write.h>
#include <nlohmann/json.hpp>

namespace antumbra::testing {

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kTable[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t b0 = bytes[i];
    const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
    const std::uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t v = (b0 << 16U) | (b1 << 8U) | b2;
    out.push_back(kTable[(v >> 18U) & 63U]);
    out.push_back(kTable[(v >> 12U) & 63U]);
    out.push_back(i + 1 < bytes.size() ? kTable[(v >> 6U) & 63U] : '=');
    out.push_back(i + 2 < bytes.size() ? kTable[v & 63U] : '=');
  }
  return out;
}

template <class T>
void append_bytes(std::vector<std::uint8_t>& out, const std::vector<T>& values) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
  out.insert(out.end(), p, p + values.size() * sizeof(T));
}

// A `size` x `size` quad in the XZ plane at height `y`, facing +Y (counter-clockwise seen
// from above), uv (0,0) at (-x, -z) and (1,1) at (+x, +z). Material 0 is referenced but
// not defined: the caller adds "materials" (and images, textures) as it needs.
inline nlohmann::json quad_gltf(float size, float y) {
  const float h = size * 0.5f;
  const std::vector<float> positions = {-h, y, -h, h, y, -h, h, y, h, -h, y, h};
  const std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
  const std::vector<std::uint16_t> indices = {0, 2, 1, 0, 3, 2};
  std::vector<std::uint8_t> bin;
  append_bytes(bin, positions);
  append_bytes(bin, uvs);
  append_bytes(bin, indices);
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  nlohmann::json doc;
  doc["asset"] = {{"version", "2.0"}, {"generator", "antumbra tests"}};
  doc["scene"] = 0;
  doc["scenes"] = nlohmann::json::array({{{"nodes", {0}}}});
  doc["nodes"] = nlohmann::json::array({{{"name", "quad"}, {"mesh", 0}}});
  doc["meshes"] = nlohmann::json::array(
      {{{"name", "quad"},
        {"primitives", nlohmann::json::array({{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                                               {"indices", 2},
                                               {"material", 0}}})}}});
  doc["buffers"] =
      nlohmann::json::array({{{"byteLength", bin.size()},
                              {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
  doc["bufferViews"] =
      nlohmann::json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                             {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
                             {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}});
  doc["accessors"] = nlohmann::json::array(
      {{{"bufferView", 0},
        {"componentType", 5126},
        {"count", 4},
        {"type", "VEC3"},
        {"min", {-h, y, -h}},
        {"max", {h, y, h}}},
       {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
       {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}});
  return doc;
}

// quad_gltf(2, 0) with KHR_lights_punctual: node "bulb node" places point light "bulb"
// (colour (1, 0.5, 0.25), 100 cd, range 5) at (1, 2, 3); an unnamed node places spot
// "cone" (50 cd, cone 0.2 / 0.5 rad, no range) at (0, 4, 0) pointing down; node "sun"
// turns an unnamed 3 lux directional light to shine down.
inline nlohmann::json lit_quad_gltf() {
  nlohmann::json doc = quad_gltf(2.0f, 0.0f);
  doc["materials"] = nlohmann::json::array({{{"name", "grey"}}});
  doc["extensionsUsed"] = {"KHR_lights_punctual"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] =
      nlohmann::json::array({{{"name", "bulb"},
                              {"type", "point"},
                              {"color", {1.0, 0.5, 0.25}},
                              {"intensity", 100.0},
                              {"range", 5.0}},
                             {{"name", "cone"},
                              {"type", "spot"},
                              {"intensity", 50.0},
                              {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
                             {{"type", "directional"}, {"intensity", 3.0}}});
  const double h = std::sqrt(0.5);
  // -Z turned to -Y: a quarter turn about X.
  doc["nodes"].push_back({{"name", "bulb node"},
                          {"translation", {1.0, 2.0, 3.0}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  doc["nodes"].push_back({{"translation", {0.0, 4.0, 0.0}},
                          {"rotation", {-h, 0.0, 0.0, h}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  doc["nodes"].push_back({{"name", "sun"},
                          {"rotation", {-h, 0.0, 0.0, h}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  doc["scenes"][0]["nodes"] = {0, 1, 2, 3};
  return doc;
}

// RGBA8 pixels as PNG bytes.
inline std::vector<std::uint8_t> png_bytes(int width, int height,
                                           const std::vector<std::uint8_t>& rgba) {
  // stb reads width * height * 4 bytes whatever the vector holds: a short one is a test bug.
  if (rgba.size() != static_cast<std::size_t>(width) * height * 4) {
    throw std::invalid_argument("png_bytes: the pixels do not fill the image");
  }
  std::vector<std::uint8_t> out;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto& bytes = *static_cast<std::vector<std::uint8_t>*>(context);
        const auto* p = static_cast<const std::uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
      },
      &out, width, height, 4, rgba.data(), width * 4);
  return out;
}

// A `cells` x `cells` checkerboard, `texels` per cell: opaque white cells where
// (x + y) is even, transparent ones (alpha 0) elsewhere.
inline std::vector<std::uint8_t> checkerboard_rgba(int cells, int texels) {
  const int side = cells * texels;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(side) * side * 4);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const bool opaque = ((x / texels) + (y / texels)) % 2 == 0;
      std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * side + x) * 4];
      p[0] = p[1] = p[2] = 255;
      p[3] = opaque ? 255 : 0;
    }
  }
  return rgba;
}

inline void write_file(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

inline void write_json(const std::filesystem::path& path, const nlohmann::json& doc) {
  std::ofstream(path) << doc.dump(2);
}

}  // namespace antumbra::testing
