// A source with the parameters of a scene of several materials (a choice, a species table,
// a pair table, nested wall objects), for `granpipe describe` and `validate` on them.
#include "granpipe/plugin.hpp"

namespace {

enum class Law : std::uint8_t { Linear, Hertz };
granpipe::ChoiceNames<Law> choice_names(Law) {
  return {{"linear", Law::Linear}, {"hertz", Law::Hertz}};
}

class Materials : public granpipe::Source {
 public:
  explicit Materials(const granpipe::PluginContext& ctx) : law_(ctx.params.choice<Law>("law")) {}
  granpipe::FrameContent content() const override { return {.dim = 3}; }
  bool next(granpipe::Frame&) override { return false; }

 private:
  Law law_;
};

granpipe::Schema wall() {
  granpipe::Schema s;
  s.real("k_n", 2e5, "normal stiffness").min(0.0, true).unit("m0 g / d0");
  s.real("mu", 0.5, "friction coefficient").min(0.0);
  return s;
}

granpipe::Schema schema() {
  granpipe::Schema species;
  species.real("diameter", std::nullopt, "diameter").min(0.0, true).unit("d0");
  species.real("density", 1.91, "mass density").min(0.0, true);
  granpipe::Schema pair;
  pair.real("k_n", std::nullopt, "normal stiffness").min(0.0, true);
  pair.real("mu", 0.5, "friction coefficient").min(0.0);
  granpipe::Schema walls;
  walls.object("base", wall(), "the flat base");
  walls.object("cylinder", wall(), "the side wall");
  granpipe::Schema s;
  s.choice<Law>("law", Law::Linear, "contact law");
  s.species_table("species", species, R"([{"name": "small", "diameter": 1}])",
                  "the particle species");
  s.pair_table("contacts", "species", pair, R"({"*": {"k_n": 2e5}})", "contact coefficients");
  s.object("walls", walls, "the container's walls");
  return s;
}

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_source<Materials>("materials", "a scene of several materials", schema());
}
