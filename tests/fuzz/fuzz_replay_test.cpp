// Replays every fuzz target's kept inputs, then seeded mutations of them (docs/robustness.md,
// "Fuzzing"). Under the ASan + UBSan suite a crash, a leak or undefined behaviour fails the
// run; the input being run is written first to a file named at the start of each test, so
// a crash leaves it behind to be kept in fuzz/regressions/<target>/.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mutator.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {
namespace {

namespace fs = std::filesystem;
using testing::Input;

const fs::path kFuzzDir = ANTUMBRA_FUZZ_DIR;
// Mutants per target in one run: a few seconds per target under ASan on a CI core.
// ANTUMBRA_FUZZ_MUTANTS raises it for a longer local run.
constexpr int kDefaultMutants = 4000;

int mutant_count() {
  const char* text = std::getenv("ANTUMBRA_FUZZ_MUTANTS");
  return text != nullptr && std::atoi(text) > 0 ? std::atoi(text) : kDefaultMutants;
}

Input read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Input((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The corpus, then the regressions, each folder in name order.
std::vector<fs::path> kept_inputs(std::string_view target) {
  std::vector<fs::path> paths;
  for (const char* folder : {"corpus", "regressions"}) {
    const fs::path dir = kFuzzDir / folder / std::string(target);
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> here;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_regular_file()) here.push_back(entry.path());
    }
    std::sort(here.begin(), here.end());
    paths.insert(paths.end(), here.begin(), here.end());
  }
  return paths;
}

class FuzzReplay : public ::testing::TestWithParam<Target> {
 protected:
  // Writes `input` where a crash leaves it, then runs the target on it.
  void run(const Input& input) {
    {
      std::ofstream out(last_input_, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(input.data()),
                static_cast<std::streamsize>(input.size()));
    }
    GetParam().run(Bytes(input.data(), input.size()));
  }

  void SetUp() override {
    last_input_ = fs::temp_directory_path() /
                  ("antumbra-fuzz-replay-" + std::string(GetParam().name) + ".last");
    std::printf("a crash leaves its input in %s\n", last_input_.string().c_str());
  }

  fs::path last_input_;
};

TEST_P(FuzzReplay, HasACorpusAndADictionary) {
  const std::string name(GetParam().name);
  EXPECT_FALSE(kept_inputs(name).empty()) << "no inputs in fuzz/corpus/" << name;
  EXPECT_FALSE(testing::read_dictionary(kFuzzDir / "dict" / (name + ".dict")).empty())
      << "no tokens in fuzz/dict/" << name << ".dict";
}

TEST_P(FuzzReplay, KeptInputsEndInAResultOrDiagnostics) {
  for (const fs::path& path : kept_inputs(GetParam().name)) {
    SCOPED_TRACE(path.string());
    run(read_file(path));
  }
}

TEST_P(FuzzReplay, SeededMutantsEndInAResultOrDiagnostics) {
  std::vector<Input> seeds;
  for (const fs::path& path : kept_inputs(GetParam().name)) seeds.push_back(read_file(path));
  ASSERT_FALSE(seeds.empty());
  const std::string name(GetParam().name);
  testing::Mutator mutator(0xA5u + static_cast<std::uint32_t>(name.size()),
                           testing::read_dictionary(kFuzzDir / "dict" / (name + ".dict")));
  const int mutants = mutant_count();
  for (int i = 0; i < mutants; ++i) {
    const Input& base = seeds[static_cast<std::size_t>(i) % seeds.size()];
    const Input& other = seeds[static_cast<std::size_t>(i * 7 + 3) % seeds.size()];
    run(mutator.mutate(base, other));
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         ::testing::ValuesIn(targets().begin(), targets().end()),
                         [](const ::testing::TestParamInfo<Target>& param) {
                           std::string name(param.param.name);
                           std::erase(name, '-');
                           return name;
                         });

TEST(FuzzTargets, EveryTargetIsFoundByName) {
  for (const Target& t : targets()) EXPECT_EQ(find_target(t.name), &t);
  EXPECT_EQ(find_target("no-such-target"), nullptr);
}

}  // namespace
}  // namespace antumbra::fuzz
