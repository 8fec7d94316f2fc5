// Mean particle radius and particle count per frame, and each particle's scaled radius
// published as a column: the smallest useful analyzer.
#include <granpipe/plugin.hpp>

namespace {

class RadiusStats : public granpipe::Analyzer {
 public:
  explicit RadiusStats(const granpipe::PluginContext& ctx) : scale_(ctx.params.real("scale")) {}

  void consume(const granpipe::Frame& frame, granpipe::FrameCache&) override {
    if (frame.size() > 0) radius_.add(scale_ * frame.radius().mean());
    count_.add(static_cast<double>(frame.size()));
    scaled_ = scale_ * frame.radius();
  }

  // A per-particle result that later analyzers and frames.h5 see.
  std::vector<granpipe::Property> publishes() const override { return {scaled_radius()}; }
  void publish(granpipe::PropertyTable& columns) override {
    columns.get<Eigen::ArrayXd>("scaled_radius") = scaled_;
  }

  void finish(granpipe::Results& results) override {
    results.add_mean("mean_radius", radius_, "length", "mean particle radius, times scale");
    results.add_mean("particles", count_, "", "particles per frame");
  }

 private:
  static granpipe::Property scaled_radius() {
    return {"scaled_radius", granpipe::Scope::Particle, granpipe::ValueType::Real, 1, "length",
            "particle radius times scale"};
  }
  double scale_;
  granpipe::RunningMean radius_, count_;
  Eigen::ArrayXd scaled_;
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
