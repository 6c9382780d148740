#include "editor_test_support.hpp"

#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace antumbra::editor::testing {

void expect_same_lights(const std::vector<scene::PointLight>& expected,
                        const std::vector<scene::PointLight>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(expected[i].name);
    EXPECT_EQ(expected[i].name, actual[i].name);
    EXPECT_EQ(expected[i].type, actual[i].type);
    EXPECT_EQ(expected[i].position, actual[i].position);
    EXPECT_EQ(expected[i].color, actual[i].color);
    EXPECT_EQ(expected[i].intensity, actual[i].intensity);
    EXPECT_EQ(expected[i].range, actual[i].range);
    EXPECT_EQ(expected[i].size, actual[i].size);
    EXPECT_EQ(expected[i].casts_shadows, actual[i].casts_shadows);
    EXPECT_EQ(expected[i].direction, actual[i].direction);
    EXPECT_EQ(expected[i].spot_outer, actual[i].spot_outer);
    EXPECT_EQ(expected[i].spot_inner, actual[i].spot_inner);
  }
}

std::filesystem::path fixture(const std::string& name) {
  return std::filesystem::path(ANTUMBRA_EDITOR_TEST_DATA) / name;
}

std::filesystem::path source_file(const std::string& relative) {
  return std::filesystem::path(ANTUMBRA_SOURCE_DIR) / relative;
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

ScratchDir::ScratchDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("antumbra-editor-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path ScratchDir::copy(const std::filesystem::path& from,
                                       const std::string& as) const {
  std::filesystem::path to = path_ / (as.empty() ? from.filename().string() : as);
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
  return to;
}

std::vector<std::string> ScratchDir::files() const {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(path_))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {

fg::ParamDesc number(std::string name, double def, double lo, double hi) {
  fg::ParamDesc p;
  p.name = std::move(name);
  p.type = fg::ParamType::number;
  p.default_value = def;
  p.min = lo;
  p.max = hi;
  return p;
}

fg::ParamDesc integer(std::string name, int def, int lo, int hi) {
  fg::ParamDesc p = number(std::move(name), def, lo, hi);
  p.type = fg::ParamType::integer;
  p.default_value = def;
  return p;
}

fg::ParamDesc choice(std::string name, std::string def, std::vector<std::string> choices) {
  fg::ParamDesc p;
  p.name = std::move(name);
  p.type = fg::ParamType::enumeration;
  p.default_value = std::move(def);
  p.choices = std::move(choices);
  return p;
}

fg::PortDesc port(std::string name, fg::PortDirection direction, fg::ResourceKind kind,
                  fg::Access access) {
  fg::PortDesc p;
  p.name = std::move(name);
  p.direction = direction;
  p.kind = kind;
  p.access = access;
  p.stage = fg::Stage::compute;
  return p;
}

fg::PassDesc pass(std::string type, std::vector<fg::ParamDesc> params,
                  std::vector<fg::PortDesc> ports = {}) {
  fg::PassDesc desc;
  desc.type = std::move(type);
  desc.params = std::move(params);
  desc.ports = std::move(ports);
  return desc;
}

constexpr auto kIn = fg::PortDirection::input;
constexpr auto kOut = fg::PortDirection::output;
constexpr auto kImage = fg::ResourceKind::image;
constexpr auto kBuffer = fg::ResourceKind::buffer;

}  // namespace

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The lines of `b` that differ from `a`.
std::vector<std::string> changed_lines(const std::string& a, const std::string& b) {
  const auto la = lines(a);
  const auto lb = lines(b);
  EXPECT_EQ(la.size(), lb.size());
  std::vector<std::string> out;
  for (std::size_t i = 0; i < la.size() && i < lb.size(); ++i) {
    if (la[i] != lb[i]) out.push_back(lb[i]);
  }
  return out;
}

fg::Registry make_fake_registry() {
  fg::Registry registry;
  registry.add(pass("light-layering",
                    {integer("maxLayers", 4, 1, 32),
                     choice("order", "dsatur", {"dsatur", "smallest-last", "largest-first"})},
                    {port("assignment", kOut, kBuffer, fg::Access::storage_write)}));
  registry.add(pass("lighting", {number("ambient", 1.0, 0.0, 4.0)},
                    {port("assignment", kIn, kBuffer, fg::Access::storage_read),
                     port("hdr", kOut, kImage, fg::Access::storage_write)}));
  fg::ParamDesc enabled;
  enabled.name = "enabled";
  enabled.type = fg::ParamType::boolean;
  enabled.default_value = true;
  registry.add(pass("tonemap",
                    {number("exposure", 1.0, 0.0, 16.0),
                     choice("operator", "aces", {"aces", "reinhard", "none"}), enabled},
                    {port("hdr", kIn, kImage, fg::Access::sampled),
                     port("ldr", kOut, kImage, fg::Access::storage_write)}));
  // For the structural edits: an image in and out, and a buffer in to refuse images.
  fg::PortDesc src = port("src", kIn, kImage, fg::Access::sampled);
  src.optional = true;
  fg::PortDesc weights = port("weights", kIn, kBuffer, fg::Access::storage_read);
  weights.optional = true;
  fg::PortDesc dst = port("dst", kOut, kImage, fg::Access::storage_write);
  dst.formats = {fg::Format::rgba16f, fg::Format::rgba8};
  dst.size_of = fg::SizeContract{"src", fg::SizeRelation::same};
  registry.add(pass("blur", {number("radius", 2.0, 0.0, 64.0)}, {src, weights, dst}));
  registry.add(pass("shadow-pcss",
                    {integer("blockerSearch", 5, 1, 16), choice("kernel", "11", {"5", "11", "21"}),
                     number("lightSizeScale", 1.0, 0.0, 8.0)}));
  return registry;
}

}  // namespace antumbra::editor::testing
