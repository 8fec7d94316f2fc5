#pragma once
// How deep a contact of a sound run may go. A soft-sphere contact models a small
// deformation: at the Brazil-nut scene's stiffness (k_n = 2e5) its impacts press small
// spheres about 4 % of their radius deep (a landing at 8 d0/t), and even its heavy
// intruder landing on the base about 11 % of its radius. A sphere dropped from z = 1e4
// reaches 59 % (linear) and 84 % (Hertz), and two spheres meeting faster than their
// stiffness can stop pass through each other past 100 %: results with no physical meaning.
// The engine stops a run whose contact goes deeper than this fraction of the smaller
// radius (of the particle's, against a wall), and a start holding such an overlap, or a
// sphere reaching that far through a wall, is refused.
namespace granpipe::dem {

inline constexpr double kMaxOverlapFraction = 0.3;

}  // namespace granpipe::dem
