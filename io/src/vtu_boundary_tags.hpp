#pragma once
// How VTU files keep boundary tags: one field-data array per tag, named "boundary:<tag name>",
// holding the tag's faces as [n, v_1 .. v_n, n, ...]; readers match them to cell faces by
// vertex set. Shared by the VTU reader and writer.
#include <string>
#include <string_view>

namespace volmesh {

inline constexpr std::string_view kBoundaryArrayPrefix = "boundary:";

// VTK writes array names into XML attributes without escaping them, so the characters XML
// reserves, '%' and control characters are written as %XX.
inline std::string boundary_array_name(std::string_view tag_name) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out(kBoundaryArrayPrefix);
  for (char ch : tag_name) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte < 0x20 || byte == 0x7F ||
        std::string_view("&<>\"'%").find(ch) != std::string_view::npos)
      out += {'%', kHex[byte >> 4], kHex[byte & 15]};
    else
      out += ch;
  }
  return out;
}

// The tag name of a boundary array (without the prefix); malformed escapes stay as they are.
inline std::string boundary_tag_name(std::string_view array_name) {
  auto hex = [](char ch) {
    return ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10 : -1;
  };
  std::string out;
  for (std::size_t i = 0; i < array_name.size(); ++i) {
    if (array_name[i] == '%' && i + 2 < array_name.size() && hex(array_name[i + 1]) >= 0 &&
        hex(array_name[i + 2]) >= 0) {
      out += static_cast<char>(hex(array_name[i + 1]) * 16 + hex(array_name[i + 2]));
      i += 2;
    } else {
      out += array_name[i];
    }
  }
  return out;
}

}  // namespace volmesh
