#pragma once
// Fast, locale-independent numbers in text files: formatting for the text writers (doubles in
// the shortest form that reads back to the same value) and parsing for the text readers.
#include <charconv>
#include <string>
#include <string_view>
#include <system_error>

namespace volmesh {

inline void append_number(std::string& out, double value) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, res.ptr);
}

inline void append_number(std::string& out, long long value) {
  char buf[24];
  auto res = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, res.ptr);
}

inline void append_number(std::string& out, int value) { append_number(out, static_cast<long long>(value)); }

// Parses all of `text` as one number of type T; a leading '+' is allowed (from_chars refuses
// it). False for an empty text, anything around the number, or a value out of T's range.
template <class T>
bool parse_number(std::string_view text, T& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// The same with blanks (spaces, tabs, carriage returns) around the number: a header field.
template <class T>
bool parse_field(std::string_view text, T& value) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return parse_number(text, value);
}

}  // namespace volmesh
