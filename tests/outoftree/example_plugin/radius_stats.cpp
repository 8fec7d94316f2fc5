// radius_stats.cpp: mean radius, a histogram of radii, and each particle's scaled radius
// published as a column. The README shows this file; the out-of-tree test builds it.
#include <algorithm>
#include <granpipe/plugin.hpp>
#include <vector>

namespace {

class RadiusStats : public granpipe::Analyzer {
 public:
  explicit RadiusStats(const granpipe::PluginContext& ctx)
      : scale_(ctx.params.real("scale")),
        r_max_(ctx.params.real("r_max")),
        counts_(static_cast<std::size_t>(ctx.params.integer("bins")), 0.0) {}

  // What a frame must carry beyond position, radius, id and species (dim, contacts,
  // columns such as "velocity"); the pipeline is refused before running when neither the
  // source nor an analyzer before this one provides it.
  granpipe::FrameContent needs() const override { return {}; }

  // Read the frame, never modify it; keep running sums, not frames.
  void consume(const granpipe::Frame& frame, granpipe::FrameCache&) override {
    scaled_ = scale_ * frame.radius();
    if (frame.size() > 0) radius_.add(scaled_.mean());
    count_.add(static_cast<double>(frame.size()));
    const double width = r_max_ / static_cast<double>(counts_.size());
    const std::size_t last = counts_.size() - 1;
    for (double r : scaled_) {
      // r / width rounds up to the bin count for an r a rounding below r_max: the last bin.
      if (r < r_max_) counts_[std::min(static_cast<std::size_t>(r / width), last)] += 1.0;
    }
  }

  // Optional: per-particle results as new columns, seen by the analyzers after this one
  // and by the writers (frames.h5 among them). Contact columns (Scope::Contact) work the
  // same way: publish() is called once per scope you declare columns of (contacts only for
  // frames with a contact table); columns.scope() tells which.
  std::vector<granpipe::Property> publishes() const override {
    return {{"scaled_radius", granpipe::Scope::Particle, granpipe::ValueType::Real, 1, "length",
             "particle radius times scale"}};
  }
  void publish(granpipe::PropertyTable& columns) override {
    columns.get<Eigen::ArrayXd>("scaled_radius") = scaled_;
  }

  void finish(granpipe::Results& results) override {
    results.add_mean("mean_radius", radius_, "length", "mean particle radius, times scale");
    results.add_mean("particles", count_, "", "particles per frame");
    granpipe::Histogram h;
    const auto bins = static_cast<double>(counts_.size());
    for (std::size_t k = 0; k <= counts_.size(); ++k) {
      h.edges.push_back(r_max_ * static_cast<double>(k) / bins);
    }
    h.values = counts_;  // particles over all frames
    h.xlabel = "radius times scale";
    h.doc = "scaled radii of all particles of all frames";
    results.add_histogram("radii", h);
  }

 private:
  double scale_, r_max_;
  std::vector<double> counts_;
  granpipe::RunningMean radius_, count_;
  Eigen::ArrayXd scaled_;
};

granpipe::Schema schema() {
  granpipe::Schema s;
  s.real("scale", 1.0, "factor applied to the radius").min(0.0, /*exclusive=*/true);
  // No default: a pipeline must give it.
  s.real("r_max", std::nullopt, "upper end of the radius histogram").min(0.0, true).unit("length");
  s.integer("bins", 20, "bins of the radius histogram").range(1, 10000);
  return s;
}

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<RadiusStats>("radius_stats", "mean radius, radius histogram, scaled radius",
                                     schema());
}
