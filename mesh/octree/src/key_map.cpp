#include "volmesh/octree/key_map.hpp"

#include <bit>

namespace volmesh {

void KeyMap::reserve(std::size_t expected) {
  const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(16, 2 * expected));
  if (capacity <= slots_.size()) return;
  std::vector<Slot> old(capacity, Slot{kEmpty, kNoIndex});
  old.swap(slots_);
  mask_ = capacity - 1;
  size_ = 0;
  for (const Slot& s : old)
    if (s.key != kEmpty) insert(s.key, s.value);
}

void KeyMap::grow() { reserve(size_ + 1); }

void KeyMap::insert(std::uint64_t key, Index value) {
  if (2 * (size_ + 1) > slots_.size()) grow();
  for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
    if (slots_[i].key == key) {
      slots_[i].value = value;
      return;
    }
    if (slots_[i].key == kEmpty) {
      slots_[i] = {key, value};
      ++size_;
      return;
    }
  }
}

// Backward-shift deletion keeps every probe sequence unbroken without tombstones.
void KeyMap::erase(std::uint64_t key) {
  if (slots_.empty()) return;
  std::size_t i = slot(key);
  while (slots_[i].key != key) {
    if (slots_[i].key == kEmpty) return;
    i = (i + 1) & mask_;
  }
  for (std::size_t j = (i + 1) & mask_; slots_[j].key != kEmpty; j = (j + 1) & mask_) {
    const std::size_t home = slot(slots_[j].key);
    // Entry j may fill the hole at i when its home slot is not in the cyclic range (i, j].
    const bool stays = i <= j ? (i < home && home <= j) : (i < home || home <= j);
    if (stays) continue;
    slots_[i] = slots_[j];
    i = j;
  }
  slots_[i] = {kEmpty, kNoIndex};
  --size_;
}

void KeyMap::clear() {
  slots_.clear();
  mask_ = size_ = 0;
}

}  // namespace volmesh
