#pragma once
// FNV-1a 64-bit: fast, stable across runs and platforms; used for cache keys, not
// for security.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace antumbra::gpu {

class Fnv1a64 {
 public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;

  constexpr Fnv1a64& update(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      state_ ^= bytes[i];
      state_ *= kPrime;
    }
    return *this;
  }
  constexpr Fnv1a64& update(std::string_view text) {
    for (char c : text) {
      state_ ^= static_cast<unsigned char>(c);
      state_ *= kPrime;
    }
    return *this;
  }
  // A length-prefixed field, so that ("ab","c") and ("a","bc") hash differently.
  Fnv1a64& field(std::string_view text) {
    const std::uint64_t size = text.size();
    update(&size, sizeof(size));
    return update(text);
  }
  [[nodiscard]] constexpr std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = kOffsetBasis;
};

constexpr std::uint64_t fnv1a64(std::string_view text) {
  return Fnv1a64{}.update(text).value();
}

// 16 lower-case hex digits.
std::string to_hex(std::uint64_t value);

}  // namespace antumbra::gpu
