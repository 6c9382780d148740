#include "antumbra/base/text.hpp"

namespace antumbra::base {

// Built by appending: GCC 12 warns (-Wrestrict, a false positive) on "'" + s + "'".
std::string quote_name(std::string_view name) {
  std::string out;
  out.reserve(name.size() + 2);
  out += '\'';
  out.append(name);
  out += '\'';
  return out;
}

std::string name_list(std::span<const std::string> names, std::size_t shown) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < shown; ++i) {
    if (i > 0) out += ", ";
    out += quote_name(names[i]);
  }
  if (names.size() > shown) {
    out += ", ... and ";
    out += std::to_string(names.size() - shown);
    out += " more";
  }
  return out;
}

}  // namespace antumbra::base
