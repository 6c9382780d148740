#include "mutator.hpp"

#include <algorithm>
#include <array>
#include <fstream>

namespace antumbra::fuzz::testing {
namespace {

constexpr std::size_t kMaxInput = 1 << 20;  // mutants stay small: the suite is bounded

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The token between the first and the last quote of a dictionary line, unescaped.
bool parse_token(const std::string& line, Input& token) {
  const auto open = line.find('"');
  const auto close = line.rfind('"');
  if (open == std::string::npos || close <= open) return false;
  token.clear();
  for (std::size_t i = open + 1; i < close; ++i) {
    char c = line[i];
    if (c == '\\' && i + 1 < close) {
      const char next = line[++i];
      if (next == 'x' && i + 2 < close && hex_digit(line[i + 1]) >= 0 &&
          hex_digit(line[i + 2]) >= 0) {
        c = static_cast<char>(hex_digit(line[i + 1]) * 16 + hex_digit(line[i + 2]));
        i += 2;
      } else {
        c = next;
      }
    }
    token.push_back(static_cast<std::uint8_t>(c));
  }
  return true;
}

}  // namespace

std::vector<Input> read_dictionary(const std::filesystem::path& path) {
  std::vector<Input> tokens;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    Input token;
    if (parse_token(line, token) && !token.empty()) tokens.push_back(std::move(token));
  }
  return tokens;
}

Mutator::Mutator(std::uint32_t seed, std::vector<Input> dictionary)
    : random_(seed), dictionary_(std::move(dictionary)) {
}

std::size_t Mutator::position(const Input& data, bool past_end) {
  const std::size_t n = data.size() + (past_end ? 1 : 0);
  if (n == 0) return 0;
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
}

void Mutator::one_move(Input& data, const Input& other) {
  static constexpr std::array<std::uint8_t, 12> kInteresting{0x00, 0x01, 0x7F, 0x80, 0xFF, '"',
                                                             '{',  '[',  '-',  '9',  'e',  '.'};
  const int move = std::uniform_int_distribution<int>(0, 6)(random_);
  if (data.empty() && move < 4) {
    data.push_back(kInteresting[position(Input(kInteresting.size()), false)]);
    return;
  }
  switch (move) {
    case 0:  // flip a bit
      data[position(data, false)] ^= static_cast<std::uint8_t>(1u << (random_() % 8));
      break;
    case 1:  // an interesting byte
      data[position(data, false)] = kInteresting[random_() % kInteresting.size()];
      break;
    case 2: {  // delete a span
      const std::size_t at = position(data, false);
      const std::size_t n = std::min<std::size_t>(data.size() - at, 1 + random_() % 16);
      data.erase(data.begin() + static_cast<std::ptrdiff_t>(at),
                 data.begin() + static_cast<std::ptrdiff_t>(at + n));
      break;
    }
    case 3: {  // duplicate a span in place (repeated keys, nested brackets, long numbers)
      const std::size_t at = position(data, false);
      const std::size_t n = std::min<std::size_t>(data.size() - at, 1 + random_() % 64);
      const Input span(data.begin() + static_cast<std::ptrdiff_t>(at),
                       data.begin() + static_cast<std::ptrdiff_t>(at + n));
      data.insert(data.begin() + static_cast<std::ptrdiff_t>(at), span.begin(), span.end());
      break;
    }
    case 4:
    case 5: {  // a dictionary token, inserted or written over
      if (dictionary_.empty()) break;
      const Input& token = dictionary_[random_() % dictionary_.size()];
      const std::size_t at = position(data, true);
      if (move == 4 || at + token.size() > data.size()) {
        data.insert(data.begin() + static_cast<std::ptrdiff_t>(at), token.begin(), token.end());
      } else {
        std::copy(token.begin(), token.end(), data.begin() + static_cast<std::ptrdiff_t>(at));
      }
      break;
    }
    default: {  // splice: a prefix of this input, the rest from the other
      if (other.empty()) break;
      const std::size_t cut = position(data, true);
      const std::size_t from = position(other, false);
      data.resize(cut);
      data.insert(data.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
      break;
    }
  }
}

Input Mutator::mutate(const Input& base, const Input& other) {
  Input data = base;
  const int moves = 1 + static_cast<int>(random_() % 4);
  for (int i = 0; i < moves; ++i) one_move(data, other);
  if (data.size() > kMaxInput) data.resize(kMaxInput);
  return data;
}

}  // namespace antumbra::fuzz::testing
