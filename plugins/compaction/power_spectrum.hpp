#pragma once
// The power spectrum of the steady-state fluctuations X - X_SS against the frequency, in
// inverse taps (the paper's Fig. 3), and the slope of log S against log f.
//
// A discrete spectrum needs frames evenly spaced in taps. A tapping run saves every
// save_every-th tap and, with log_frames, taps ten per decade between them; the spectrum
// uses only the frames on one grid: the spacing is the commonest gap between consecutive
// frames (the larger of equally common ones), and the frames are the longest unbroken
// stretch of a grid of that spacing (the latest of equally long ones).
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace granpipe::compaction {

struct EvenFrames {
  std::vector<std::size_t> index;  // into the series, in increasing tap
  double spacing = std::nan("");   // taps between them; NaN for fewer than two frames
};

// `taps` increasing.
EvenFrames evenly_spaced(const std::vector<double>& taps);

struct Spectrum {
  std::vector<double> frequency;  // 1/taps, k / (n spacing), k = 1 .. n/2 (no f = 0)
  std::vector<double> power;      // one-sided: sum of power times 1/(n spacing) = variance
};

// The periodogram of `values` minus their mean, sampled every `spacing` taps (GSL's
// mixed-radix real FFT, any length); every power NaN if a value is.
Spectrum power_spectrum(const std::vector<double>& values, double spacing);

struct Slope {
  double value = 0.0, error = 0.0;  // NaN with fewer than 3 frequencies
};

// The frequencies at which the power is above zero: the points of the slope.
std::size_t positive_powers(const Spectrum& s);

// Least squares of ln S against ln f over positive_powers (NaN with fewer than 3), with the
// standard error from the residual scatter.
Slope log_log_slope(const Spectrum& s);

}  // namespace granpipe::compaction
