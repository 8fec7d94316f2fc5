#include "power_spectrum.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_real.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <unordered_map>

#include "granpipe/errors.hpp"

namespace granpipe::compaction {

namespace {

// Taps are whole numbers; compared as such, rounding cannot break a grid.
std::int64_t whole(double tap) { return std::llround(tap); }

std::int64_t commonest_gap(const std::vector<double>& taps) {
  std::map<std::int64_t, long> count;
  for (std::size_t k = 1; k < taps.size(); ++k) ++count[whole(taps[k]) - whole(taps[k - 1])];
  std::int64_t gap = 0;
  long most = 0;
  for (const auto& [g, c] : count) {
    if (c >= most) {  // ascending gaps: a tie goes to the larger
      gap = g;
      most = c;
    }
  }
  return gap;
}

struct WavetableFree {
  void operator()(gsl_fft_real_wavetable* w) const { gsl_fft_real_wavetable_free(w); }
};
struct WorkspaceFree {
  void operator()(gsl_fft_real_workspace* w) const { gsl_fft_real_workspace_free(w); }
};

}  // namespace

EvenFrames evenly_spaced(const std::vector<double>& taps) {
  EvenFrames even;
  if (taps.empty()) return even;
  const std::int64_t gap = commonest_gap(taps);
  if (gap <= 0) {
    even.index.push_back(taps.size() - 1);
    return even;
  }
  even.spacing = static_cast<double>(gap);
  // The length of the unbroken grid ending at each frame; the longest grid wins, the latest
  // of equally long ones (a last frame off the grid, the run's end, took the grid with it).
  std::unordered_map<std::int64_t, std::size_t> grid_length;
  std::size_t end = 0, longest = 0;
  for (std::size_t k = 0; k < taps.size(); ++k) {
    const std::int64_t t = whole(taps[k]);
    const auto before = grid_length.find(t - gap);
    const std::size_t length = (before == grid_length.end() ? 0 : before->second) + 1;
    grid_length[t] = length;
    if (length >= longest) {
      longest = length;
      end = k;
    }
  }
  // Back from its end over the frames between the grid's taps.
  std::int64_t next = whole(taps[end]);
  for (std::size_t k = end + 1; k-- > 0 && even.index.size() < longest;) {
    if (whole(taps[k]) != next) continue;
    even.index.push_back(k);
    next -= gap;
  }
  std::reverse(even.index.begin(), even.index.end());
  return even;
}

Spectrum power_spectrum(const std::vector<double>& values, double spacing) {
  Spectrum s;
  const std::size_t n = values.size();
  if (n < 2) return s;
  for (std::size_t k = 1; 2 * k <= n; ++k)
    s.frequency.push_back(static_cast<double>(k) / (static_cast<double>(n) * spacing));
  // A value undefined leaves the mean, and with it every power, undefined (its deviations
  // passed as none, and the spectrum came out zero).
  if (std::any_of(values.begin(), values.end(), [](double v) { return !std::isfinite(v); })) {
    s.power.assign(s.frequency.size(), std::nan(""));
    return s;
  }
  double mean = 0.0;
  for (double v : values) mean += v / static_cast<double>(n);
  std::vector<double> data;
  double largest = 0.0, spread = 0.0;
  for (double v : values) {
    data.push_back(v - mean);
    largest = std::max(largest, std::abs(v));
    spread = std::max(spread, std::abs(data.back()));
  }
  // Deviations within the rounding of the values are no fluctuation but the rounding of the
  // mean's sum, which a transform of a prime length turned into powers of 1e-63 and a slope
  // (1.67 +- 0.31 for a constant series, exit 0): no power at all.
  if (spread <= 64.0 * std::numeric_limits<double>::epsilon() * largest)
    std::fill(data.begin(), data.end(), 0.0);
  const std::unique_ptr<gsl_fft_real_wavetable, WavetableFree> table(
      gsl_fft_real_wavetable_alloc(n));
  const std::unique_ptr<gsl_fft_real_workspace, WorkspaceFree> work(
      gsl_fft_real_workspace_alloc(n));
  if (gsl_fft_real_transform(data.data(), 1, n, table.get(), work.get()) != GSL_SUCCESS)
    throw InternalError("compaction: GSL's real FFT failed for " + std::to_string(n) + " values");
  // Half-complex order: data[2k-1], data[2k] the real and imaginary parts of term k; for an
  // even n, data[n-1] the real Nyquist term, counted once in the one-sided spectrum.
  const double scale = spacing / static_cast<double>(n);
  for (std::size_t k = 1; 2 * k <= n; ++k) {
    const bool nyquist = 2 * k == n;
    const double re = data[2 * k - 1], im = nyquist ? 0.0 : data[2 * k];
    s.power.push_back((nyquist ? 1.0 : 2.0) * scale * (re * re + im * im));
  }
  return s;
}

std::size_t positive_powers(const Spectrum& s) {
  return static_cast<std::size_t>(
      std::count_if(s.power.begin(), s.power.end(), [](double p) { return p > 0.0; }));
}

Slope log_log_slope(const Spectrum& s) {
  Slope slope{std::nan(""), std::nan("")};
  std::vector<double> x, y;
  for (std::size_t k = 0; k < s.frequency.size(); ++k) {
    if (s.power[k] > 0.0) {
      x.push_back(std::log(s.frequency[k]));
      y.push_back(std::log(s.power[k]));
    }
  }
  const std::size_t m = x.size();
  if (m < 3) return slope;
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    mx += x[k] / static_cast<double>(m);
    my += y[k] / static_cast<double>(m);
  }
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  slope.value = sxy / sxx;
  double residuals = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const double r = y[k] - my - slope.value * (x[k] - mx);
    residuals += r * r;
  }
  slope.error = std::sqrt(residuals / static_cast<double>(m - 2) / sxx);
  return slope;
}

}  // namespace granpipe::compaction
