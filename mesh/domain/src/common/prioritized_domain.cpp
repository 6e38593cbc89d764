// A domain whose regions are ranks, renamed to the labels they stand for.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/prioritized.hpp"

namespace volmesh {

namespace {

class PrioritizedDomain final : public Domain {
 public:
  PrioritizedDomain(std::unique_ptr<Domain> ranked, std::vector<Index> label_of_rank)
      : inner_(std::move(ranked)), label_(std::move(label_of_rank)) {}

  Index region(const Vec3& p) const override { return label_[inner_->region(p)]; }
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override {
    std::vector<Crossing> out = inner_->crossings(a, b);
    rename(out);
    return out;
  }
  Vec3 normal(const Vec3& p) const override { return inner_->normal(p); }
  Box3 bounds() const override { return inner_->bounds(); }
  std::vector<Index> regions() const override {
    std::vector<Index> out = inner_->regions();
    for (Index& r : out) r = label_[r];
    std::sort(out.begin(), out.end());
    return out;
  }
  std::string surface_name(const Vec3& p) const override { return inner_->surface_name(p); }
  std::string boundary_name(const Vec3& p) const override { return inner_->boundary_name(p); }

  void region(std::span<const Vec3> points, std::span<Index> out) const override {
    inner_->region(points, out);
    for (Index& r : out) r = label_[r];
  }
  void crossings(std::span<const Vec3> a, std::span<const Vec3> b,
                 std::vector<std::vector<Crossing>>& out) const override {
    inner_->crossings(a, b, out);
    for (std::vector<Crossing>& c : out) rename(c);
  }

 private:
  void rename(std::vector<Crossing>& crossings) const {
    for (Crossing& c : crossings) {
      c.before = label_[c.before];
      c.after = label_[c.after];
    }
  }

  std::unique_ptr<Domain> inner_;
  std::vector<Index> label_;  // per rank; label_[0] = 0
};

}  // namespace

Index rank_of(const std::vector<Index>& order, Index label) {
  const auto it = std::find(order.begin(), order.end(), label);
  return it == order.end() ? 0 : static_cast<Index>(order.end() - it);
}

std::unique_ptr<Domain> prioritized(std::unique_ptr<Domain> ranked, std::vector<Index> order) {
  std::vector<Index> label_of_rank{0};
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (*it < 1) throw InputError("priority: label " + std::to_string(*it) + " is not >= 1");
    if (std::count(order.begin(), order.end(), *it) > 1)
      throw InputError("priority: label " + std::to_string(*it) + " is listed twice");
    label_of_rank.push_back(*it);
  }
  for (Index r : ranked->regions())
    if (r < 0 || r >= static_cast<Index>(label_of_rank.size()))
      throw std::invalid_argument("prioritized: the domain has region " + std::to_string(r) +
                                  ", beyond the " + std::to_string(order.size()) + " ranks");
  return std::make_unique<PrioritizedDomain>(std::move(ranked), std::move(label_of_rank));
}

}  // namespace volmesh
