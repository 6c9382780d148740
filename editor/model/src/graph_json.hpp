#pragma once
// What the structural graph edits (graph_edits.hpp) share: edits worked out on a copy of
// the document, passes and ports looked up by name with the refusal a wrong name gets,
// unique names, a new resource's defaults and the errors an edit brings.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/editor/edit_history.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/registry.hpp"

namespace antumbra::editor {

// An edit worked out against a copy of the document: refused (why), or the command that
// makes it.
struct GraphEdits::Planned {
  EditResult verdict;
  Command command;
};

namespace detail {

using base::Json;

// The edits of one command, each applied to a working copy as it is added, so that later
// ones see earlier ones (a pass moved with its new binding).
class EditBuilder {
 public:
  explicit EditBuilder(const Json& root) : root_(root) {}
  [[nodiscard]] const Json& root() const { return root_; }
  [[nodiscard]] const std::vector<JsonEdit>& edits() const { return edits_; }

  // Sets (or, with nullopt, removes) a member of the object at `parent`.
  void set(const std::string& parent, const std::string& key, std::optional<Json> value);
  void insert(const std::string& array, std::size_t index, Json element);
  void erase(const std::string& array, std::size_t index);
  // Moves the element at `from` to index `to` (as counted before the move).
  void move(const std::string& array, std::size_t from, std::size_t to);
  // Binds `port` of /passes/<pass> under "in" or "out" (nullopt: unbinds it).
  void bind(std::size_t pass, std::string_view list, const std::string& port,
            std::optional<std::string> resource);

 private:
  void apply(JsonEdit edit);

  Json root_;
  std::vector<JsonEdit> edits_;
  EditHistory scratch_;  // applies each edit exactly as the document's history will
};

// A port found by names, or the refusal a wrong name gets (with a did-you-mean).
struct FoundPort {
  std::size_t pass = 0;  // index in /passes
  const fg::PassDesc* type = nullptr;
  const fg::PortDesc* port = nullptr;
  std::optional<EditResult> refusal;
};
// `direction`: the port must be one (a connection's ends); nullopt: either.
[[nodiscard]] FoundPort find_port(const Json& root, const fg::Registry& registry,
                                  const PortRef& ref,
                                  std::optional<fg::PortDirection> direction = std::nullopt);

// "in" or "out", as the file groups a port's binding.
[[nodiscard]] const char* binding_list(const fg::PortDesc& port);
// The resource bound to `port` of `pass` (a /passes element), empty when none.
[[nodiscard]] std::string bound_resource(const Json& pass, std::string_view list,
                                         std::string_view port);
[[nodiscard]] std::string pass_pointer(std::size_t pass);

// `base` when `taken` says no, else base2, base3, ...
[[nodiscard]] std::string unique_name(const std::string& base,
                                      const std::function<bool(const std::string&)>& taken);

// A new resource for `port` of /passes/<pass>: its kind; an image's format (the port's
// first accepted one, else d32f for depth and rgba16f for colour), size and layers (those
// of the image bound to the port its contracts and size group name, else the viewport and
// the port's minimum); a buffer's size (kDefaultBufferBytes). Named after the port when
// that name is free, else after the pass and the port.
inline constexpr std::uint64_t kDefaultBufferBytes = 65536;
[[nodiscard]] std::pair<std::string, Json> default_resource(const Json& root, std::size_t pass,
                                                            const fg::PortDesc& port,
                                                            const fg::PassDesc& type);

// The errors compiling `root` gives (none when it compiles).
[[nodiscard]] base::Diagnostics compile_errors(const Json& root, const std::string& file,
                                               const fg::Registry& registry,
                                               const fg::CompileOptions& options);
// The first error of `after` that `before` did not have, matched by code and message (an
// edit moves locations): the one an edit brought.
[[nodiscard]] std::optional<base::Diagnostic> new_error(const base::Diagnostics& before,
                                                        const base::Diagnostics& after);

}  // namespace detail
}  // namespace antumbra::editor
