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
#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/fg/plan.hpp"
#include "antumbra/fg/reflection.hpp"

namespace antumbra::fg {

template <class P>
class ParamTable {
 public:
  // A boolean, number, integer or string parameter stored in `member`.
  template <class T>
  ParamTable& add(ParamDesc desc, T P::*member) {
    check_row<T>(desc);
    rows_.push_back({std::move(desc),
                     [member](P& out, const Json& value) {
                       auto converted = base::json_as<T>(value);
                       if (!converted) return false;
                       out.*member = *std::move(converted);
                       return true;
                     },
                     [member](const P& in) { return Json(in.*member); }});
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
    auto assign = [member, choices, values](P& out, const Json& value) {
      const auto text = base::json_as<std::string>(value);
      const auto it = text ? std::find(choices.begin(), choices.end(), *text) : choices.end();
      if (it == choices.end()) return false;
      out.*member = values[static_cast<std::size_t>(it - choices.begin())];
      return true;
    };
    auto store = [member, name, choices = std::move(choices),
                  values = std::move(values)](const P& in) -> Json {
      const auto it = std::find(values.begin(), values.end(), in.*member);
      if (it == values.end()) fail(name, "holds a value that is none of its choices");
      return choices[static_cast<std::size_t>(it - values.begin())];
    };
    rows_.push_back({std::move(desc), std::move(assign), std::move(store)});
    return *this;
  }

  // Every row of `table`, stored in the sub-struct `member` (parameters several passes
  // share, such as the lighting terms).
  template <class S>
  ParamTable& include(S P::*member, const ParamTable<S>& table) {
    for (std::size_t i = 0; i < table.descs_size(); ++i) {
      rows_.push_back({table.desc(i),
                       [member, &table, i](P& out, const Json& value) {
                         return table.try_assign(i, out.*member, value);
                       },
                       [member, &table, i](const P& in) { return table.store(i, in.*member); }});
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
  // a parameter that is absent takes its default. Throws when a value does not fit its
  // row: the compiler has checked a plan's parameters, so that is a broken invariant.
  [[nodiscard]] P read(const Json& params) const {
    P out{};
    for (const auto& row : rows_) {
      const Json& value = value_in(params, row.desc);
      if (!row.assign(out, value)) fail(row.desc.name, "value " + value.dump() + " does not fit");
    }
    return out;
  }
  // As read(), or nothing when a value does not fit: for a graph's own "params" before the
  // compiler has checked them (PassDesc::resolve runs first; the check reports the value).
  [[nodiscard]] std::optional<P> try_read(const Json& params) const {
    P out{};
    for (const auto& row : rows_) {
      if (!row.assign(out, value_in(params, row.desc))) return std::nullopt;
    }
    return out;
  }
  [[nodiscard]] P defaults() const { return read(Json::object()); }

  // The parameters of `values` that differ from those of `before`, as JSON members
  // written into `params` (what a resolve hook chose, in the graph's own words).
  void write_changes(const P& before, const P& values, Json& params) const {
    for (const auto& row : rows_) {
      Json now = row.store(values);
      if (now != row.store(before)) params[row.desc.name] = std::move(now);
    }
  }

  [[nodiscard]] std::size_t descs_size() const { return rows_.size(); }
  [[nodiscard]] const ParamDesc& desc(std::size_t i) const { return rows_[i].desc; }
  [[nodiscard]] bool try_assign(std::size_t i, P& out, const Json& value) const {
    return rows_[i].assign(out, value);
  }
  [[nodiscard]] Json store(std::size_t i, const P& in) const { return rows_[i].store(in); }

  // The pass's hooks (PassDesc::check, port_use, resolve) written against its typed
  // parameters: the wrappers read them through this table, so no hook reads a parameter
  // by name (docs/architecture.md, "Passes"). The table must outlive the PassDesc: passes
  // keep theirs in a function-local static.
  using TypedCheck = void (*)(const PlanPass& pass, const P& params, const Plan& plan,
                              const GraphDesc& graph, Diagnostics& diagnostics);
  using TypedPortUse = std::optional<PortUse> (*)(const PortDesc& port, const P& params,
                                                  Format format);
  using TypedResolve = std::vector<std::string> (*)(P& params, const PassInstanceDesc& pass,
                                                    const GraphDesc& graph,
                                                    const DeviceTraits* device);

  [[nodiscard]] PassCheck check(TypedCheck fn) const {
    return [this, fn](const PlanPass& pass, const Plan& plan, const GraphDesc& graph,
                      Diagnostics& diagnostics) {
      fn(pass, read(pass.params), plan, graph, diagnostics);
    };
  }
  [[nodiscard]] PortUseFn port_use(TypedPortUse fn) const {
    return [this, fn](const PortDesc& port, const Json& params, Format format) {
      return fn(port, read(params), format);
    };
  }
  // A parameter the graph sets to a value the hook cannot read is left alone: the
  // compiler's parameter check reports it.
  [[nodiscard]] ParamResolveFn resolve(TypedResolve fn) const {
    return [this, fn](PassInstanceDesc& pass, const GraphDesc& graph,
                      const DeviceTraits* device) -> std::vector<std::string> {
      const Json& given = pass.params;
      const std::optional<P> before = try_read(given.is_object() ? given : Json::object());
      if (!before) return {};
      P values = *before;
      std::vector<std::string> lines = fn(values, pass, graph, device);
      Json& params = pass.params;
      if (!params.is_object()) params = Json::object();
      write_changes(*before, values, params);
      return lines;
    };
  }

 private:
  struct Row {
    ParamDesc desc;
    std::function<bool(P&, const Json&)> assign;  // false: the value does not fit the row
    std::function<Json(const P&)> store;
  };

  static const Json& value_in(const Json& params, const ParamDesc& desc) {
    const auto it = params.find(desc.name);
    return it != params.end() ? *it : desc.default_value;
  }

  [[noreturn]] static void fail(const std::string& name, const std::string& what) {
    throw std::logic_error("parameter '" + name + "': " + what);
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
    if (!base::json_as<T>(desc.default_value)) fail(desc.name, "its default does not fit its type");
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
