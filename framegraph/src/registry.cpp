#include "antumbra/fg/registry.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>

namespace antumbra::fg {

namespace {

// A contract names another image port of the same type: a typo in a description would
// otherwise make the compiler skip the check as if that port were unbound.
void check_contracts(const PassDesc& desc) {
  for (const auto& port : desc.ports) {
    for (const std::string* other : {port.size_of ? &port.size_of->port : nullptr,
                                     port.layers_of ? &port.layers_of->port : nullptr}) {
      if (other == nullptr) continue;
      const PortDesc* target = desc.find_port(*other);
      if (target == nullptr || target == &port || target->kind != ResourceKind::image ||
          port.kind != ResourceKind::image) {
        throw std::invalid_argument("pass type '" + desc.type + "': port '" + port.name +
                                    "' states a contract against '" + *other +
                                    "', which is not another image port of the type");
      }
    }
  }
}

}  // namespace

void Registry::add(PassDesc desc) {
  if (desc.type.empty()) throw std::invalid_argument("pass type without a name");
  std::set<std::string, std::less<>> seen;
  for (const auto& port : desc.ports) {
    if (!seen.insert(port.name).second) {
      throw std::invalid_argument("pass type '" + desc.type + "' repeats port '" + port.name + "'");
    }
  }
  check_contracts(desc);
  seen.clear();
  for (const auto& param : desc.params) {
    if (!seen.insert(param.name).second) {
      throw std::invalid_argument("pass type '" + desc.type + "' repeats param '" + param.name +
                                  "'");
    }
  }
  std::string type = desc.type;
  if (!passes_.emplace(type, std::move(desc)).second) {
    throw std::invalid_argument("pass type '" + type + "' registered twice");
  }
}

const PassDesc* Registry::find(std::string_view type) const {
  auto it = passes_.find(type);
  return it == passes_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::types() const {
  std::vector<std::string> out;
  out.reserve(passes_.size());
  for (const auto& [name, desc] : passes_) out.push_back(name);
  return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Case-insensitive: "Exposure" for "exposure" is the same typo class as a swap.
  const auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1])) {
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
      }
    }
    prev2.swap(prev);
    prev.swap(cur);
  }
  return prev[m];
}

std::optional<std::string> suggest(std::string_view name,
                                   const std::vector<std::string>& candidates) {
  // Allow roughly one edit per three characters, at least one and at most three.
  const std::size_t limit = std::clamp<std::size_t>((name.size() + 2) / 3, 1, 3);
  std::optional<std::string> best;
  std::size_t best_distance = limit + 1;
  for (const auto& candidate : candidates) {
    const std::size_t d = edit_distance(name, candidate);
    if (d < best_distance && d < std::max(name.size(), candidate.size())) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  if (auto s = suggest(name, candidates)) return "; did you mean '" + *s + "'?";
  return "";
}

}  // namespace antumbra::fg
