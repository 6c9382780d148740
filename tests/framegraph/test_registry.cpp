// Registry and "did you mean".
#include <gtest/gtest.h>

#include <stdexcept>

#include "fake_registry.hpp"

namespace antumbra::fg {
namespace {

TEST(Registry, FindsAndListsSortedTypes) {
  const Registry r = testing::make_fake_registry();
  ASSERT_NE(r.find("gbuffer"), nullptr);
  EXPECT_EQ(r.find("gbuffer")->find_port("depth")->direction, PortDirection::output);
  EXPECT_EQ(r.find("nope"), nullptr);
  const auto types = r.types();
  EXPECT_TRUE(std::is_sorted(types.begin(), types.end()));
  EXPECT_EQ(types.size(), r.size());
}

TEST(Registry, RejectsDuplicates) {
  Registry r;
  r.add(PassDesc{"a", "", {}, {}, false});
  EXPECT_THROW(r.add(PassDesc{"a", "", {}, {}, false}), std::invalid_argument);
  PassDesc twice{"b", "", {}, {}, false};
  twice.ports.resize(2);
  twice.ports[0].name = twice.ports[1].name = "x";
  EXPECT_THROW(r.add(twice), std::invalid_argument);
}

TEST(DidYouMean, EditDistance) {
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("tonemap", "tonemap"), 0u);
  EXPECT_EQ(edit_distance("tonmeap", "tonemap"), 1u);  // swap
  EXPECT_EQ(edit_distance("Exposure", "exposure"), 0u);
}

TEST(DidYouMean, Suggests) {
  const std::vector<std::string> c{"deferred-lighting", "gbuffer", "tonemap"};
  EXPECT_EQ(suggest("gbufer", c), "gbuffer");
  EXPECT_EQ(suggest("tonemapp", c), "tonemap");
  EXPECT_EQ(suggest("deferred-lightning", c), "deferred-lighting");
  EXPECT_EQ(suggest("bloom", c), std::nullopt);
  EXPECT_EQ(suggest("x", {"y"}), std::nullopt);  // replacing everything is no suggestion
  EXPECT_EQ(did_you_mean("hrd", {"hdr", "ldr"}), "; did you mean 'hdr'?");
  EXPECT_EQ(did_you_mean("zzz", {"hdr"}), "");
}

TEST(Reflection, FormatsRoundTrip) {
  for (Format f : all_formats()) EXPECT_EQ(parse_format(to_string(f)), f);
  EXPECT_EQ(parse_format("undefined"), std::nullopt);
  EXPECT_EQ(bytes_per_texel(Format::rgba16f), 8u);
  EXPECT_TRUE(is_depth_format(Format::d16));
  EXPECT_FALSE(is_depth_format(Format::r32f));
  EXPECT_TRUE(is_write(Access::color_attachment));
  EXPECT_TRUE(is_read(Access::storage_read_write));
  EXPECT_FALSE(is_write(Access::sampled));
}

}  // namespace
}  // namespace antumbra::fg
