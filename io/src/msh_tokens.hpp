#pragma once
// The lexer of the text mesh readers (MSH, MEDIT, TetGen): the file read whole, split into
// whitespace-separated tokens, with checked numbers and one-line errors naming the file and
// line.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "surface_text.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::msh {

inline std::string read_text(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size =
      std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  std::ifstream in(path, std::ios::binary);
  if (ec || !in || !std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + ": cannot open (no such file, or not a regular file)");
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) throw InputError(path.string() + ": cannot read");
  return text;
}

// Whitespace-separated tokens of a text file (on surface_text.hpp's cursor), with checked
// numbers and errors naming the file and line; `comment`, when given, starts a comment that
// runs to the line end.
class Tokens {
 public:
  Tokens(std::string source, std::string text, char comment = '\0')
      : source_(std::move(source)), text_(std::move(text)), cursor_(text_), comment_(comment) {}
  Tokens(const Tokens&) = delete;  // the cursor points into text_
  Tokens& operator=(const Tokens&) = delete;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": " + cursor_.where() + ": " + what);
  }

  bool at_end() {
    cursor_.skip_space(comment_);
    return cursor_.at_end();
  }

  std::string_view word() {
    if (at_end()) fail("unexpected end of file");
    return cursor_.word();
  }

  long long integer(const char* what) { return number<long long>(what); }
  double real() { return number<double>("a number"); }

  // A count of items that each take at least `min_bytes` of the remaining text, so that a
  // corrupt count fails here instead of allocating.
  long long count(const char* what, std::size_t min_bytes) {
    const long long n = integer(what);
    if (n < 0 || n > kMaxIndex ||
        static_cast<unsigned long long>(n) * min_bytes > cursor_.remaining())
      fail(std::string("implausible ") + what + " " + std::to_string(n));
    return n;
  }

  std::string quoted() {
    const std::size_t open = at_end() ? text_.size() : offset();
    if (open == text_.size() || text_[open] != '"') fail("expected a quoted name");
    const std::size_t close = text_.find('"', open + 1);
    if (close == std::string::npos || text_.find('\n', open) < close)
      fail("unterminated quoted name");
    cursor_ = surface_detail::TextCursor(text_, close + 1, cursor_.line());
    return text_.substr(open + 1, close - open - 1);
  }

  void expect(std::string_view keyword) {
    const std::string_view w = word();
    if (w != keyword) fail("expected " + std::string(keyword) + ", found '" + shown(w) + "'");
  }

  // Skips an unknown section up to its $End line.
  void skip_section(std::string_view name) {
    const std::string end = "$End" + std::string(name);
    const std::size_t at = text_.find(end, offset());
    if (at == std::string::npos) fail("section $" + std::string(name) + " has no " + end);
    const auto lines = std::count(text_.begin() + static_cast<std::ptrdiff_t>(offset()),
                                  text_.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    cursor_ = surface_detail::TextCursor(text_, at + end.size(), cursor_.line() + lines);
  }

 private:
  template <class T>
  T number(const char* what) {
    if (at_end()) fail("unexpected end of file");
    T value{};
    if (!cursor_.number(value))
      fail(std::string("expected ") + what + ", found '" + shown(cursor_.word()) + "'");
    return value;
  }

  static std::string shown(std::string_view w) { return std::string(w.substr(0, 40)); }
  std::size_t offset() const { return text_.size() - cursor_.remaining(); }

  std::string source_;
  std::string text_;
  surface_detail::TextCursor cursor_;
  char comment_;
};

}  // namespace volmesh::msh
