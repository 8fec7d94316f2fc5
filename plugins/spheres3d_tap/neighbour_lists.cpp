#include "neighbour_lists.hpp"

#include <algorithm>
#include <string>

#include "granpipe/errors.hpp"

namespace granpipe::spheres3d_tap {

NeighbourLists::NeighbourLists(const TapBox& box, double move, double slack)
    : periodic_(box.periodic()),
      side_(box.side),
      half_side_(0.5 * box.side),
      radius2_(box.radius * box.radius),
      reach2_((2.0 * box.radius + move + 2.0 * slack) * (2.0 * box.radius + move + 2.0 * slack)),
      // The grid holds centres, each within the slack of its reference.
      range_(2.0 * box.radius + move + 3.0 * slack),
      slack2_(slack * slack),
      // A query's cells span up to 2 range_ and two cells (each under 2R / sqrt 3) more;
      // a box narrower than that shows some of its cells twice.
      images_repeat_(box.periodic() && box.side < 2.0 * range_ + 4.0 * box.radius) {}

void NeighbourLists::rebuild(const std::vector<Eigen::Vector3d>& centres, const SphereGrid& grid) {
  refs_ = centres;
  counts_.assign(centres.size(), 0);
  entries_.resize(centres.size() * capacity_);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const auto self = static_cast<std::int32_t>(i);
    for_each_near(self, grid, [&](std::int32_t j) { add(self, j); });
  }
}

void NeighbourLists::renew(std::int32_t i, const std::vector<Eigen::Vector3d>& centres,
                           const SphereGrid& grid) {
  const auto k = static_cast<std::size_t>(i);
  for (std::uint32_t n = 0; n < counts_[k]; ++n)
    erase(static_cast<std::int32_t>(entries_[k * capacity_ + n]), i);
  counts_[k] = 0;
  refs_[k] = centres[k];
  for_each_near(i, grid, [&](std::int32_t j) {
    add(i, j);
    add(j, i);
  });
  ++renewals_;
}

template <class F>
void NeighbourLists::for_each_near(std::int32_t i, const SphereGrid& grid, F&& f) const {
  const Eigen::Vector3d& ref = refs_[static_cast<std::size_t>(i)];
  grid.for_each_in(ref.array() - range_, ref.array() + range_,
                   [&](std::int32_t j, const Eigen::Vector3d&) {
                     if (j != i && distance2(refs_[static_cast<std::size_t>(j)], ref) < reach2_ &&
                         !(images_repeat_ && listed(i, j)))
                       f(j);
                   });
}

bool NeighbourLists::listed(std::int32_t in, std::int32_t j) const {
  const auto* list = entries_.data() + static_cast<std::size_t>(in) * capacity_;
  return std::find(list, list + counts_[static_cast<std::size_t>(in)],
                   static_cast<std::uint32_t>(j)) != list + counts_[static_cast<std::size_t>(in)];
}

void NeighbourLists::add(std::int32_t to, std::int32_t j) {
  const auto k = static_cast<std::size_t>(to);
  if (counts_[k] == capacity_) {
    // Every list gets twice the room, in place from the back so nothing is overwritten.
    const std::size_t old = capacity_;
    capacity_ *= 2;
    entries_.resize(counts_.size() * capacity_);
    for (std::size_t s = counts_.size(); s-- > 0;)
      std::copy_backward(
          entries_.begin() + static_cast<std::ptrdiff_t>(s * old),
          entries_.begin() + static_cast<std::ptrdiff_t>(s * old + counts_[s]),
          entries_.begin() + static_cast<std::ptrdiff_t>(s * capacity_ + counts_[s]));
  }
  entries_[k * capacity_ + counts_[k]++] = static_cast<std::uint32_t>(j);
}

void NeighbourLists::erase(std::int32_t from, std::int32_t j) {
  const auto k = static_cast<std::size_t>(from);
  std::uint32_t* list = entries_.data() + k * capacity_;
  std::uint32_t* end = list + counts_[k];
  std::uint32_t* it = std::find(list, end, static_cast<std::uint32_t>(j));
  if (it == end) {
    throw InternalError("neighbour lists: sphere " + std::to_string(j) +
                        " missing from the list of " + std::to_string(from));
  }
  *it = *(end - 1);
  --counts_[k];
}

}  // namespace granpipe::spheres3d_tap
