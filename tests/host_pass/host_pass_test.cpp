// A host's pass type without a device (docs/adding-a-pass.md, "A pass type from outside the
// tree"): the registry a session with the host's options runs, the schema and the pass
// reference generated from it, graphs validated against it, and the names a host may not
// take.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/fg/schema.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "host_graph.hpp"
#include "host_tint_pass.hpp"

namespace {

namespace base = antumbra::base;
namespace codes = antumbra::codes;
namespace fg = antumbra::fg;
namespace fgvk = antumbra::fgvk;
namespace runtime = antumbra::runtime;
using host_example::HostTintPass;
using host_example::testing::host_options;
using host_example::testing::kTintPass;
using host_example::testing::tinted_graph_text;

constexpr auto kNone = std::string::npos;

base::Result<fg::Plan> compile(const nlohmann::ordered_json& params) {
  static const fgvk::PassRegistry kRegistry = runtime::pass_registry(host_options());
  return fg::compile_graph(fg::GraphSource::from_text(tinted_graph_text(params), "host-tint.json"),
                           kRegistry.reflection());
}

std::unique_ptr<fgvk::Pass> make_tint(const fg::PlanPass& pass) {
  return std::make_unique<HostTintPass>(pass);
}

TEST(HostPassRegistry, TheHostTypeIsRegisteredAfterTheBuiltinOnes) {
  const fgvk::PassRegistry registry = runtime::pass_registry(host_options());
  ASSERT_NE(registry.reflection().find("host-tint"), nullptr);
  EXPECT_NE(registry.factory("host-tint"), nullptr);
  EXPECT_FALSE(registry.builtin("host-tint"));
  EXPECT_NE(registry.reflection().find("tonemap"), nullptr);
  EXPECT_TRUE(registry.builtin("tonemap"));
  // Without the host's registration, the built-in types alone.
  EXPECT_EQ(runtime::pass_registry({}).reflection().find("host-tint"), nullptr);
}

TEST(HostPassRegistry, SchemaAndReferenceDescribeTheHostType) {
  const fgvk::PassRegistry registry = runtime::pass_registry(host_options());
  const base::Json schema = fg::generate_schema(registry.reflection());
  const base::Json& pass = schema.at("$defs").at("pass");
  const base::Json& types = pass.at("properties").at("type").at("enum");
  EXPECT_NE(std::find(types.begin(), types.end(), "host-tint"), types.end());
  const auto& branches = pass.at("allOf");
  const auto branch = std::find_if(branches.begin(), branches.end(), [](const base::Json& b) {
    return b.at("if").at("properties").at("type").at("const") == "host-tint";
  });
  ASSERT_NE(branch, branches.end()) << "no schema branch for host-tint";
  const base::Json& then = branch->at("then").at("properties");
  const base::Json& params = then.at("params").at("properties");
  for (const char* name : {"tintRed", "tintGreen", "tintBlue", "strength"}) {
    ASSERT_TRUE(params.contains(name)) << name;
    EXPECT_EQ(params.at(name).at("type"), "number") << name;
    EXPECT_EQ(params.at(name).at("minimum"), 0.0) << name;
    EXPECT_EQ(params.at(name).at("maximum"), 1.0) << name;
  }
  EXPECT_EQ(params.at("strength").at("default"), 0.5);
  EXPECT_TRUE(then.at("in").at("properties").contains("source"));
  EXPECT_TRUE(then.at("out").at("properties").contains("tinted"));

  const std::string reference = fg::pass_reference_markdown(registry.reflection());
  EXPECT_NE(reference.find("host-tint"), kNone);
  EXPECT_NE(reference.find("tintGreen"), kNone);
}

TEST(HostPassGraph, AGraphWithTheHostTypeValidates) {
  const auto result = compile({{"strength", 1.0}});
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  EXPECT_EQ(result.diagnostics().warning_count(), 0u) << result.diagnostics().to_text();
  const fg::PlanPass* tint = result->find_pass("tint");
  ASSERT_NE(tint, nullptr);
  EXPECT_EQ(tint->type, "host-tint");
  EXPECT_EQ(tint->params.at("strength"), 1.0);
  EXPECT_EQ(tint->params.at("tintGreen"), 0.5);  // the default, filled in
  EXPECT_EQ(result->resources.at(static_cast<std::size_t>(result->output)).name, "tinted");
}

TEST(HostPassGraph, ABadHostParameterIsALocatedDiagnostic) {
  const std::string params = "/passes/" + std::to_string(kTintPass) + "/params/";
  const auto expect_located = [&](const base::Diagnostics& diagnostics, const char* code,
                                  const std::string& pointer, const std::string& words) {
    const base::Diagnostic* d = diagnostics.find(code);
    ASSERT_NE(d, nullptr) << code << " missing from:\n" << diagnostics.to_text();
    EXPECT_EQ(d->severity, base::Severity::error);
    EXPECT_EQ(d->file, "host-tint.json");
    EXPECT_EQ(d->pointer, pointer);
    EXPECT_GT(d->line, 0);
    EXPECT_GT(d->column, 0);
    EXPECT_NE(d->message.find(words), kNone) << d->message;
  };
  const auto range = compile({{"strength", 2.0}});
  EXPECT_FALSE(range.ok());
  expect_located(range.diagnostics(), codes::graph::kParamRange, params + "strength", "strength");
  const auto type = compile({{"tintRed", "red"}});
  EXPECT_FALSE(type.ok());
  expect_located(type.diagnostics(), codes::graph::kParamType, params + "tintRed", "tintRed");
  const auto unknown = compile({{"strenght", 1.0}});
  EXPECT_FALSE(unknown.ok());
  expect_located(unknown.diagnostics(), codes::graph::kUnknownParam, params + "strenght",
                 "did you mean 'strength'");
}

TEST(HostPassRegistry, AHostTypeNamedLikeABuiltinOneIsRefused) {
  runtime::SessionOptions options = host_options();
  options.register_passes = [](fgvk::PassRegistry& registry) {
    fg::PassDesc desc = HostTintPass::describe();
    desc.type = "tonemap";
    registry.add(std::move(desc), &make_tint);
  };
  try {
    static_cast<void>(runtime::pass_registry(options));
    ADD_FAILURE() << "a host's type named 'tonemap' was registered";
  } catch (const fgvk::DuplicatePassType& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.type(), "tonemap");
    EXPECT_NE(what.find("'tonemap' is a built-in pass type"), kNone) << what;
    EXPECT_NE(what.find("a host's pass type needs a name of its own"), kNone) << what;
  }
  EXPECT_THROW(static_cast<void>(runtime::pass_registry(options)), std::invalid_argument);
  // The session propagates it unchanged, before it opens a device.
  EXPECT_THROW(runtime::RenderSession session(runtime::DataPaths{host_example::testing::kSourceDir},
                                              options),
               fgvk::DuplicatePassType);
}

TEST(HostPassRegistry, AHostTypeRegisteredTwiceIsRefused) {
  runtime::SessionOptions options;
  options.register_passes = [](fgvk::PassRegistry& registry) {
    host_example::register_host_passes(registry);
    host_example::register_host_passes(registry);
  };
  try {
    static_cast<void>(runtime::pass_registry(options));
    ADD_FAILURE() << "'host-tint' was registered twice";
  } catch (const fgvk::DuplicatePassType& e) {
    EXPECT_NE(std::string(e.what()).find("'host-tint' is already registered"), kNone) << e.what();
  }
}

}  // namespace
