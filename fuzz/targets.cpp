#include "targets.hpp"

#include <array>

namespace antumbra::fuzz {
namespace {

constexpr std::array kTargets{
    Target{"graph", graph}, Target{"scene", scene},
    Target{"gltf", gltf},   Target{"edit-script", edit_script},
    Target{"pfm", pfm},     Target{"png", png},
};

}  // namespace

std::span<const Target> targets() {
  return kTargets;
}

const Target* find_target(std::string_view name) {
  for (const Target& t : kTargets) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

}  // namespace antumbra::fuzz
