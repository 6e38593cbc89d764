#pragma once
// Loading and storing binary numbers in a file's byte order, whatever the host's: shared by
// the binary surface, image and voxel formats.
#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

namespace volmesh::byte_order {

template <class T>
T load(const char* bytes, bool big_endian) {
  char buf[sizeof(T)];
  std::memcpy(buf, bytes, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(buf, buf + sizeof(T));
  T value;
  std::memcpy(&value, buf, sizeof(T));
  return value;
}

template <class T>
void append(std::string& out, T value, bool big_endian) {
  char buf[sizeof(T)];
  std::memcpy(buf, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(buf, buf + sizeof(T));
  out.append(buf, sizeof(T));
}

}  // namespace volmesh::byte_order
