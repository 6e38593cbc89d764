#pragma once
// A flat hash map from 64-bit keys (Morton or locational codes) to indices: the O(1) lookup
// behind the octree's leaf and vertex tables. Open addressing with linear probing; built
// once and then read concurrently (const lookups are thread-safe).
#include <cstdint>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

class KeyMap {
 public:
  KeyMap() = default;
  explicit KeyMap(std::size_t expected) { reserve(expected); }

  // Room for `expected` keys without growing (load factor <= 1/2).
  void reserve(std::size_t expected);
  // Inserts or overwrites. The key ~0 is reserved (never a valid code).
  void insert(std::uint64_t key, Index value);
  // Removes a key if present.
  void erase(std::uint64_t key);
  // The value, or kNoIndex when absent.
  Index find(std::uint64_t key) const {
    if (slots_.empty()) return kNoIndex;
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return slots_[i].value;
      if (slots_[i].key == kEmpty) return kNoIndex;
    }
  }
  std::size_t size() const { return size_; }
  void clear();

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::size_t slot(std::uint64_t key) const {
    // splitmix64 finaliser: Morton codes of neighbours differ in few low bits.
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ULL;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebULL;
    key ^= key >> 31;
    return static_cast<std::size_t>(key) & mask_;
  }
  void grow();

  struct Slot {  // key and value side by side: one cache line per probe
    std::uint64_t key;
    Index value;
  };
  std::vector<Slot> slots_;
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace volmesh
