#pragma once
// Pass types known to a program: their reflection (the Vulkan-free fg::Registry the
// compiler, validator and schema use) and the factory that makes the runtime pass.

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "antumbra/fg/registry.hpp"
#include "antumbra/fgvk/pass.hpp"

namespace antumbra::fgvk {

// PassRegistry::add of a type name the registry already holds: a host's pass type named
// like a built-in one (docs/adding-a-pass.md, "A pass type from outside the tree").
class DuplicatePassType : public std::invalid_argument {
 public:
  DuplicatePassType(const std::string& type, bool builtin);
  [[nodiscard]] const std::string& type() const { return type_; }

 private:
  std::string type_;
};

class PassRegistry {
 public:
  // Throws DuplicatePassType when `desc.type` is registered already, std::logic_error
  // without a factory, std::invalid_argument for a description that repeats a port or
  // parameter name (fg::Registry::add).
  void add(fg::PassDesc desc, PassFactory make);
  // Marks every type registered so far as built-in (register_builtin_passes() ends with
  // it), so that a later type of the same name is refused as taking a built-in's name.
  void mark_builtin();
  [[nodiscard]] bool builtin(std::string_view type) const { return builtin_.contains(type); }
  [[nodiscard]] const fg::Registry& reflection() const { return reflection_; }
  // nullptr when the type is unknown.
  [[nodiscard]] PassFactory factory(std::string_view type) const;

 private:
  fg::Registry reflection_;
  std::map<std::string, PassFactory, std::less<>> factories_;
  std::set<std::string, std::less<>> builtin_;
};

}  // namespace antumbra::fgvk
