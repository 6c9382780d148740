#pragma once
// A parameter's name with its C++ type, for code outside the pass that owns the parameter
// (the layer checks, the editor and edit scripts read the layer cap through one key).

#include <limits>
#include <optional>
#include <type_traits>

#include "antumbra/base/json_document.hpp"

namespace antumbra::base {

template <class T>
struct ParamKey {
  const char* name;
};

// `value` as T, or nullopt when it is of another JSON type or does not fit T (an integer
// parameter written 2.5 is not an int, 300 is not a uint8). A whole number written 3.0
// reads as 3: the graph compiler's type check is stricter (FG032 refuses it), but a reader
// of a document the compiler has not accepted yet, such as the editor, sees what the user
// meant. The one conversion of parameter values: fg::ParamTable reads through it too.
template <class T>
std::optional<T> json_as(const Json& value) {
  if constexpr (std::is_same_v<T, bool>) {
    if (value.is_boolean()) return value.template get<bool>();
  } else if constexpr (std::is_integral_v<T>) {
    if (value.is_number_integer() || value.is_number_float()) {
      const double number = value.template get<double>();
      const bool fits = number >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
                        number <= static_cast<double>(std::numeric_limits<T>::max());
      if (fits && number == static_cast<double>(static_cast<T>(number))) {
        return value.is_number_integer() ? value.template get<T>() : static_cast<T>(number);
      }
    }
  } else if constexpr (std::is_floating_point_v<T>) {
    if (value.is_number()) return value.template get<T>();
  } else {
    if (value.is_string()) return value.template get<T>();
  }
  return std::nullopt;
}

// The value of `key` in a parameter object (a graph's "params" or a plan pass's params),
// or nullopt when it is absent or not of type T.
template <class T>
std::optional<T> read_param(const Json& params, ParamKey<T> key) {
  const auto it = params.find(key.name);
  return it == params.end() ? std::nullopt : json_as<T>(*it);
}

}  // namespace antumbra::base
