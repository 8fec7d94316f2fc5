#pragma once
// The Percus-Yevick (scaled-particle) prediction of P0: the probability that a probe
// sphere of radius sigma R placed at random among hard spheres of radius R at packing
// fraction phi overlaps none of them (docs/pores.md: the paper's Eqs. (8)-(9), whose
// variable is the probe's radius plus R, and why Eq. (9) is not used as printed).
namespace granpipe::pores {

// For sigma >= 0 and 0 <= phi < 1: ln P0 = ln(1 - phi) - [3 phi/(1 - phi) sigma
// + (3 phi/(1 - phi) + 9 phi^2 / (2 (1 - phi)^2)) sigma^2 + phi (1 + phi + phi^2)/(1 - phi)^3
// sigma^3], the cubic that continues the exact small-probe form 1 - phi (1 + sigma)^3 with
// its first two derivatives and grows as the PY compressibility pressure.
double p0_percus_yevick(double phi, double sigma);

}  // namespace granpipe::pores
