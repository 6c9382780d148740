#include "shader_error_column.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace antumbra::gpu::detail {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t") == std::string::npos;
}

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

struct Lexeme {
  std::size_t start = 0;
  std::string_view text;
};

// The operators of more than one character, longest first, so that "<<=" is one lexeme.
constexpr std::array<std::string_view, 21> kLongOperators = {
    "<<=", ">>=", "<<", ">>", "++", "--", "<=", ">=", "==", "!=", "&&",
    "||",  "^^",  "*=", "/=", "+=", "-=", "%=", "&=", "^=", "|="};

// The end of the number starting at `i`: digits, letters (suffixes, hex, exponents), '.', and
// an exponent's sign.
std::size_t number_end(std::string_view line, std::size_t i) {
  const bool hex = line.substr(i, 2) == "0x" || line.substr(i, 2) == "0X";
  while (i < line.size()) {
    const char c = line[i];
    const bool sign = (c == '+' || c == '-') && !hex && (line[i - 1] == 'e' || line[i - 1] == 'E');
    if (!word_char(c) && c != '.' && !sign) break;
    ++i;
  }
  return i;
}

std::size_t lexeme_end(std::string_view line, std::size_t i) {
  if (word_char(line[i]) && !digit(line[i])) {
    while (i < line.size() && word_char(line[i])) ++i;
    return i;
  }
  if (digit(line[i]) || (line[i] == '.' && i + 1 < line.size() && digit(line[i + 1]))) {
    return number_end(line, i);
  }
  for (std::string_view op : kLongOperators) {
    if (line.substr(i, op.size()) == op) return i + op.size();
  }
  return i + 1;
}

// GLSL's tokens on one line, comments skipped: enough to tell where each token starts.
std::vector<Lexeme> lex_line(std::string_view line) {
  std::vector<Lexeme> lexemes;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ' || line[i] == '\t') {
      ++i;
    } else if (line.substr(i, 2) == "//") {
      break;
    } else if (line.substr(i, 2) == "/*") {
      const auto close = line.find("*/", i + 2);
      i = close == std::string_view::npos ? line.size() : close + 2;
    } else {
      const std::size_t end = lexeme_end(line, i);
      lexemes.push_back({i, line.substr(i, end - i)});
      i = end;
    }
  }
  return lexemes;
}

// glslang's grammar names for punctuation (glslang.y), as written in the source.
constexpr std::array<std::pair<std::string_view, std::string_view>, 45> kPunctuation = {{
    {"LEFT_OP", "<<"},       {"RIGHT_OP", ">>"},    {"INC_OP", "++"},     {"DEC_OP", "--"},
    {"LE_OP", "<="},         {"GE_OP", ">="},       {"EQ_OP", "=="},      {"NE_OP", "!="},
    {"AND_OP", "&&"},        {"OR_OP", "||"},       {"XOR_OP", "^^"},     {"MUL_ASSIGN", "*="},
    {"DIV_ASSIGN", "/="},    {"ADD_ASSIGN", "+="},  {"MOD_ASSIGN", "%="}, {"LEFT_ASSIGN", "<<="},
    {"RIGHT_ASSIGN", ">>="}, {"AND_ASSIGN", "&="},  {"XOR_ASSIGN", "^="}, {"OR_ASSIGN", "|="},
    {"SUB_ASSIGN", "-="},    {"LEFT_PAREN", "("},   {"RIGHT_PAREN", ")"}, {"LEFT_BRACKET", "["},
    {"RIGHT_BRACKET", "]"},  {"LEFT_BRACE", "{"},   {"RIGHT_BRACE", "}"}, {"DOT", "."},
    {"COMMA", ","},          {"COLON", ":"},        {"EQUAL", "="},       {"SEMICOLON", ";"},
    {"BANG", "!"},           {"DASH", "-"},         {"TILDE", "~"},       {"PLUS", "+"},
    {"STAR", "*"},           {"SLASH", "/"},        {"PERCENT", "%"},     {"LEFT_ANGLE", "<"},
    {"RIGHT_ANGLE", ">"},    {"VERTICAL_BAR", "|"}, {"CARET", "^"},       {"AMPERSAND", "&"},
    {"QUESTION", "?"},
}};

bool is_float_literal(std::string_view number) {
  const bool hex = number.size() > 1 && (number[1] == 'x' || number[1] == 'X');
  return !hex && number.find_first_of(".eEfF") != std::string_view::npos;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

// Whether `lexeme` may be a token of the grammar's `kind`. Over-matching only costs a probe;
// keywords are named by their spelling in capitals (VEC4, RETURN, SAMPLER2D).
bool may_be(std::string_view lexeme, std::string_view kind) {
  for (const auto& [name, spelling] : kPunctuation) {
    if (kind == name) return lexeme.substr(0, spelling.size()) == spelling;
  }
  const bool number =
      digit(lexeme.front()) || (lexeme.size() > 1 && lexeme[0] == '.' && digit(lexeme[1]));
  const bool word = word_char(lexeme.front()) && !digit(lexeme.front());
  if (kind == "BOOLCONSTANT") return lexeme == "true" || lexeme == "false";
  if (kind.ends_with("CONSTANT")) {
    const bool floating = kind.find("FLOAT") != std::string_view::npos ||
                          kind.find("DOUBLE") != std::string_view::npos;
    return number && is_float_literal(lexeme) == floating;
  }
  if (kind == "IDENTIFIER" || kind == "TYPE_NAME" || kind == "FIELD_SELECTION") return word;
  return equal_ignoring_case(lexeme, kind);
}

// "syntax error, unexpected RIGHT_PAREN, expecting ..." -> "RIGHT_PAREN"; "" when the message
// names no kind; nullopt when it is not a syntax error.
std::optional<std::string> syntax_error_kind(const std::string& message) {
  if (message.find("syntax error") == std::string::npos) return std::nullopt;
  const std::string_view marker = "unexpected ";
  const auto at = message.find(marker);
  if (at == std::string::npos) return std::string();
  const auto begin = at + marker.size();
  auto end = begin;
  while (end < message.size() && (word_char(message[end]) || message[end] == '$')) ++end;
  return message.substr(begin, end - begin);
}

// The text with line `index` cut at `column` and every later line blanked but for
// preprocessor directives (an #endif must still close its #if). A parse of it reports the
// same syntax error on that line only if the parser stopped before the cut.
std::string cut_at(const std::vector<std::string>& lines, std::size_t index, std::size_t column) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto first = lines[i].find_first_not_of(" \t");
    if (i < index || (i > index && first != std::string::npos && lines[i][first] == '#')) {
      text += lines[i];
    } else if (i == index) {
      text += lines[i].substr(0, column);
    }
    text += '\n';
  }
  return text;
}

// Where on line `index` the parser met the token of `kind` that it could not take. Several
// tokens of that kind: the last one whose cut does not reproduce the error (the error is
// reproduced exactly when the cut comes after that token), by bisection.
std::optional<std::size_t> stopped_at(const std::vector<std::string>& lines, std::size_t index,
                                      const std::string& file, std::string_view kind,
                                      const ErrorProbe& probe) {
  if (kind.starts_with('$') || kind == "end") return std::nullopt;  // the end of the file
  const std::vector<Lexeme> lexemes = lex_line(lines[index]);
  std::vector<std::size_t> starts;
  for (const Lexeme& l : lexemes) {
    if (kind.empty() || may_be(l.text, kind)) starts.push_back(l.start);
  }
  if (starts.empty()) {
    for (const Lexeme& l : lexemes) starts.push_back(l.start);
  }
  if (starts.empty()) return std::nullopt;
  std::size_t low = 0;
  std::size_t high = starts.size() - 1;
  while (low < high) {
    const std::size_t mid = (low + high + 1) / 2;
    if (probe(file, cut_at(lines, index, starts[mid]))) {
      high = mid - 1;
    } else {
      low = mid;
    }
  }
  return starts[low];
}

// The first occurrence of the quoted token on the line: as a whole token, else as text.
std::optional<std::size_t> token_at(const std::string& line, const std::string& token) {
  for (const Lexeme& l : lex_line(line)) {
    if (l.text == token) return l.start;
  }
  const auto at = line.find(token);
  return at == std::string::npos ? std::nullopt : std::optional<std::size_t>(at);
}

std::string quoted_token(const std::string& message) {
  const auto open = message.find('\'');
  const auto close = open == std::string::npos ? open : message.find('\'', open + 1);
  return close == std::string::npos ? std::string() : message.substr(open + 1, close - open - 1);
}

bool unfinished(const std::string& line) {
  const auto last = line.find_last_not_of(" \t");
  return last != std::string::npos && line[last] != ';' && line[last] != '{' && line[last] != '}' &&
         line[line.find_first_not_of(" \t")] != '#' && line.find("//") == std::string::npos;
}

// A syntax error at the first token of a line whose previous non-blank line does not end a
// statement or block is a missing ';' or ')' at the end of that line: points there.
bool point_at_unfinished_line(base::Diagnostic& error, const std::vector<std::string>& lines,
                              std::size_t index, std::size_t column) {
  if (lines[index].find_first_not_of(" \t") != column) return false;
  std::size_t previous = index;
  while (previous > 0 && blank(lines[previous - 1])) --previous;
  if (previous == 0 || !unfinished(lines[previous - 1])) return false;
  const std::string& before = lines[previous - 1];
  error.line = static_cast<int>(previous);
  error.column = static_cast<int>(before.find_last_not_of(" \t") + 2);
  error.message += " (at the end of this line: a missing ';' or ')'?)";
  error.excerpt = before;
  return true;
}

}  // namespace

void locate_in_source(base::Diagnostic& error, const std::string& text, const ErrorProbe& probe) {
  const std::vector<std::string> lines = split_lines(text);
  if (error.line < 1 || error.line > static_cast<int>(lines.size())) return;
  const auto index = static_cast<std::size_t>(error.line - 1);
  const std::string token = quoted_token(error.message);
  const std::optional<std::string> kind = syntax_error_kind(error.message);
  std::optional<std::size_t> column;
  if (!token.empty()) {
    column = token_at(lines[index], token);
  } else if (kind) {
    column = stopped_at(lines, index, error.file, *kind, probe);
  }
  if (kind && column && point_at_unfinished_line(error, lines, index, *column)) return;
  error.excerpt = lines[index];
  if (column) error.column = static_cast<int>(*column) + 1;
}

}  // namespace antumbra::gpu::detail
