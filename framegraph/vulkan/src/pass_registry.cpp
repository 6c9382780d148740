#include "antumbra/fgvk/pass_registry.hpp"

#include <stdexcept>

namespace antumbra::fgvk {

void PassRegistry::add(fg::PassDesc desc, PassFactory make) {
  if (make == nullptr) throw std::logic_error("pass type " + desc.type + " has no factory");
  if (reflection_.find(desc.type) != nullptr) {
    throw std::logic_error("pass type " + desc.type + " registered twice");
  }
  factories_.emplace(desc.type, make);
  reflection_.add(std::move(desc));
}

PassFactory PassRegistry::factory(std::string_view type) const {
  auto it = factories_.find(type);
  return it == factories_.end() ? nullptr : it->second;
}

const BoundImage* PassBindings::image(std::string_view port) const {
  for (const auto& e : entries_) {
    if (e.port == port) return e.image;
  }
  return nullptr;
}

const BoundBuffer* PassBindings::buffer(std::string_view port) const {
  for (const auto& e : entries_) {
    if (e.port == port) return e.buffer;
  }
  return nullptr;
}

const BoundImage& PassBindings::required_image(std::string_view port) const {
  const BoundImage* found = image(port);
  if (found == nullptr)
    throw std::logic_error("port " + std::string(port) + " is not bound to an image");
  return *found;
}

}  // namespace antumbra::fgvk
