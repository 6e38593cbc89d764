#pragma once
// Fast, locale-independent number formatting for the text writers. Doubles are written in
// the shortest form that reads back to the same value.
#include <charconv>
#include <string>

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

}  // namespace volmesh
