#include "gltf_accessors.hpp"

#include <algorithm>
#include <cstring>
#include <initializer_list>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::scene::detail {

bool fail(GltfIssue& issue, const char* code, std::string message, std::string pointer) {
  issue = GltfIssue{code, std::move(message), std::move(pointer)};
  return false;
}

namespace {

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
// Accessors without a buffer view read as zeros, so only this bounds their allocation.
constexpr std::size_t kMaxElements = std::size_t{1} << 26;

std::size_t component_size(int component_type) {
  switch (component_type) {
    case kByte:
    case kUByte:
      return 1;
    case kShort:
    case kUShort:
      return 2;
    case kUInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

std::size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

// A validated accessor: `count` elements at `data + i * stride` (or all zeros when
// the accessor has no buffer view, as the spec allows).
struct Layout {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  bool normalized = false;
};

bool validate(const tinygltf::Model& model, int index, const std::string& referrer, int type,
              std::initializer_list<int> component_types, const char* what, Layout& out,
              GltfIssue& issue) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    return fail(issue, codes::scene::kGltfBadReference,
                "accessor index " + std::to_string(index) + " does not exist", referrer);
  }
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  const std::string ap = "/accessors/" + std::to_string(index);
  if (a.sparse.isSparse) {
    return fail(issue, codes::scene::kGltfUnsupported, "sparse accessors are not supported", ap);
  }
  bool component_ok = false;
  for (const int c : component_types) component_ok = component_ok || c == a.componentType;
  if (a.type != type || !component_ok) {
    return fail(issue, codes::scene::kGltfBadAccessor,
                std::string(what) + " accessor has type " + std::to_string(a.type) +
                    " / componentType " + std::to_string(a.componentType) +
                    ", which glTF does not allow for it",
                ap);
  }
  if (a.count == 0) return fail(issue, codes::scene::kGltfBadAccessor, "accessor count is 0", ap);
  if (a.count > kMaxElements) {
    return fail(issue, codes::scene::kGltfTooLarge,
                "accessor count " + std::to_string(a.count) + " is past the import limit", ap);
  }
  const std::size_t element = component_size(a.componentType) * component_count(a.type);
  out = Layout{nullptr, element, a.count, a.componentType, a.normalized};
  if (a.bufferView < 0) return true;  // all zeros
  if (static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) {
    return fail(issue, codes::scene::kGltfBadReference,
                "bufferView " + std::to_string(a.bufferView) + " does not exist",
                ap + "/bufferView");
  }
  const tinygltf::BufferView& v = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string vp = "/bufferViews/" + std::to_string(a.bufferView);
  if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model.buffers.size()) {
    return fail(issue, codes::scene::kGltfBadReference,
                "buffer " + std::to_string(v.buffer) + " does not exist", vp + "/buffer");
  }
  const std::size_t buffer_size = model.buffers[static_cast<std::size_t>(v.buffer)].data.size();
  if (v.byteLength > buffer_size || v.byteOffset > buffer_size - v.byteLength) {
    return fail(issue, codes::scene::kGltfOutOfBounds,
                "bufferView (offset " + std::to_string(v.byteOffset) + ", length " +
                    std::to_string(v.byteLength) + ") lies outside its buffer of " +
                    std::to_string(buffer_size) + " bytes",
                vp);
  }
  std::size_t stride = element;
  if (v.byteStride != 0) {
    if (v.byteStride < element || v.byteStride > 252 ||
        v.byteStride % component_size(a.componentType) != 0) {
      return fail(issue, codes::scene::kGltfBadAccessor,
                  "byteStride " + std::to_string(v.byteStride) + " is invalid for " +
                      std::to_string(element) + "-byte elements",
                  vp + "/byteStride");
    }
    stride = v.byteStride;
  }
  // The last element must end inside the view: offset + (count-1)*stride + element.
  const bool fits = a.byteOffset <= v.byteLength && element <= v.byteLength - a.byteOffset &&
                    (a.count - 1) <= (v.byteLength - a.byteOffset - element) / stride;
  if (!fits) {
    return fail(issue, codes::scene::kGltfOutOfBounds,
                "accessor of " + std::to_string(a.count) + " elements (offset " +
                    std::to_string(a.byteOffset) + ", stride " + std::to_string(stride) +
                    ") runs past the end of its " + std::to_string(v.byteLength) +
                    "-byte bufferView",
                ap);
  }
  out.data =
      model.buffers[static_cast<std::size_t>(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
  out.stride = stride;
  return true;
}

template <class T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

// Component `c` of element `i` as float; normalized integers map to [0, 1] / [-1, 1].
float component(const Layout& l, std::size_t i, std::size_t c) {
  if (l.data == nullptr) return 0.0f;
  const unsigned char* p = l.data + i * l.stride + c * component_size(l.component_type);
  switch (l.component_type) {
    case kFloat:
      return load<float>(p);
    case kUByte:
      return static_cast<float>(load<std::uint8_t>(p)) / (l.normalized ? 255.0f : 1.0f);
    case kUShort:
      return static_cast<float>(load<std::uint16_t>(p)) / (l.normalized ? 65535.0f : 1.0f);
    case kByte:
      return std::max(static_cast<float>(load<std::int8_t>(p)) / (l.normalized ? 127.0f : 1.0f),
                      -1.0f);
    case kShort:
      return std::max(static_cast<float>(load<std::int16_t>(p)) / (l.normalized ? 32767.0f : 1.0f),
                      -1.0f);
    default:
      return static_cast<float>(load<std::uint32_t>(p));
  }
}

bool read_vec3(const tinygltf::Model& model, int accessor, const std::string& referrer,
               const char* what, std::vector<glm::vec3>& out, GltfIssue& issue) {
  Layout l;
  if (!validate(model, accessor, referrer, TINYGLTF_TYPE_VEC3, {kFloat}, what, l, issue)) {
    return false;
  }
  out.resize(l.count);
  for (std::size_t i = 0; i < l.count; ++i) {
    out[i] = {component(l, i, 0), component(l, i, 1), component(l, i, 2)};
  }
  return true;
}

}  // namespace

bool read_positions(const tinygltf::Model& model, int accessor, const std::string& referrer,
                    std::vector<glm::vec3>& out, GltfIssue& issue) {
  return read_vec3(model, accessor, referrer, "POSITION", out, issue);
}

bool read_normals(const tinygltf::Model& model, int accessor, const std::string& referrer,
                  std::vector<glm::vec3>& out, GltfIssue& issue) {
  return read_vec3(model, accessor, referrer, "NORMAL", out, issue);
}

bool read_texcoords(const tinygltf::Model& model, int accessor, const std::string& referrer,
                    const char* what, std::vector<glm::vec2>& out, GltfIssue& issue) {
  Layout l;
  if (!validate(model, accessor, referrer, TINYGLTF_TYPE_VEC2, {kFloat, kUByte, kUShort}, what, l,
                issue)) {
    return false;
  }
  l.normalized = true;  // integer texcoords are always normalized in glTF
  out.resize(l.count);
  for (std::size_t i = 0; i < l.count; ++i) out[i] = {component(l, i, 0), component(l, i, 1)};
  return true;
}

bool read_tangents(const tinygltf::Model& model, int accessor, const std::string& referrer,
                   std::vector<glm::vec4>& out, GltfIssue& issue) {
  Layout l;
  if (!validate(model, accessor, referrer, TINYGLTF_TYPE_VEC4, {kFloat}, "TANGENT", l, issue)) {
    return false;
  }
  out.resize(l.count);
  for (std::size_t i = 0; i < l.count; ++i) {
    out[i] = {component(l, i, 0), component(l, i, 1), component(l, i, 2), component(l, i, 3)};
  }
  return true;
}

bool read_indices(const tinygltf::Model& model, int accessor, const std::string& referrer,
                  std::vector<std::uint32_t>& out, GltfIssue& issue) {
  Layout l;
  if (!validate(model, accessor, referrer, TINYGLTF_TYPE_SCALAR, {kUByte, kUShort, kUInt},
                "indices", l, issue)) {
    return false;
  }
  out.resize(l.count);
  for (std::size_t i = 0; i < l.count; ++i) {
    const unsigned char* p = l.data == nullptr ? nullptr : l.data + i * l.stride;
    if (p == nullptr) {
      out[i] = 0;
    } else if (l.component_type == kUByte) {
      out[i] = load<std::uint8_t>(p);
    } else if (l.component_type == kUShort) {
      out[i] = load<std::uint16_t>(p);
    } else {
      out[i] = load<std::uint32_t>(p);
    }
  }
  return true;
}

}  // namespace antumbra::scene::detail
