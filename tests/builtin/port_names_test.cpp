// Port names are constants shared by a pass's description and its runtime (fg::PortId,
// passes/common/ports.hpp): the runtime's lookups take nothing else, so a misspelt port
// does not compile, and a port the pass never declared is a logic error, not a silent
// "unbound".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "antumbra/fgvk/pass.hpp"
#include "common/ports.hpp"
#include "register_builtin_passes.hpp"

namespace antumbra::passes {
namespace {

template <class Bindings>
concept LooksUpByString = requires(const Bindings& b) {
  b.image("depth");
};
static_assert(!LooksUpByString<fgvk::PassBindings>, "port lookups must take an fg::PortId");
static_assert(!std::is_convertible_v<const char*, fg::PortId>);

TEST(PortNames, BindingsAnswerDeclaredPortsAndRefuseOthers) {
  fgvk::BoundImage depth;
  depth.extent = {4, 4};
  const fgvk::PassBindings bindings({{"depth", &depth, nullptr}, {"shadowData", nullptr, nullptr}});
  EXPECT_EQ(bindings.image(port::kDepth), &depth);
  EXPECT_EQ(&bindings.required_image(port::kDepth), &depth);
  EXPECT_EQ(bindings.buffer(port::kShadowData), nullptr);  // declared, optional, unbound
  EXPECT_THROW((void)bindings.required_image(port::kShadowData), std::logic_error);
  EXPECT_THROW((void)bindings.image(port::kAtlas), std::logic_error);  // not declared
  EXPECT_THROW((void)bindings.buffer(port::kLayerTable), std::logic_error);
}

// The constants as ports.hpp declares them (`inline constexpr fg::PortId kX{"name"};`),
// read from the header itself: a new port is one line there and no list here to extend.
std::set<std::string> declared_port_names() {
  std::ifstream in(std::filesystem::path(ANTUMBRA_SOURCE_DIR) / "passes" / "common" / "ports.hpp");
  std::stringstream text;
  text << in.rdbuf();
  const std::regex constant(R"re(inline constexpr fg::PortId k\w+\{"(\w+)"\};)re");
  std::set<std::string> names;
  const std::string source = text.str();
  for (std::sregex_iterator it(source.begin(), source.end(), constant), end; it != end; ++it) {
    names.insert((*it)[1].str());
  }
  return names;
}

// Every built-in port is one of the constants, so descriptions cannot name a port the
// runtime has no constant for.
TEST(PortNames, EveryBuiltinPortIsAConstant) {
  const std::set<std::string> constants = declared_port_names();
  EXPECT_TRUE(constants.contains(std::string(port::kDepth)) &&
              constants.contains(std::string(port::kPeeled)))
      << "ports.hpp was not read as expected";
  const auto registry = builtin_pass_registry();
  int ports = 0;
  for (const auto& [type, desc] : registry.reflection().passes()) {
    for (const auto& p : desc.ports) {
      EXPECT_TRUE(constants.contains(p.name)) << desc.type << " port " << p.name;
      ++ports;
    }
  }
  EXPECT_GT(ports, 40);
}

}  // namespace
}  // namespace antumbra::passes
