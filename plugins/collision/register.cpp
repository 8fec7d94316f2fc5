#include "collision_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::collision::CollisionAnalyzer>(
      "collision",
      "contact time and restitution coefficient of a two-sphere collision (frames every time step) "
      "against the linear spring-dashpot law's analytic values",
      granpipe::collision::schema());
}
