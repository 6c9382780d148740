#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "antumbra/base/param_key.hpp"
#include "antumbra/fg/param_table.hpp"

namespace antumbra::fg {
namespace {

enum class Mode : std::uint8_t { fast, exact };

struct Shared {
  float scale = 0.0f;
};

struct Params {
  float exposure = 0.0f;
  std::uint32_t taps = 0;
  bool cache = false;
  Mode mode = Mode::fast;
  std::string label;
  Shared shared;
};

const ParamTable<Shared>& shared_table() {
  static const auto kTable = ParamTable<Shared>().add(
      {.name = "scale", .type = ParamType::number, .default_value = 2.0, .min = 0.0, .max = 4.0},
      &Shared::scale);
  return kTable;
}

ParamTable<Params> table() {
  return ParamTable<Params>()
      .add({.name = "exposure",
            .type = ParamType::number,
            .default_value = 1.5,
            .min = 0.0,
            .max = 16.0},
           &Params::exposure)
      .add(
          {.name = "taps", .type = ParamType::integer, .default_value = 5, .min = 1.0, .max = 23.0},
          &Params::taps)
      .add({.name = "cache", .type = ParamType::boolean, .default_value = true}, &Params::cache)
      .choice({.name = "mode",
               .type = ParamType::enumeration,
               .default_value = "exact",
               .choices = {"fast", "exact"}},
              &Params::mode, {Mode::fast, Mode::exact})
      .add({.name = "label", .type = ParamType::string, .default_value = "x"}, &Params::label)
      .include(&Params::shared, shared_table());
}

TEST(ParamTable, DescribesEveryRowInOrder) {
  const auto descs = table().descs();
  ASSERT_EQ(descs.size(), 6u);
  EXPECT_EQ(descs[0].name, "exposure");
  EXPECT_EQ(descs[3].choices, (std::vector<std::string>{"fast", "exact"}));
  EXPECT_EQ(descs[5].name, "scale");
}

TEST(ParamTable, DefaultsFillEveryMember) {
  const Params p = table().defaults();
  EXPECT_FLOAT_EQ(p.exposure, 1.5f);
  EXPECT_EQ(p.taps, 5u);
  EXPECT_TRUE(p.cache);
  EXPECT_EQ(p.mode, Mode::exact);
  EXPECT_EQ(p.label, "x");
  EXPECT_FLOAT_EQ(p.shared.scale, 2.0f);
}

TEST(ParamTable, ReadsAPlanPassValues) {
  const Json params = {{"exposure", 3},  {"taps", 7.0},  {"cache", false},
                       {"mode", "fast"}, {"label", "y"}, {"scale", 0.5}};
  const Params p = table().read(params);
  EXPECT_FLOAT_EQ(p.exposure, 3.0f);
  EXPECT_EQ(p.taps, 7u);
  EXPECT_FALSE(p.cache);
  EXPECT_EQ(p.mode, Mode::fast);
  EXPECT_EQ(p.label, "y");
  EXPECT_FLOAT_EQ(p.shared.scale, 0.5f);
}

TEST(ParamTable, AValueOfTheWrongTypeIsAnErrorNeverAZero) {
  EXPECT_THROW((void)table().read(Json{{"exposure", "bright"}}), std::logic_error);
  EXPECT_THROW((void)table().read(Json{{"taps", 2.5}}), std::logic_error);
  EXPECT_THROW((void)table().read(Json{{"mode", "slow"}}), std::logic_error);
}

TEST(ParamTable, ARowThatContradictsItselfThrowsWhenTheTableIsBuilt) {
  struct P {
    float f = 0.0f;
    int i = 0;
    Mode m = Mode::fast;
  };
  const auto out_of_range = [] {
    (void)ParamTable<P>().add(
        {.name = "f", .type = ParamType::number, .default_value = 9.0, .min = 0.0, .max = 1.0},
        &P::f);
  };
  const auto wrong_type = [] {
    (void)ParamTable<P>().add({.name = "i", .type = ParamType::number, .default_value = 1}, &P::i);
  };
  const auto twice = [] {
    (void)ParamTable<P>()
        .add({.name = "f", .type = ParamType::number, .default_value = 0.0}, &P::f)
        .add({.name = "f", .type = ParamType::integer, .default_value = 0}, &P::i);
  };
  const auto bad_choice = [] {
    (void)ParamTable<P>().choice({.name = "m",
                                  .type = ParamType::enumeration,
                                  .default_value = "slow",
                                  .choices = {"fast", "exact"}},
                                 &P::m, {Mode::fast, Mode::exact});
  };
  const auto values_mismatch = [] {
    (void)ParamTable<P>().choice({.name = "m",
                                  .type = ParamType::enumeration,
                                  .default_value = "fast",
                                  .choices = {"fast", "exact"}},
                                 &P::m, {Mode::fast});
  };
  EXPECT_THROW(out_of_range(), std::logic_error);
  EXPECT_THROW(wrong_type(), std::logic_error);
  EXPECT_THROW(twice(), std::logic_error);
  EXPECT_THROW(bad_choice(), std::logic_error);
  EXPECT_THROW(values_mismatch(), std::logic_error);
}

// The hooks a pass writes against its typed parameters (ParamTable::check, port_use,
// resolve): the wrappers read the values through the table, so a hook never reads a
// parameter by name.
const ParamTable<Params>& static_table() {
  static const ParamTable<Params> kTable = table();
  return kTable;
}

TEST(ParamTable, TryReadRefusesWhatReadThrowsFor) {
  EXPECT_EQ(static_table().try_read(Json{{"mode", "slow"}}), std::nullopt);
  EXPECT_EQ(static_table().try_read(Json{{"scale", "big"}}), std::nullopt);  // an included row
  const auto p = static_table().try_read(Json{{"mode", "fast"}});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->mode, Mode::fast);
}

TEST(ParamTable, PortUseHooksSeeTypedValuesWithDefaultsFilledIn) {
  const PortUseFn use = static_table().port_use(
      [](const PortDesc&, const Params& p, Format format) -> std::optional<PortUse> {
        if (p.mode != Mode::fast || format != Format::r32f) return std::nullopt;
        return PortUse{Access::storage_write, Stage::compute};
      });
  const PortDesc port{.name = "out"};
  EXPECT_FALSE(use(port, Json::object(), Format::r32f));  // default mode: exact
  const auto fast = use(port, Json{{"mode", "fast"}}, Format::r32f);
  ASSERT_TRUE(fast.has_value());
  EXPECT_EQ(fast->access, Access::storage_write);
}

TEST(ParamTable, ChecksReadThePlanPassValues) {
  const PassCheck check =
      static_table().check([](const PlanPass& pass, const Params& p, const Plan&,
                              const GraphDesc& graph, Diagnostics& diagnostics) {
        if (p.taps > 8) {
          diagnostics.add(graph.document.make("FG999", Severity::error,
                                              pass.name + ": " + std::to_string(p.taps), ""));
        }
      });
  PlanPass pass;
  pass.name = "blur";
  pass.params = Json{{"taps", 9}};
  Diagnostics diagnostics;
  check(pass, Plan{}, GraphDesc{}, diagnostics);
  ASSERT_EQ(diagnostics.items().size(), 1u);
  EXPECT_EQ(diagnostics.items()[0].message, "blur: 9");
}

TEST(ParamTable, ResolveWritesBackOnlyWhatTheHookChangedInTheGraphsWords) {
  const ParamResolveFn resolve =
      static_table().resolve([](Params& p, const PassInstanceDesc&, const GraphDesc&,
                                const DeviceTraits*) -> std::vector<std::string> {
        p.mode = Mode::fast;
        return {"chose fast"};
      });
  PassInstanceDesc pass;
  pass.params = Json{{"taps", 3}};
  EXPECT_EQ(resolve(pass, GraphDesc{}, nullptr), std::vector<std::string>{"chose fast"});
  EXPECT_EQ(pass.params, (Json{{"taps", 3}, {"mode", "fast"}}));  // no defaults written
}

TEST(ParamTable, ResolveLeavesAValueItCannotReadToTheParameterCheck) {
  const ParamResolveFn resolve =
      static_table().resolve([](Params& p, const PassInstanceDesc&, const GraphDesc&,
                                const DeviceTraits*) -> std::vector<std::string> {
        p.taps = 1;
        return {"changed"};
      });
  PassInstanceDesc pass;
  pass.params = Json{{"mode", 7}};
  EXPECT_TRUE(resolve(pass, GraphDesc{}, nullptr).empty());
  EXPECT_EQ(pass.params, (Json{{"mode", 7}}));
}

TEST(ParamKey, ReadsOnlyTheDeclaredType) {
  constexpr base::ParamKey<int> kCap{"maxLayers"};
  EXPECT_EQ(base::read_param(Json{{"maxLayers", 3}}, kCap), 3);
  EXPECT_EQ(base::read_param(Json{{"maxLayers", 2.5}}, kCap), std::nullopt);
  EXPECT_EQ(base::read_param(Json{{"other", 3}}, kCap), std::nullopt);
  EXPECT_EQ(base::read_param(Json{{"maxLayers", "3"}}, kCap), std::nullopt);
}

// A whole number written 6.0 reads as 6 for every reader (the pass's table, the editor's
// and the layer checks' keys), although the compiler refuses it (FG032); values outside
// the C++ type never read.
TEST(ParamKey, WholeNumbersWrittenAsFloatsAreIntegers) {
  constexpr base::ParamKey<int> kCap{"maxLayers"};
  EXPECT_EQ(base::read_param(Json{{"maxLayers", 6.0}}, kCap), 6);
  EXPECT_EQ(base::read_param(Json{{"maxLayers", -2.0}}, kCap), -2);
  EXPECT_EQ(base::read_param(Json{{"maxLayers", 1e12}}, kCap), std::nullopt);  // not an int
  EXPECT_EQ(base::json_as<std::uint8_t>(Json(300)), std::nullopt);
  EXPECT_EQ(base::json_as<std::uint32_t>(Json(-1)), std::nullopt);
  EXPECT_EQ(base::json_as<double>(Json(2)), 2.0);
}

}  // namespace
}  // namespace antumbra::fg
