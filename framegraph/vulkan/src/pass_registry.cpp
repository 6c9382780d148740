#include "antumbra/fgvk/pass_registry.hpp"

#include <stdexcept>

namespace antumbra::fgvk {

DuplicatePassType::DuplicatePassType(const std::string& type, bool builtin)
    : std::invalid_argument(
          "pass type '" + type + "' is " +
          (builtin ? "a built-in pass type" : "already registered") +
          "; a host's pass type needs a name of its own (docs/adding-a-pass.md, \"A pass type "
          "from outside the tree\")"),
      type_(type) {
}

void PassRegistry::add(fg::PassDesc desc, PassFactory make) {
  if (reflection_.find(desc.type) != nullptr)
    throw DuplicatePassType(desc.type, builtin(desc.type));
  if (make == nullptr) throw std::logic_error("pass type " + desc.type + " has no factory");
  const std::string type = desc.type;
  reflection_.add(std::move(desc));  // may refuse the description: then nothing is added
  factories_.emplace(type, make);
}

void PassRegistry::mark_builtin() {
  for (const auto& [type, make] : factories_) builtin_.insert(type);
}

PassFactory PassRegistry::factory(std::string_view type) const {
  auto it = factories_.find(type);
  return it == factories_.end() ? nullptr : it->second;
}

const PassBindings::Entry& PassBindings::entry(fg::PortId port) const {
  for (const auto& e : entries_) {
    if (e.port == port.name()) return e;
  }
  throw std::logic_error("port " + std::string(port) + " is not a port of this pass");
}

void FrameReport::replace(PassMessage message) {
  for (auto& m : messages_) {
    if (m.pass == message.pass && m.code == message.code) {
      m = std::move(message);
      return;
    }
  }
  messages_.push_back(std::move(message));
}

const BoundImage* PassBindings::image(fg::PortId port) const {
  return entry(port).image;
}

const BoundBuffer* PassBindings::buffer(fg::PortId port) const {
  return entry(port).buffer;
}

const BoundImage& PassBindings::required_image(fg::PortId port) const {
  const BoundImage* found = image(port);
  if (found == nullptr)
    throw std::logic_error("port " + std::string(port) + " is not bound to an image");
  return *found;
}

}  // namespace antumbra::fgvk
