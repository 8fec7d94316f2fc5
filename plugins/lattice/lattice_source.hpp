#pragma once
// `lattice`: perfect (or jittered) crystal packings of equal disks or spheres, with
// nearest neighbours exactly touching. Known packing fractions and coordination numbers
// make them the reference configurations for testing analyzers.
#include <cstdint>

#include "granpipe/plugin.hpp"
#include "unit_cells.hpp"

namespace granpipe::lattice {

Schema schema();

class LatticeSource : public Source {
 public:
  explicit LatticeSource(const PluginContext& ctx);

  FrameContent content() const override;
  bool next(Frame& frame) override;
  Work work() const override;
  void finish(Results& results) override;

 private:
  void jitter(Frame& frame, std::int64_t index) const;

  Seeds seeds_;
  UnitCell cell_;
  double radius_;  // nominal radius: nearest-neighbour distance / 2
  double jitter_;  // displacement bound, in units of radius_
  Frame perfect_;  // the unjittered frame, copied for every frame
  std::int64_t frames_ = 1, next_ = 0;
};

}  // namespace granpipe::lattice
