#pragma once
// A small seeded mutator for the replay suite: libFuzzer's cheapest moves (bit flips,
// interesting bytes, deletions, duplications, dictionary tokens, splices with another
// input), with no coverage feedback. Deterministic for a seed, so a failure names an input
// that can be written out and replayed.

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace antumbra::fuzz::testing {

using Input = std::vector<std::uint8_t>;

// The tokens of a libFuzzer dictionary file: one "..." per line (optionally name="..."),
// with \\, \" and \xNN escapes; comments (#) and blank lines skipped.
std::vector<Input> read_dictionary(const std::filesystem::path& path);

class Mutator {
 public:
  Mutator(std::uint32_t seed, std::vector<Input> dictionary);
  // `base` changed by one to four moves; `other` is the splice partner.
  Input mutate(const Input& base, const Input& other);

 private:
  void one_move(Input& data, const Input& other);
  std::size_t position(const Input& data, bool past_end);

  std::mt19937 random_;
  std::vector<Input> dictionary_;
};

}  // namespace antumbra::fuzz::testing
