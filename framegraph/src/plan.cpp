#include "antumbra/fg/plan.hpp"

namespace antumbra::fg {

std::string_view to_string(BarrierSource source) {
  switch (source) {
    case BarrierSource::this_frame:
      return "this_frame";
    case BarrierSource::last_frame:
      return "last_frame";
    case BarrierSource::aliased_memory:
      return "aliased_memory";
    case BarrierSource::imported:
      return "imported";
  }
  return "this_frame";
}

int Plan::find_resource(std::string_view resource_name) const {
  for (std::size_t i = 0; i < resources.size(); ++i) {
    if (resources[i].name == resource_name) return static_cast<int>(i);
  }
  return -1;
}

const PlanPass* Plan::find_pass(std::string_view pass_name) const {
  for (const PlanPass& pass : passes) {
    if (pass.name == pass_name) return &pass;
  }
  return nullptr;
}

}  // namespace antumbra::fg
