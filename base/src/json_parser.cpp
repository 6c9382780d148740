// A strict recursive-descent JSON parser that records the position of every value.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/json_document.hpp"

namespace antumbra::base {
namespace {

struct ParseError {
  const char* code;
  std::string message;
  TextPosition position;
  std::string pointer;  // the innermost value being read (a duplicate key: its own)
};

// Length of the UTF-8 sequence starting at s[i], or 0 when it is not valid UTF-8.
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if ((c & 0xE0) == 0xC0) {
    n = 2;
    cp = c & 0x1Fu;
  } else if ((c & 0xF0) == 0xE0) {
    n = 3;
    cp = c & 0x0Fu;
  } else if ((c & 0xF8) == 0xF0) {
    n = 4;
    cp = c & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  // Reject overlong forms, surrogates and code points past U+10FFFF.
  if ((n == 2 && cp < 0x80) || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000)) return 0;
  if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

std::string describe_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7F) return std::string("'") + c + "'";
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", u);
  return buf;
}

class Parser {
 public:
  Parser(std::string_view text, const JsonParseOptions& options) : text_(text), options_(options) {}

  Json parse_document() {
    skip_bom();
    skip_whitespace();
    if (at_end())
      throw ParseError{codes::graph::kJsonEmpty, "the file is empty; expected a JSON value",
                       here()};
    Json root = parse_value("", 0);
    skip_whitespace();
    if (!at_end()) fail("unexpected " + describe_char(peek()) + " after the end of the JSON value");
    return root;
  }

  std::unordered_map<std::string, TextPosition> value_positions;
  std::unordered_map<std::string, TextPosition> key_positions;

 private:
  [[nodiscard]] bool at_end() const { return pos_ >= text_.size(); }
  [[nodiscard]] char peek() const { return text_[pos_]; }
  [[nodiscard]] TextPosition here() const {
    return {line_, static_cast<int>(pos_ - line_start_) + 1};
  }

  std::string where_;  // JSON Pointer of the value being read, for syntax errors

  [[noreturn]] void fail(std::string message) const {
    throw ParseError{codes::graph::kJsonSyntax, std::move(message), here(), where_};
  }

  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      line_start_ = pos_ + 1;
    }
    ++pos_;
  }

  void skip_bom() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      pos_ = 3;
      line_start_ = 3;
    }
  }

  void skip_whitespace() {
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        advance();
      } else if (c == '/' && pos_ + 1 < text_.size() &&
                 (text_[pos_ + 1] == '/' || text_[pos_ + 1] == '*')) {
        fail("comments are not allowed in JSON");
      } else {
        return;
      }
    }
  }

  void expect_literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word)
      fail("invalid literal; expected '" + std::string(word) + "'");
    for (std::size_t i = 0; i < word.size(); ++i) advance();
  }

  Json parse_value(const std::string& pointer, int depth) {
    if (depth > options_.max_depth) {
      throw ParseError{codes::graph::kJsonTooDeep,
                       "nesting deeper than " + std::to_string(options_.max_depth) + " levels",
                       here()};  // no pointer: hundreds of "/0" would bury the message
    }
    // Errors inside point at the innermost value being read; the caller's is restored when
    // this value is done (an error after it belongs to the enclosing object or array).
    const std::string enclosing = std::exchange(where_, pointer);
    Json value = parse_value_at(pointer, depth);
    where_ = enclosing;
    return value;
  }

  Json parse_value_at(const std::string& pointer, int depth) {
    skip_whitespace();
    if (at_end()) fail("unexpected end of file; expected a value");
    value_positions[pointer] = here();
    const char c = peek();
    switch (c) {
      case '{':
        return parse_object(pointer, depth);
      case '[':
        return parse_array(pointer, depth);
      case '"':
        return parse_string();
      case 't':
        expect_literal("true");
        return true;
      case 'f':
        expect_literal("false");
        return false;
      case 'n':
        expect_literal("null");
        return nullptr;
      default:
        if (c == '-' || (c >= '0' && c <= '9')) return parse_number();
        fail("unexpected " + describe_char(c) + "; expected a value");
    }
  }

  Json parse_object(const std::string& pointer, int depth) {
    advance();  // '{'
    Json object = Json::object();
    skip_whitespace();
    if (!at_end() && peek() == '}') {
      advance();
      return object;
    }
    while (true) {
      skip_whitespace();
      if (at_end()) fail("unexpected end of file inside an object; expected '\"' or '}'");
      if (peek() != '"') {
        fail("unexpected " + describe_char(peek()) + "; expected a quoted key" +
             (peek() == '}' ? " (trailing commas are not allowed)" : ""));
      }
      const TextPosition key_pos = here();
      std::string key = parse_string();
      const std::string child = pointer_append(pointer, key);
      if (object.contains(key)) {
        throw ParseError{codes::graph::kJsonDuplicateKey, "duplicate key \"" + key + "\"", key_pos,
                         child};
      }
      key_positions[child] = key_pos;
      skip_whitespace();
      if (at_end() || peek() != ':') fail("expected ':' after the key \"" + key + "\"");
      advance();
      object[key] = parse_value(child, depth + 1);
      skip_whitespace();
      if (at_end()) fail("unexpected end of file inside an object; expected ',' or '}'");
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == '}') {
        advance();
        return object;
      }
      fail("unexpected " + describe_char(peek()) + "; expected ',' or '}'");
    }
  }

  Json parse_array(const std::string& pointer, int depth) {
    advance();  // '['
    Json array = Json::array();
    skip_whitespace();
    if (!at_end() && peek() == ']') {
      advance();
      return array;
    }
    while (true) {
      skip_whitespace();
      if (!at_end() && peek() == ']') fail("unexpected ']'; trailing commas are not allowed");
      array.push_back(parse_value(pointer_append(pointer, array.size()), depth + 1));
      skip_whitespace();
      if (at_end()) fail("unexpected end of file inside an array; expected ',' or ']'");
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == ']') {
        advance();
        return array;
      }
      fail("unexpected " + describe_char(peek()) + "; expected ',' or ']'");
    }
  }

  std::uint32_t parse_hex4() {
    if (pos_ + 4 > text_.size()) fail("truncated \\u escape");
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = peek();
      value <<= 4;
      if (h >= '0' && h <= '9') {
        value |= static_cast<std::uint32_t>(h - '0');
      } else if (h >= 'a' && h <= 'f') {
        value |= static_cast<std::uint32_t>(h - 'a' + 10);
      } else if (h >= 'A' && h <= 'F') {
        value |= static_cast<std::uint32_t>(h - 'A' + 10);
      } else {
        fail("invalid hex digit " + describe_char(h) + " in \\u escape");
      }
      advance();
    }
    return value;
  }

  std::string parse_string() {
    advance();  // opening quote
    std::string out;
    while (true) {
      if (at_end()) fail("unterminated string");
      const char c = peek();
      const auto u = static_cast<unsigned char>(c);
      if (c == '"') {
        advance();
        return out;
      }
      if (u < 0x20) fail("control character " + describe_char(c) + " in a string must be escaped");
      if (c == '\\') {
        advance();
        if (at_end()) fail("unterminated escape sequence");
        const char e = peek();
        advance();
        switch (e) {
          case '"':
            out += '"';
            break;
          case '\\':
            out += '\\';
            break;
          case '/':
            out += '/';
            break;
          case 'b':
            out += '\b';
            break;
          case 'f':
            out += '\f';
            break;
          case 'n':
            out += '\n';
            break;
          case 'r':
            out += '\r';
            break;
          case 't':
            out += '\t';
            break;
          case 'u': {
            std::uint32_t cp = parse_hex4();
            if (cp >= 0xD800 && cp <= 0xDBFF) {
              if (text_.substr(pos_, 2) != "\\u") fail("unpaired UTF-16 surrogate in \\u escape");
              advance();
              advance();
              const std::uint32_t low = parse_hex4();
              if (low < 0xDC00 || low > 0xDFFF) fail("invalid UTF-16 low surrogate in \\u escape");
              cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
              fail("unpaired UTF-16 surrogate in \\u escape");
            }
            append_utf8(out, cp);
            break;
          }
          default:
            fail("invalid escape sequence '\\" + std::string(1, e) + "'");
        }
        continue;
      }
      const std::size_t n = utf8_sequence_length(text_, pos_);
      if (n == 0) {
        throw ParseError{codes::graph::kJsonInvalidUtf8,
                         "invalid UTF-8 byte " + describe_char(c) + " in a string", here()};
      }
      out.append(text_.substr(pos_, n));
      for (std::size_t k = 0; k < n; ++k) advance();
    }
  }

  Json parse_number() {
    const std::size_t start = pos_;
    bool is_integer = true;
    if (peek() == '-') advance();
    if (at_end() || !std::isdigit(static_cast<unsigned char>(peek())))
      fail("invalid number; expected a digit");
    if (peek() == '0') {
      advance();
      if (!at_end() && std::isdigit(static_cast<unsigned char>(peek())))
        fail("numbers must not have leading zeros");
    } else {
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) advance();
    }
    if (!at_end() && peek() == '.') {
      is_integer = false;
      advance();
      if (at_end() || !std::isdigit(static_cast<unsigned char>(peek())))
        fail("invalid number; expected a digit after '.'");
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) advance();
    }
    if (!at_end() && (peek() == 'e' || peek() == 'E')) {
      is_integer = false;
      advance();
      if (!at_end() && (peek() == '+' || peek() == '-')) advance();
      if (at_end() || !std::isdigit(static_cast<unsigned char>(peek())))
        fail("invalid number; expected a digit in the exponent");
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) advance();
    }
    const std::string_view token = text_.substr(start, pos_ - start);
    if (is_integer) {
      if (token[0] == '-') {
        std::int64_t v = 0;
        auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec == std::errc() && p == token.data() + token.size()) return v;
      } else {
        std::uint64_t v = 0;
        auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec == std::errc() && p == token.data() + token.size()) return v;
      }
      // Too large for 64 bits: keep it as a double like other JSON readers do.
    }
    const double d = std::strtod(std::string(token).c_str(), nullptr);
    if (!std::isfinite(d)) fail("number out of range");
    return d;
  }

  std::string_view text_;
  JsonParseOptions options_;
  std::size_t pos_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;
};

}  // namespace

const char* json_type_name(const Json& value) {
  if (value.is_number_integer()) return "integer";
  if (value.is_number()) return "number";
  if (value.is_string()) return "string";
  if (value.is_boolean()) return "boolean";
  if (value.is_array()) return "array";
  if (value.is_object()) return "object";
  return "null";
}

std::string pointer_append(std::string_view pointer, std::string_view token) {
  std::string out(pointer);
  out += '/';
  for (const char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string pointer_append(std::string_view pointer, std::size_t index) {
  return std::string(pointer) + '/' + std::to_string(index);
}

JsonDocument::JsonDocument(std::string file, Json root,
                           std::unordered_map<std::string, TextPosition> value_positions,
                           std::unordered_map<std::string, TextPosition> key_positions)
    : file_(std::move(file)),
      root_(std::move(root)),
      value_positions_(std::move(value_positions)),
      key_positions_(std::move(key_positions)) {
}

TextPosition JsonDocument::position(std::string_view pointer) const {
  std::string p(pointer);
  while (true) {
    if (auto it = value_positions_.find(p); it != value_positions_.end()) return it->second;
    if (p.empty()) return {};
    p.erase(p.rfind('/'));
  }
}

TextPosition JsonDocument::key_position(std::string_view pointer) const {
  if (auto it = key_positions_.find(std::string(pointer)); it != key_positions_.end())
    return it->second;
  return position(pointer);
}

Diagnostic JsonDocument::make(std::string code, Severity severity, std::string message,
                              const std::string& pointer, bool at_key) const {
  const TextPosition pos = at_key ? key_position(pointer) : position(pointer);
  return Diagnostic{std::move(code), severity, std::move(message), file_,
                    pointer,         pos.line, pos.column};
}

namespace {

Diagnostics too_large(const std::string& file, std::uint64_t size, std::uint64_t limit) {
  Diagnostics diagnostics;
  diagnostics.add(Diagnostic{codes::graph::kJsonTooLarge, Severity::error,
                             "the JSON is " + std::to_string(size) +
                                 " bytes; a JSON file may hold at most " + std::to_string(limit) +
                                 " bytes (docs/robustness.md, \"Limits\")",
                             file, "", 0, 0});
  return diagnostics;
}

}  // namespace

Result<JsonDocument> parse_json(std::string_view text, const std::string& file,
                                const JsonParseOptions& options) {
  if (text.size() > options.max_bytes) return too_large(file, text.size(), options.max_bytes);
  Parser parser(text, options);
  try {
    Json root = parser.parse_document();
    return JsonDocument(file, std::move(root), std::move(parser.value_positions),
                        std::move(parser.key_positions));
  } catch (const ParseError& e) {
    Diagnostics diagnostics;
    diagnostics.add(Diagnostic{e.code, Severity::error, e.message, file, e.pointer, e.position.line,
                               e.position.column});
    return diagnostics;
  }
}

Result<JsonDocument> load_json_file(const std::string& path, const JsonParseOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    Diagnostics diagnostics;
    diagnostics.add(Diagnostic{codes::graph::kFileUnreadable, Severity::error,
                               "is a directory; expected a JSON file", path, "", 0, 0});
    return diagnostics;
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    // The OS's reason: a missing file and a file without read permission need different fixes.
    const int reason = errno;
    Diagnostics diagnostics;
    diagnostics.add(Diagnostic{codes::graph::kFileUnreadable, Severity::error,
                               std::string("cannot open the file: ") +
                                   (reason != 0 ? std::strerror(reason) : "unknown reason"),
                               path, "", 0, 0});
    return diagnostics;
  }
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > options.max_bytes) {
    return too_large(path, size, options.max_bytes);
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_json(buffer.str(), path, options);
}

}  // namespace antumbra::base
