#include "lattice_source.hpp"

#include <cmath>
#include <sstream>

namespace granpipe::lattice {

namespace {
// The box around the crystal (parameter boundary).
enum class Sides : std::uint8_t { Periodic, Walls };
ChoiceNames<Sides> choice_names(Sides) {
  return {{"periodic", Sides::Periodic}, {"walls", Sides::Walls}};
}
}  // namespace

Schema schema() {
  Schema s;
  s.choice<Lattice>(
      "lattice", Lattice::Fcc,
      "crystal: square, triangular (2D); sc, bcc, fcc, hcp (3D, hcp stacked along z)");
  s.integers(
       "cells", std::vector<std::int64_t>{},
       "unit cells per axis, one entry per axis (2 in 2D, 3 in 3D); empty: 4 per axis. "
       "Cells are rectangular: triangular 1 x sqrt3 (2 particles), hcp 1 x sqrt3 x "
       "sqrt(8/3) (4 particles), in nearest-neighbour distances; at most 10^7 particles in all")
      .min(1);
  // Squared distances and volumes of any lattice must stay normal doubles.
  s.real("radius", 0.5, "particle radius; nearest neighbours touch (their distance is 2 radius)")
      .range(1e-50, 1e50)
      .unit("length");
  s.choice<Sides>("boundary", Sides::Periodic,
                  "periodic: the box is exactly the periodic repeat; walls: a box tight around the "
                  "particles with walls on every side but an open top");
  s.real("jitter", 0.0,
         "each particle is displaced uniformly within a disk/ball of radius jitter*radius, and "
         "every radius is reduced to radius*(1 - jitter), so jittered particles never overlap "
         "each other or the walls")
      .min(0.0)
      .max(1.0, true);
  // 1e12 ran on at 10 MB/s of frames (an ETA of 300 000 hours).
  s.integer("frames", 1, "number of frames, each with its own jitter; at most 1e8").range(1, 1e8);
  return s;
}

namespace {

std::string axis_word(int dim) { return dim == 2 ? "2D" : "3D"; }

// A frame takes about 40 bytes per particle, is built when the pipeline is checked and is
// copied for every frame emitted: 10^7 particles take about a gigabyte already.
constexpr double kMaxParticles = 1e7;

}  // namespace

LatticeSource::LatticeSource(const PluginContext& ctx)
    : seeds_(ctx.seeds),
      cell_(unit_cell(ctx.params.choice<Lattice>("lattice"))),
      radius_(ctx.params.real("radius")),
      jitter_(ctx.params.real("jitter")),
      frames_(ctx.params.integer("frames")) {
  const int dim = cell_.dim;
  std::vector<std::int64_t> cells = ctx.params.integers("cells");
  if (cells.empty()) cells.assign(dim, 4);
  if (static_cast<int>(cells.size()) != dim) {
    throw InputError(ctx.param("cells") + ": expected " + std::to_string(dim) +
                     " entries (one per axis of the " + axis_word(dim) + " " +
                     ctx.params.string("lattice") + " lattice), got " +
                     std::to_string(cells.size()));
  }
  const bool periodic = ctx.params.choice<Sides>("boundary") == Sides::Periodic;
  const double spacing = 2.0 * radius_;  // nearest-neighbour distance

  double estimate = static_cast<double>(cell_.basis.size());
  for (auto c : cells) estimate *= static_cast<double>(c);
  if (estimate > kMaxParticles) {
    std::ostringstream s;
    s << ctx.param("cells") << ": expected at most " << kMaxParticles << " particles ("
      << cell_.basis.size() << " per cell), got " << estimate;
    throw InputError(s.str());
  }
  Eigen::Index n = static_cast<Eigen::Index>(cell_.basis.size());
  for (auto c : cells) n *= c;
  perfect_.resize(n, dim);
  perfect_.radius().setConstant(radius_);
  Eigen::Index k = 0;
  const std::int64_t nz = dim == 3 ? cells[2] : 1;
  for (std::int64_t iz = 0; iz < nz; ++iz)
    for (std::int64_t iy = 0; iy < cells[1]; ++iy)
      for (std::int64_t ix = 0; ix < cells[0]; ++ix)
        for (const auto& b : cell_.basis) {
          const Eigen::Vector3d site(static_cast<double>(ix), static_cast<double>(iy),
                                     static_cast<double>(iz));
          for (int a = 0; a < dim; ++a) {
            perfect_.position()(k, a) = spacing * (site[a] * cell_.size[a] + b[a]);
          }
          ++k;
        }

  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (periodic) {
    for (int a = 0; a < dim; ++a) hi[a] = spacing * cell_.size[a] * static_cast<double>(cells[a]);
    perfect_.container = Container::periodic_box(dim, lo, hi);
  } else {
    // Shift so that the lowest particles touch the low walls at 0; the high walls touch
    // the highest particles (in the rows or layers that reach them).
    for (int a = 0; a < dim; ++a) {
      const double shift = radius_ - perfect_.position().col(a).minCoeff();
      perfect_.position().col(a) += shift;
      hi[a] = perfect_.position().col(a).maxCoeff() + radius_;
    }
    perfect_.container = Container::open_top_box(dim, lo, hi);
  }
}

FrameContent LatticeSource::content() const { return {.dim = cell_.dim}; }

Source::Work LatticeSource::work() const { return {static_cast<double>(frames_), "frames", false}; }

bool LatticeSource::next(Frame& frame) {
  if (next_ >= frames_) return false;
  frame = perfect_;
  if (jitter_ > 0.0) jitter(frame, next_);
  frame.step = next_;
  frame.time = static_cast<double>(next_);
  ++next_;
  return true;
}

void LatticeSource::jitter(Frame& frame, std::int64_t index) const {
  // Each particle moves by at most jitter*R and shrinks by jitter*R, so a pair that
  // touched is still at least touching, and so is a particle and a wall.
  RandomStream rng = seeds_.stream("jitter", static_cast<std::uint64_t>(index));
  const double reach = jitter_ * radius_;
  const int dim = frame.dim;
  const Container& c = frame.container;
  frame.radius().setConstant(radius_ * (1.0 - jitter_));
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    double u[3], r2;
    do {  // uniform in the unit disk/ball by rejection from the cube
      r2 = 0;
      for (int a = 0; a < dim; ++a) {
        u[a] = rng.uniform(-1.0, 1.0);
        r2 += u[a] * u[a];
      }
    } while (r2 > 1.0);
    for (int a = 0; a < dim; ++a) {
      frame.position()(k, a) = c.wrap(a, frame.position()(k, a) + reach * u[a]);
    }
  }
}

void LatticeSource::finish(Results& results) {
  results.add_scalar("particles", static_cast<double>(perfect_.size()), std::nan(""), "",
                     "particles per frame");
  results.add_scalar("radius", radius_ * (1.0 - jitter_), std::nan(""), "length",
                     "particle radius (reduced by the jitter)");
  results.add_scalar("nearest_neighbour_distance", 2.0 * radius_, std::nan(""), "length",
                     "distance between neighbouring lattice sites");
}

}  // namespace granpipe::lattice
