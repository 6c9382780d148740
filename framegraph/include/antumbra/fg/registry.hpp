#pragma once
// The table of pass types the compiler knows, filled explicitly by the application
// (passes/register_builtin_passes.cpp) or by tests with fake passes. No static
// self-registration: whoever builds a registry says what is in it.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fg/reflection.hpp"

namespace antumbra::fg {

class Registry {
 public:
  // Adds a pass type. A duplicate type name is a programming error (throws
  // std::invalid_argument), as is a PassDesc whose ports or params repeat a name.
  void add(PassDesc desc);
  [[nodiscard]] const PassDesc* find(std::string_view type) const;
  [[nodiscard]] std::vector<std::string> types() const;  // sorted by name
  [[nodiscard]] std::size_t size() const { return passes_.size(); }
  [[nodiscard]] const std::map<std::string, PassDesc, std::less<>>& passes() const {
    return passes_;
  }

 private:
  std::map<std::string, PassDesc, std::less<>> passes_;
};

// Edit distance (optimal string alignment, so a swap of two neighbours costs 1).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` when it is close enough to be a plausible typo;
// ties go to the first candidate in the given order.
std::optional<std::string> suggest(std::string_view name,
                                   const std::vector<std::string>& candidates);

// "; did you mean 'x'?" or "" -- appended to "unknown ..." messages.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace antumbra::fg
