#pragma once
// The observables of the Brazil-nut paper's Figs. 3, 8, 9 and 10, per frame: the heights of
// the intruder (the one largest particle: find_intruder) and of the centre of mass of the other
// particles above the base, which moves with the container, their vertical velocities, the mean
// coordination number from the frame's contact table (particle pairs only, each contact
// counted for both particles), and the stage of the cycle.
//
// Stages (the paper's Sec. III.A): the bed is in its expansion stage from the moment it
// loses contact with the vibrating base until it lands on it again, and in its compression
// stage for the rest of the cycle. A frame is in the compression stage when any particle
// touches the base. The moments between frames where the stage changes (lift-off and
// impact) are reported at the midpoint of the two frames, so their resolution is the
// interval between frames. `cycles` (drive periods) comes from the frame's observable of
// that name (the dem source sets it); frames without it get NaN there.
#include <Eigen/Core>
#include <string>

#include "granpipe/plugin.hpp"

namespace granpipe::intruder {

enum class Stage { Expansion = 0, Compression = 1 };

struct BedState {
  double intruder_height = 0.0;    // intruder centre above the base
  double bed_height = 0.0;         // centre of mass of the other particles above the base
  double intruder_velocity = 0.0;  // vertical, in the laboratory frame
  double bed_velocity = 0.0;       // of the other particles' centre of mass, vertical
  double coordination = 0.0;       // 2 (particle-particle contacts) / particles
  long base_contacts = 0;          // particles touching the base
  Stage stage = Stage::Expansion;
};

// The intruder is the one particle larger than every other. A bed whose largest radius is
// shared (a monodisperse bed, or two large spheres) has none: reporting one of them would
// be an arbitrary choice, so such a frame is refused. Radii within a relative kSameRadius
// of the largest count as equal to it. So is a largest particle of the bed's species that
// stands no more apart from the next than the bed's radii spread (a polydisperse bed's tail).
constexpr double kSameRadius = 1e-6;
// The intruder's row; throws InputError naming `where` when there is none.
Eigen::Index find_intruder(const Frame& frame, const std::string& where);

// Throws InputError naming `where` for a frame of fewer than two particles or without an
// intruder.
BedState measure_bed(const Frame& frame, const std::string& where);

class IntruderAnalyzer : public Analyzer {
 public:
  explicit IntruderAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override;
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  StreamedTable per_frame_;
  Table transitions_;
  long frames_ = 0;
  double last_time_ = 0.0, last_cycles_ = 0.0;
  Stage last_stage_ = Stage::Expansion;
};

}  // namespace granpipe::intruder
