#include "antumbra/gpu/spirv_interface.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace antumbra::gpu {
namespace {

// The few SPIR-V opcodes, decorations and storage classes the interface needs
// (SPIR-V 1.6 specification, sections 3.20, 3.7 and 3.32).
constexpr std::uint32_t kOpName = 5;
constexpr std::uint32_t kOpEntryPoint = 15;
constexpr std::uint32_t kOpTypeInt = 21;
constexpr std::uint32_t kOpTypeFloat = 22;
constexpr std::uint32_t kOpTypeVector = 23;
constexpr std::uint32_t kOpTypeMatrix = 24;
constexpr std::uint32_t kOpTypeImage = 25;
constexpr std::uint32_t kOpTypeSampler = 26;
constexpr std::uint32_t kOpTypeSampledImage = 27;
constexpr std::uint32_t kOpTypeArray = 28;
constexpr std::uint32_t kOpTypeRuntimeArray = 29;
constexpr std::uint32_t kOpTypeStruct = 30;
constexpr std::uint32_t kOpTypePointer = 32;
constexpr std::uint32_t kOpConstant = 43;
constexpr std::uint32_t kOpVariable = 59;
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kOpMemberDecorate = 72;
constexpr std::uint32_t kBufferBlock = 3;
constexpr std::uint32_t kArrayStride = 6;
constexpr std::uint32_t kMatrixStride = 7;
constexpr std::uint32_t kLocation = 30;
constexpr std::uint32_t kBinding = 33;
constexpr std::uint32_t kDescriptorSet = 34;
constexpr std::uint32_t kOffset = 35;
constexpr std::uint32_t kUniformConstant = 0;
constexpr std::uint32_t kInput = 1;
constexpr std::uint32_t kUniform = 2;
constexpr std::uint32_t kPushConstant = 9;
constexpr std::uint32_t kStorageBuffer = 12;

struct Type {
  std::uint32_t op = 0;
  std::vector<std::uint32_t> operands;  // the instruction's words after the result id
};

struct Module {
  std::unordered_map<std::uint32_t, Type> types;
  std::unordered_map<std::uint32_t, std::uint32_t> constants;  // id -> first value word
  std::unordered_map<std::uint32_t, std::string> names;
  std::unordered_map<std::uint32_t, std::uint32_t> binding, set, array_stride, location;
  std::unordered_map<std::uint32_t, bool> buffer_block;
  // (struct id, member) -> offset / matrix stride
  std::unordered_map<std::uint64_t, std::uint32_t> member_offset, member_matrix_stride;
  struct Variable {
    std::uint32_t id, pointer_type, storage;
  };
  std::vector<Variable> variables;
  bool vertex = false;  // an entry point's execution model is Vertex (0)
};

std::uint64_t member_key(std::uint32_t id, std::uint32_t member) {
  return (std::uint64_t{id} << 32U) | member;
}

std::string literal_string(std::span<const std::uint32_t> words) {
  std::string out;
  for (const std::uint32_t word : words) {
    for (int byte = 0; byte < 4; ++byte) {
      const char c = static_cast<char>((word >> (8 * byte)) & 0xFFU);
      if (c == '\0') return out;
      out += c;
    }
  }
  return out;
}

void read_instruction(Module& m, std::uint32_t op, std::span<const std::uint32_t> w) {
  switch (op) {
    case kOpName:
      if (w.size() >= 2) m.names[w[0]] = literal_string(w.subspan(1));
      break;
    case kOpConstant:
      if (w.size() >= 3) m.constants[w[1]] = w[2];
      break;
    case kOpVariable:
      if (w.size() >= 3) m.variables.push_back({w[1], w[0], w[2]});
      break;
    case kOpEntryPoint:
      if (!w.empty() && w[0] == 0) m.vertex = true;
      break;
    case kOpDecorate:
      if (w.size() >= 2) {
        if (w[1] == kLocation && w.size() >= 3) m.location[w[0]] = w[2];
        if (w[1] == kBinding && w.size() >= 3) m.binding[w[0]] = w[2];
        if (w[1] == kDescriptorSet && w.size() >= 3) m.set[w[0]] = w[2];
        if (w[1] == kArrayStride && w.size() >= 3) m.array_stride[w[0]] = w[2];
        if (w[1] == kBufferBlock) m.buffer_block[w[0]] = true;
      }
      break;
    case kOpMemberDecorate:
      if (w.size() >= 4 && w[2] == kOffset) m.member_offset[member_key(w[0], w[1])] = w[3];
      if (w.size() >= 4 && w[2] == kMatrixStride)
        m.member_matrix_stride[member_key(w[0], w[1])] = w[3];
      break;
    default:
      if (op >= kOpTypeInt && op <= kOpTypePointer && !w.empty()) {
        m.types[w[0]] = {op, {w.begin() + 1, w.end()}};
      }
      break;
  }
}

Module parse(std::span<const std::uint32_t> words) {
  if (words.size() < 5 || words[0] != 0x07230203U) throw std::runtime_error("not a SPIR-V module");
  Module m;
  for (std::size_t i = 5; i < words.size();) {
    const std::uint32_t count = words[i] >> 16U;
    const std::uint32_t op = words[i] & 0xFFFFU;
    if (count == 0 || i + count > words.size()) throw std::runtime_error("truncated SPIR-V");
    read_instruction(m, op, words.subspan(i + 1, count - 1));
    i += count;
  }
  return m;
}

const Type* find_type(const Module& m, std::uint32_t id) {
  const auto it = m.types.find(id);
  return it == m.types.end() ? nullptr : &it->second;
}

// Bytes a value of type `id` occupies in a block (offsets and strides as decorated).
std::uint32_t type_size(const Module& m, std::uint32_t id, std::uint32_t matrix_stride = 0) {
  const Type* t = find_type(m, id);
  if (t == nullptr) return 0;
  switch (t->op) {
    case kOpTypeInt:
    case kOpTypeFloat:
      return t->operands.at(0) / 8;
    case kOpTypeVector:
      return t->operands.at(1) * type_size(m, t->operands.at(0));
    case kOpTypeMatrix: {
      const std::uint32_t column =
          matrix_stride != 0 ? matrix_stride : type_size(m, t->operands.at(0));
      return t->operands.at(1) * column;
    }
    case kOpTypeArray: {
      const auto length = m.constants.find(t->operands.at(1));
      const auto stride = m.array_stride.find(id);
      const std::uint32_t element =
          stride != m.array_stride.end() ? stride->second : type_size(m, t->operands.at(0));
      return length == m.constants.end() ? 0 : length->second * element;
    }
    case kOpTypeStruct: {
      std::uint32_t end = 0;
      for (std::uint32_t i = 0; i < t->operands.size(); ++i) {
        const auto offset = m.member_offset.find(member_key(id, i));
        const auto stride = m.member_matrix_stride.find(member_key(id, i));
        const std::uint32_t at = offset == m.member_offset.end() ? end : offset->second;
        end = std::max(end,
                       at + type_size(m, t->operands[i],
                                      stride == m.member_matrix_stride.end() ? 0 : stride->second));
      }
      return end;
    }
    default:
      return 0;
  }
}

// The element type of arrays of descriptors (texture arrays are one binding).
std::uint32_t strip_arrays(const Module& m, std::uint32_t id) {
  for (const Type* t = find_type(m, id);
       t != nullptr && (t->op == kOpTypeArray || t->op == kOpTypeRuntimeArray);
       t = find_type(m, id)) {
    id = t->operands.at(0);
  }
  return id;
}

VkDescriptorType descriptor_type(const Module& m, std::uint32_t storage, std::uint32_t pointee) {
  const std::uint32_t id = strip_arrays(m, pointee);
  const Type* t = find_type(m, id);
  if (t == nullptr) return VK_DESCRIPTOR_TYPE_MAX_ENUM;
  if (storage == kStorageBuffer) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  if (storage == kUniform) {
    return m.buffer_block.contains(id) ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                       : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  }
  if (t->op == kOpTypeSampledImage) return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  if (t->op == kOpTypeSampler) return VK_DESCRIPTOR_TYPE_SAMPLER;
  if (t->op == kOpTypeImage) {
    // Operand 6 of OpTypeImage (after the result id): Sampled, 1 = with a sampler, 2 = storage.
    return t->operands.at(5) == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                  : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
  }
  return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

// A vertex input of type `id`: its component count and their numeric type. Only 32-bit
// scalars and vectors of them are described; anything else (16/64-bit, matrices, arrays)
// stays components 0, scalar other, which no attribute format matches.
SpirvVertexInput vertex_input(const Module& m, std::uint32_t id) {
  SpirvVertexInput input;
  const Type* t = find_type(m, id);
  std::uint32_t components = 1;
  if (t != nullptr && t->op == kOpTypeVector) {
    components = t->operands.at(1);
    t = find_type(m, t->operands.at(0));
  }
  if (t == nullptr || (t->op != kOpTypeFloat && t->op != kOpTypeInt) || t->operands.at(0) != 32) {
    return input;
  }
  input.scalar = t->op == kOpTypeFloat    ? SpirvScalar::float32
                 : t->operands.at(1) != 0 ? SpirvScalar::sint32
                                          : SpirvScalar::uint32;
  input.components = components;
  return input;
}

}  // namespace

SpirvInterface reflect_spirv(std::span<const std::uint32_t> words) {
  const Module m = parse(words);
  SpirvInterface out;
  for (const auto& v : m.variables) {
    const Type* pointer = find_type(m, v.pointer_type);
    if (pointer == nullptr || pointer->op != kOpTypePointer) continue;
    const std::uint32_t pointee = pointer->operands.at(1);
    if (v.storage == kPushConstant) {
      out.push_constant_bytes = std::max(out.push_constant_bytes, type_size(m, pointee));
      continue;
    }
    if (v.storage == kInput) {
      const auto location = m.location.find(v.id);
      if (!m.vertex || location == m.location.end()) continue;  // built-ins have none
      SpirvVertexInput input = vertex_input(m, pointee);
      input.location = location->second;
      const auto name = m.names.find(v.id);
      if (name != m.names.end()) input.name = name->second;
      out.vertex_inputs.push_back(std::move(input));
      continue;
    }
    if (v.storage != kUniformConstant && v.storage != kUniform && v.storage != kStorageBuffer)
      continue;
    const auto binding = m.binding.find(v.id);
    if (binding == m.binding.end()) continue;
    const auto set = m.set.find(v.id);
    const auto name = m.names.find(v.id);
    const auto block_name = m.names.find(strip_arrays(m, pointee));
    out.bindings.push_back(
        {set == m.set.end() ? 0U : set->second, binding->second,
         descriptor_type(m, v.storage, pointee),
         name != m.names.end() && !name->second.empty()
             ? name->second
             : (block_name != m.names.end() ? block_name->second : std::string())});
  }
  std::sort(out.vertex_inputs.begin(), out.vertex_inputs.end(),
            [](const auto& a, const auto& b) { return a.location < b.location; });
  return out;
}

std::string descriptor_type_name(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_SAMPLER:
      return "sampler";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
      return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
      return "sampled image";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return "storage image";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
      return "storage buffer";
    default:
      return "descriptor type " + std::to_string(static_cast<int>(type));
  }
}

std::string glsl_type_name(SpirvScalar scalar, std::uint32_t components) {
  if (scalar == SpirvScalar::other || components == 0) return "non-32-bit or composite type";
  const char* scalar_name = scalar == SpirvScalar::float32  ? "float"
                            : scalar == SpirvScalar::sint32 ? "int"
                            : scalar == SpirvScalar::uint32 ? "uint"
                                                            : "?";
  if (components == 1) return scalar_name;
  const char* prefix = scalar == SpirvScalar::float32  ? ""
                       : scalar == SpirvScalar::sint32 ? "i"
                       : scalar == SpirvScalar::uint32 ? "u"
                                                       : "?";
  return std::string(prefix) + "vec" + std::to_string(components);
}

}  // namespace antumbra::gpu
