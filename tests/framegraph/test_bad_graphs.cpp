// Table-driven: every fixture in tests/data/graphs/bad/ fails with the code, JSON
// Pointer and line written in bad/expectations.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "test_support.hpp"

namespace antumbra::fg {
namespace {

struct Expectation {
  std::string file;
  std::string code;
  std::string pointer;
  int line = 0;
};

std::vector<Expectation> load_expectations() {
  auto doc = load_json_file(testing::data_path("graphs/bad/expectations.json"));
  if (!doc.ok()) throw std::runtime_error(doc.diagnostics().to_text());
  std::vector<Expectation> out;
  for (const auto& e : doc->root()) {
    out.push_back({e["file"].get<std::string>(), e["code"].get<std::string>(),
                   e["pointer"].get<std::string>(), e["line"].get<int>()});
  }
  return out;
}

class BadGraph : public ::testing::TestWithParam<Expectation> {};

TEST_P(BadGraph, FailsWithExpectedDiagnostic) {
  const Expectation& e = GetParam();
  const std::string path = testing::data_path("graphs/bad/" + e.file);
  auto r = compile_file(path, testing::fake_registry());
  ASSERT_FALSE(r.ok()) << e.file << " compiled";
  const Diagnostic* d = r.diagnostics().find(e.code);
  ASSERT_NE(d, nullptr) << e.file << ": no " << e.code << " in\n" << r.diagnostics().to_text();
  EXPECT_EQ(d->severity, Severity::error);
  EXPECT_EQ(d->pointer, e.pointer) << format_text(*d);
  EXPECT_EQ(d->line, e.line) << format_text(*d);
  EXPECT_GT(d->column, 0) << format_text(*d);
  EXPECT_EQ(d->file, path);
  EXPECT_FALSE(d->message.empty());
}

std::string test_name(const ::testing::TestParamInfo<Expectation>& info) {
  std::string name = info.param.file.substr(0, info.param.file.find('.'));
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadGraph, ::testing::ValuesIn(load_expectations()), test_name);

TEST(BadGraphTable, CoversEveryFixture) {
  std::set<std::string> listed;
  for (const auto& e : load_expectations()) listed.insert(e.file);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::data_path("graphs/bad"))) {
    const std::string name = entry.path().filename().string();
    if (name == "expectations.json" || entry.path().extension() != ".json") continue;
    ++files;
    EXPECT_TRUE(listed.count(name)) << name << " has no expectation";
  }
  EXPECT_EQ(files, listed.size());
  EXPECT_GE(files, 30u);
}

}  // namespace
}  // namespace antumbra::fg
