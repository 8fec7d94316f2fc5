#pragma once
// The centres a triangulation of a box with periodic sides needs: every particle, brought
// into the box, and its images across each periodic side within the skin (skin.hpp) of
// that side. A cell whose circumsphere lies within the skin around the box is then a cell
// of the infinite periodic packing: every centre of the periodic packing inside that
// sphere is among these.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "granpipe/frame.hpp"
#include "skin.hpp"

namespace granpipe::pores {

struct Centres {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> particle;  // the frame's row of each point
  std::vector<std::uint32_t> primary;   // per particle: the row of its point in the box
};

// Without periodic sides (or skin 0): the frame's centres as they are.
Centres centres_with_images(const Frame& frame, const Skin& skin);

// The images within `skin` of the sides that are not within `thinner`, in the same order
// (points and particles; no primary rows): what widens the skin of centres_with_images.
Centres images_between(const Frame& frame, const Skin& thinner, const Skin& skin);

}  // namespace granpipe::pores
