#pragma once
// A cursor over the text of a surface file: words and numbers without iostreams (surfaces can
// have millions of triangles), with line numbers for error messages.
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

#include "text_format.hpp"

namespace volmesh::surface_detail {

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
inline bool is_space(char c) { return is_blank(c) || c == '\n'; }

// Parses a header count; a count too large for 64 bits saturates, so that the caller reports
// it as over the index limit rather than as malformed.
inline bool parse_count(std::string_view w, std::uint64_t& count) {
  if (w.empty() || w.find_first_not_of("0123456789") != std::string_view::npos) return false;
  if (std::from_chars(w.data(), w.data() + w.size(), count).ec == std::errc::result_out_of_range)
    count = UINT64_MAX;
  return true;
}

class TextCursor {
 public:
  explicit TextCursor(std::string_view text, std::size_t offset = 0, long line = 1)
      : p_(text.data() + offset), end_(text.data() + text.size()), line_(line) {}

  bool at_end() const { return p_ == end_; }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  long line() const { return line_; }
  std::string where() const { return "line " + std::to_string(line_); }

  // Skips blanks, line ends and, if `comment` is given, comments running to the line end.
  void skip_space(char comment = '\0') {
    while (p_ != end_) {
      if (*p_ == '\n') {
        ++line_;
        ++p_;
      } else if (is_blank(*p_)) {
        ++p_;
      } else if (comment != '\0' && *p_ == comment) {
        skip_to_line_end();
      } else {
        return;
      }
    }
  }
  // Skips blanks on the current line only.
  void skip_blanks() {
    while (p_ != end_ && is_blank(*p_)) ++p_;
  }
  // True at a line end, the end of the text, or a comment (after skip_blanks).
  bool at_line_end(char comment = '\0') const {
    return p_ == end_ || *p_ == '\n' || (comment != '\0' && *p_ == comment);
  }
  // Moves past the end of the current line, ignoring whatever is left on it.
  void next_line() {
    skip_to_line_end();
    if (p_ != end_) {
      ++p_;
      ++line_;
    }
  }

  // The next run of non-space characters on the current line (empty at a line end).
  std::string_view word() {
    skip_blanks();
    const char* begin = p_;
    while (p_ != end_ && !is_space(*p_)) ++p_;
    return {begin, static_cast<std::size_t>(p_ - begin)};
  }

  // The next word on the current line parsed as a whole number; false (and the cursor
  // unchanged) if it is missing or not a number.
  template <class T>
  bool number(T& value) {
    const char* saved = p_;
    std::string_view w = word();
    if (!parse_number(w, value)) {
      p_ = saved;
      return false;
    }
    return true;
  }

 private:
  void skip_to_line_end() {
    while (p_ != end_ && *p_ != '\n') ++p_;
  }

  const char* p_;
  const char* end_;
  long line_;
};

}  // namespace volmesh::surface_detail
