#pragma once
// A pass's parameters declared once: each row of a ParamTable names a member of the
// pass's parameter struct beside the parameter's reflection (name, type, default, range,
// description). describe() publishes descs(); the pass reads its values once with read().
// So the name a graph file uses and the member the pass reads cannot drift apart, and a
// misspelt member is a build error; a row whose default does not fit its own type, range
// or choices throws when the table is built (at start-up, and in the registry test).

#include <algorithm>
#include <concepts>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "antumbra/base/param_key.hpp"
#include "antumbra/fg/reflection.hpp"

namespace antumbra::fg {

template <class P>
class ParamTable {
 public:
  // A boolean, number, integer or string parameter stored in `member`.
  template <class T>
  ParamTable& add(ParamDesc desc, T P::*member) {
    check_row<T>(desc);
    const std::string name = desc.name;
    rows_.push_back({std::move(desc), [member, name](P& out, const Json& value) {
                       out.*member = convert<T>(name, value);
                     }});
    return *this;
  }

  // An enumeration stored as a C++ value: `values[i]` stands for `desc.choices[i]`; when
  // the row lists no choices, they are the values' names by to_string(value).
  template <class E>
  ParamTable& choice(ParamDesc desc, E P::*member, std::vector<E> values) {
    if constexpr (requires(E value) { to_string(value); }) {
      if (desc.choices.empty()) {
        for (const E value : values) desc.choices.emplace_back(to_string(value));
      }
    }
    if (desc.type != ParamType::enumeration || values.size() != desc.choices.size())
      fail(desc.name, "an enumeration needs one value per choice");
    check_row<std::string>(desc);
    const std::string name = desc.name;
    auto choices = desc.choices;
    rows_.push_back({std::move(desc), [member, name, choices = std::move(choices),
                                       values = std::move(values)](P& out, const Json& value) {
                       const auto text = convert<std::string>(name, value);
                       for (std::size_t i = 0; i < choices.size(); ++i) {
                         if (choices[i] == text) {
                           out.*member = values[i];
                           return;
                         }
                       }
                       fail(name, "'" + text + "' is not one of its choices");
                     }});
    return *this;
  }

  // Every row of `table`, stored in the sub-struct `member` (parameters several passes
  // share, such as the lighting terms).
  template <class S>
  ParamTable& include(S P::*member, const ParamTable<S>& table) {
    for (std::size_t i = 0; i < table.descs_size(); ++i) {
      rows_.push_back({table.desc(i), [member, &table, i](P& out, const Json& value) {
                         table.assign(i, out.*member, value);
                       }});
    }
    return *this;
  }

  [[nodiscard]] std::vector<ParamDesc> descs() const {
    std::vector<ParamDesc> out;
    out.reserve(rows_.size());
    for (const auto& row : rows_) out.push_back(row.desc);
    return out;
  }

  // The values in `params` (a plan pass's params: every parameter, defaults filled in);
  // a parameter that is absent takes its default.
  [[nodiscard]] P read(const Json& params) const {
    P out{};
    for (const auto& row : rows_) {
      const auto it = params.find(row.desc.name);
      row.assign(out, it != params.end() ? *it : row.desc.default_value);
    }
    return out;
  }
  [[nodiscard]] P defaults() const { return read(Json::object()); }

  [[nodiscard]] std::size_t descs_size() const { return rows_.size(); }
  [[nodiscard]] const ParamDesc& desc(std::size_t i) const { return rows_[i].desc; }
  void assign(std::size_t i, P& out, const Json& value) const { rows_[i].assign(out, value); }

 private:
  struct Row {
    ParamDesc desc;
    std::function<void(P&, const Json&)> assign;
  };

  [[noreturn]] static void fail(const std::string& name, const std::string& what) {
    throw std::logic_error("parameter '" + name + "': " + what);
  }

  template <class T>
  static T convert(const std::string& name, const Json& value) {
    if (auto converted = base::json_as<T>(value)) return *std::move(converted);
    fail(name, "value " + value.dump() + " does not fit its C++ type");
  }

  template <class T>
  void check_row(const ParamDesc& desc) const {
    for (const auto& row : rows_)
      if (row.desc.name == desc.name) fail(desc.name, "declared twice");
    const ParamType expected = std::is_same_v<T, bool>          ? ParamType::boolean
                               : std::is_integral_v<T>          ? ParamType::integer
                               : std::is_floating_point_v<T>    ? ParamType::number
                               : desc.type == ParamType::string ? ParamType::string
                                                                : ParamType::enumeration;
    if (desc.type != expected) fail(desc.name, "its type does not match the member's");
    (void)convert<T>(desc.name, desc.default_value);
    if (desc.default_value.is_number()) {
      const double value = desc.default_value.get<double>();
      if ((desc.min && value < *desc.min) || (desc.max && value > *desc.max))
        fail(desc.name, "its default is outside its range");
    }
    if (desc.type == ParamType::enumeration &&
        std::find(desc.choices.begin(), desc.choices.end(),
                  desc.default_value.get<std::string>()) == desc.choices.end())
      fail(desc.name, "its default is not one of its choices");
  }

  std::vector<Row> rows_;
};

}  // namespace antumbra::fg
