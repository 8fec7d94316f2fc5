// Mean particle radius and particle count per frame: the smallest useful analyzer.
#include <granpipe/plugin.hpp>

namespace {

class RadiusStats : public granpipe::Analyzer {
 public:
  explicit RadiusStats(const granpipe::PluginContext& ctx) : scale_(ctx.params.real("scale")) {}

  void consume(const granpipe::Frame& frame, granpipe::FrameCache&) override {
    if (frame.size() > 0) radius_.add(scale_ * frame.radius().mean());
    count_.add(static_cast<double>(frame.size()));
  }

  void finish(granpipe::Results& results) override {
    results.add_mean("mean_radius", radius_, "length", "mean particle radius, times scale");
    results.add_mean("particles", count_, "", "particles per frame");
  }

 private:
  double scale_;
  granpipe::RunningMean radius_, count_;
};

granpipe::Schema schema() {
  granpipe::Schema s;
  s.real("scale", 1.0, "factor applied to the radius").min(0.0, true);
  return s;
}

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<RadiusStats>("radius_stats", "mean radius and particle count", schema());
}
