#include "json_splice.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace antumbra::editor::detail {
namespace {

using base::Json;

// Where a value lies in the text. Members of an object start at their key.
struct Span {
  std::size_t begin = 0;  // the value's first byte
  std::size_t end = 0;    // one past its last
  std::size_t key = 0;    // a member's key (== begin for elements and the root)
  std::vector<Span> children;
};

// Finds the spans of a JSON text that parsed strictly before (JsonDocument), so it only
// checks what it needs to stay in bounds: anything unexpected fails the whole splice.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::optional<Span> root() {
    Span span = value();
    skip_space();
    if (failed_ || pos_ != text_.size()) return std::nullopt;
    return span;
  }

 private:
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }

  bool take(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  void skip_string() {
    ++pos_;  // the opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    if (pos_ >= text_.size()) failed_ = true;
    pos_ = std::min(pos_ + 1, text_.size());
  }

  void skip_scalar() {
    while (pos_ < text_.size() &&
           std::string_view(",]} \t\r\n").find(text_[pos_]) == std::string_view::npos) {
      ++pos_;
    }
  }

  Span value() {
    skip_space();
    Span span{pos_, pos_, pos_, {}};
    if (pos_ >= text_.size()) {
      failed_ = true;
    } else if (text_[pos_] == '{' || text_[pos_] == '[') {
      container(span, text_[pos_] == '{');
    } else if (text_[pos_] == '"') {
      skip_string();
    } else {
      skip_scalar();
    }
    span.end = pos_;
    return span;
  }

  void container(Span& span, bool object) {
    ++pos_;
    const char close = object ? '}' : ']';
    if (take(close)) return;
    while (!failed_) {
      skip_space();
      const std::size_t key = pos_;
      if (object) {
        if (pos_ >= text_.size() || text_[pos_] != '"') break;
        skip_string();
        if (!take(':')) break;
      }
      Span child = value();
      child.key = key;
      span.children.push_back(std::move(child));
      if (take(close)) return;
      if (!take(',')) break;
    }
    failed_ = true;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  bool failed_ = false;
};

bool simple(const Json& value) {
  if (!value.is_structured()) return true;
  return value.is_array() && !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const Json& e) { return !e.is_structured(); });
}

std::string inline_text(const Json& value) {
  if (!value.is_structured() || value.empty()) return value.dump();
  std::string out = value.is_object() ? "{ " : "[";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first) out += ", ";
    first = false;
    if (value.is_object()) out += Json(it.key()).dump() + ": ";
    out += inline_text(it.value());
  }
  return out + (value.is_object() ? " }" : "]");
}

// One member or element of a container being written: an original one (its index in the
// loaded container) or a new one.
struct Piece {
  int original = -1;
  std::string text;
};

constexpr std::size_t kInlineWidth = 100;

class Splicer {
 public:
  explicit Splicer(std::string_view text) : text_(text) {}

  std::string render(const Span& span, const Json& before, const Json& after) {
    const bool same_number = before.is_number() && after.is_number() && before == after;
    if ((before == after && before.type() == after.type()) || same_number) return text(span);
    if (before.is_object() && after.is_object() && before.size() == span.children.size()) {
      return assemble(span, object_pieces(span, before, after), '{', '}');
    }
    if (before.is_array() && after.is_array() && before.size() == span.children.size()) {
      return assemble(span, array_pieces(span, before, after), '[', ']');
    }
    return format_value(after, line_indent(span.begin));
  }

 private:
  [[nodiscard]] std::string text(const Span& span) const {
    return std::string(text_.substr(span.begin, span.end - span.begin));
  }

  // The whitespace that starts the line holding `pos`.
  [[nodiscard]] std::string line_indent(std::size_t pos) const {
    const std::size_t line = text_.rfind('\n', pos == 0 ? 0 : pos - 1);
    const std::size_t start = line == std::string_view::npos ? 0 : line + 1;
    std::size_t end = start;
    while (end < pos && (text_[end] == ' ' || text_[end] == '\t')) ++end;
    return std::string(text_.substr(start, end - start));
  }

  // Where the children of `span` start their lines: the first child's indent when it is
  // alone at the start of its line, else two spaces in from the container's line.
  [[nodiscard]] std::string child_indent(const Span& span) const {
    if (!span.children.empty()) {
      const std::size_t key = span.children.front().key;
      std::string indent = line_indent(key);
      const std::size_t line_start = text_.rfind('\n', key == 0 ? 0 : key - 1);
      if (line_start != std::string_view::npos && line_start + 1 + indent.size() == key)
        return indent;
    }
    return line_indent(span.begin) + "  ";
  }

  // How the value at `span` (`value` in the file) is laid out.
  [[nodiscard]] Layout layout_of(const Span& span, const Json& value) const {
    Layout layout;
    layout.multiline =
        text_.substr(span.begin, span.end - span.begin).find('\n') != std::string_view::npos;
    if (!value.is_structured() || value.size() != span.children.size()) return layout;
    std::size_t i = 0;
    for (auto it = value.begin(); it != value.end(); ++it, ++i) {
      if (!it->is_structured()) continue;
      Layout child = layout_of(span.children[i], *it);
      if (value.is_object()) {
        layout.members.emplace(it.key(), std::move(child));
      } else {
        layout.elements.push_back(std::move(child));
      }
    }
    return layout;
  }

  // The layout a new member or element of `span` follows: its last structured sibling's.
  [[nodiscard]] std::optional<Layout> sibling_layout(const Span& span, const Json& before) const {
    for (std::size_t i = span.children.size(); i-- > 0;) {
      const Json& sibling = before.is_object()
                                ? std::next(before.begin(), static_cast<std::ptrdiff_t>(i)).value()
                                : before[i];
      if (sibling.is_structured()) return layout_of(span.children[i], sibling);
    }
    return std::nullopt;
  }

  std::vector<Piece> object_pieces(const Span& span, const Json& before, const Json& after) {
    const std::string indent = child_indent(span);
    const std::optional<Layout> like = sibling_layout(span, before);
    std::vector<Piece> pieces;
    for (auto it = after.begin(); it != after.end(); ++it) {
      const auto old = before.find(it.key());
      if (old == before.end()) {
        pieces.push_back({-1, Json(it.key()).dump() + ": " +
                                  format_value(it.value(), indent, like ? &*like : nullptr)});
        continue;
      }
      const auto j = static_cast<std::size_t>(std::distance(before.begin(), old));
      const Span& child = span.children[j];
      pieces.push_back(
          {static_cast<int>(j), std::string(text_.substr(child.key, child.begin - child.key)) +
                                    render(child, *old, it.value())});
    }
    return pieces;
  }

  std::vector<Piece> array_pieces(const Span& span, const Json& before, const Json& after);
  std::string assemble(const Span& span, const std::vector<Piece>& pieces, char open, char close);

  std::string_view text_;
};

// Pairs of (before, after) indices of equal elements, in order: a longest common
// subsequence, so elements inserted, removed or moved leave the others untouched.
std::vector<std::pair<std::size_t, std::size_t>> common_elements(const Json& before,
                                                                 const Json& after) {
  const std::size_t n = before.size();
  const std::size_t m = after.size();
  std::vector<std::vector<std::size_t>> lcs(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t k = m; k-- > 0;) {
      lcs[i][k] =
          before[i] == after[k] ? lcs[i + 1][k + 1] + 1 : std::max(lcs[i + 1][k], lcs[i][k + 1]);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0, k = 0; i < n && k < m;) {
    if (before[i] == after[k]) {
      pairs.emplace_back(i++, k++);
    } else if (lcs[i + 1][k] >= lcs[i][k + 1]) {
      ++i;
    } else {
      ++k;
    }
  }
  return pairs;
}

// How much of `a` is still in `b`: equal members of two objects, 1 for two values of one
// scalar type, 0 for nothing in common.
std::size_t likeness(const Json& a, const Json& b) {
  if (a.is_object() && b.is_object()) {
    std::size_t same = 0;
    for (auto it = a.begin(); it != a.end(); ++it) {
      const auto other = b.find(it.key());
      if (other != b.end() && *other == it.value()) ++same;
    }
    return same;
  }
  return a.type() == b.type() && !a.is_structured() ? 1 : 0;
}

// The element of before[from, to) most like `element` (the first of equals), to be edited
// in place into it; nullopt when none has anything in common with it.
std::optional<std::size_t> closest(const Json& before, std::size_t from, std::size_t to,
                                   const Json& element) {
  std::optional<std::size_t> best;
  std::size_t best_score = 0;
  for (std::size_t j = from; j < to; ++j) {
    const std::size_t score = likeness(before[j], element);
    if (score > best_score) {
      best = j;
      best_score = score;
    }
  }
  return best;
}

std::vector<Piece> Splicer::array_pieces(const Span& span, const Json& before, const Json& after) {
  auto pairs = common_elements(before, after);
  pairs.emplace_back(before.size(), after.size());  // a sentinel closing the last run
  const std::string indent = child_indent(span);
  const std::optional<Layout> like = sibling_layout(span, before);
  std::vector<bool> used(before.size(), false);
  for (const auto& [i, k] : pairs) {
    if (i < before.size()) used[i] = true;
  }
  std::vector<Piece> pieces;
  std::size_t i = 0;
  std::size_t k = 0;
  for (const auto& [next_i, next_k] : pairs) {
    // Between two common elements: changed elements pair up in order (edited in place);
    // the rest are new, or moved from elsewhere (their original text reused).
    for (; k < next_k; ++k) {
      if (const auto j = closest(before, i, next_i, after[k])) {
        used[*j] = true;
        pieces.push_back({static_cast<int>(*j), render(span.children[*j], before[*j], after[k])});
        i = *j + 1;
        continue;
      }
      Piece piece{-1, format_value(after[k], indent, like ? &*like : nullptr)};
      for (std::size_t j = 0; j < before.size(); ++j) {
        if (!used[j] && before[j] == after[k]) {
          used[j] = true;
          piece.text = text(span.children[j]);
          break;
        }
      }
      pieces.push_back(std::move(piece));
    }
    if (next_i < before.size())
      pieces.push_back({static_cast<int>(next_i), text(span.children[next_i])});
    i = next_i + 1;
    k = next_k + 1;
  }
  return pieces;
}

// The container with `pieces` between its brackets: the original separator between two
// pieces that were neighbours, else the one that stood before (or after) an original
// piece, else the container's last one; a container that had nothing gets one line for
// short content and a line per piece otherwise.
std::string Splicer::assemble(const Span& span, const std::vector<Piece>& pieces, char open,
                              char close) {
  if (pieces.empty()) return {open, close};
  const auto& children = span.children;
  const std::size_t n = children.size();
  const auto sep = [&](std::size_t j) {
    return std::string(text_.substr(children[j].end, children[j + 1].key - children[j].end));
  };
  if (n == 0) {
    bool fits = true;
    std::size_t width = 0;
    for (const Piece& p : pieces) {
      fits = fits && p.text.find('\n') == std::string::npos;
      width += p.text.size() + 2;
    }
    std::string joined;
    const std::string indent = line_indent(span.begin);
    const bool one_line = fits && width <= kInlineWidth;
    const std::string between = one_line ? ", " : ",\n" + indent + "  ";
    for (const Piece& p : pieces) joined += (joined.empty() ? "" : between) + p.text;
    if (!one_line) return std::string{open} + "\n" + indent + "  " + joined + "\n" + indent + close;
    return open == '{' ? "{ " + joined + " }" : "[" + joined + "]";
  }
  const std::string fallback = n >= 2 ? sep(n - 2)
                               : text(span).find('\n') != std::string::npos
                                   ? ",\n" + child_indent(span)
                                   : std::string(", ");
  std::string out(1, open);
  out += text_.substr(span.begin + 1, children.front().key - span.begin - 1);
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (p > 0) {
      const int a = pieces[p - 1].original;
      const int b = pieces[p].original;
      if (a >= 0 && b == a + 1) {
        out += sep(static_cast<std::size_t>(a));
      } else if (b > 0) {
        out += sep(static_cast<std::size_t>(b - 1));
      } else if (a >= 0 && static_cast<std::size_t>(a) + 1 < n) {
        out += sep(static_cast<std::size_t>(a));
      } else {
        out += fallback;
      }
    }
    out += pieces[p].text;
  }
  out += text_.substr(children.back().end, span.end - 1 - children.back().end);
  out += close;
  return out;
}

}  // namespace

std::string format_value(const Json& value, const std::string& indent, const Layout* like) {
  if (!value.is_structured() || value.empty()) return value.dump();
  const bool all_simple =
      std::all_of(value.begin(), value.end(), [](const Json& e) { return simple(e); });
  if (like != nullptr ? !like->multiline : all_simple) {
    std::string one_line = inline_text(value);
    if (one_line.size() + indent.size() <= kInlineWidth) return one_line;
  }
  const std::string inner = indent + "  ";
  std::string out(1, value.is_object() ? '{' : '[');
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    out += first ? "\n" : ",\n";
    first = false;
    out += inner;
    const Layout* child = nullptr;
    if (like != nullptr && value.is_object()) {
      const auto found = like->members.find(it.key());
      if (found != like->members.end()) child = &found->second;
    } else if (like != nullptr && !like->elements.empty()) {
      child = &like->elements.front();
    }
    if (value.is_object()) out += Json(it.key()).dump() + ": ";
    out += format_value(it.value(), inner, child);
  }
  return out + "\n" + indent + (value.is_object() ? '}' : ']');
}

std::optional<std::string> splice_json(std::string_view text, const Json& before,
                                       const Json& after) {
  const std::optional<Span> root = Scanner(text).root();
  if (!root) return std::nullopt;
  std::string out(text.substr(0, root->begin));
  out += Splicer(text).render(*root, before, after);
  out += text.substr(root->end);
  return out;
}

}  // namespace antumbra::editor::detail
