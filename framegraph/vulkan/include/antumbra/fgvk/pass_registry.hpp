#pragma once
// Pass types known to a program: their reflection (the Vulkan-free fg::Registry the
// compiler, validator and schema use) and the factory that makes the runtime pass.

#include <map>
#include <string>
#include <string_view>

#include "antumbra/fg/registry.hpp"
#include "antumbra/fgvk/pass.hpp"

namespace antumbra::fgvk {

class PassRegistry {
 public:
  void add(fg::PassDesc desc, PassFactory make);
  [[nodiscard]] const fg::Registry& reflection() const { return reflection_; }
  // nullptr when the type is unknown.
  [[nodiscard]] PassFactory factory(std::string_view type) const;

 private:
  fg::Registry reflection_;
  std::map<std::string, PassFactory, std::less<>> factories_;
};

}  // namespace antumbra::fgvk
