// height_fit.cpp: the core's curve fitter from a plugin built against an installed granpipe
// (DEPENDS GSL). Fits each particle's radius as a line in its height, r = a + b z, over all
// frames; a lattice of equal spheres gives a = their radius and b = 0.
#include <granpipe/curve_fit.hpp>
#include <granpipe/plugin.hpp>
#include <vector>

namespace {

class HeightFit : public granpipe::Analyzer {
 public:
  explicit HeightFit(const granpipe::PluginContext&) {}
  granpipe::FrameContent needs() const override { return {}; }

  void consume(const granpipe::Frame& frame, granpipe::FrameCache&) override {
    const int z = frame.dim - 1;
    for (Eigen::Index k = 0; k < frame.size(); ++k) {
      height_.push_back(frame.position()(k, z));
      radius_.push_back(frame.radius()[k]);
    }
  }

  void finish(granpipe::Results& results) override {
    const granpipe::CurveModel line{
        [](const Eigen::VectorXd& p, double z) { return p[0] + p[1] * z; },
        [](const Eigen::VectorXd&, double z) {
          Eigen::VectorXd g(2);
          g << 1.0, z;
          return g;
        }};
    const granpipe::CurveFit fit =
        granpipe::fit_curve(line, height_, radius_, {}, Eigen::Vector2d(1.0, 0.0));
    results.add_fit("radius_line", granpipe::result_fit(fit, "r = a + b z", {"a", "b"}));
  }

 private:
  std::vector<double> height_, radius_;
};

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<HeightFit>("height_fit", "radius fitted as a line in height",
                                   granpipe::Schema());
}
