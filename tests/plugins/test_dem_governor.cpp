// The dem thread governor (thread_governor.hpp) on a simulated clock: it keeps all threads
// on a quiet machine, falls back to one while one is faster, and comes back when the load
// goes, paying for few probes.
#include <gtest/gtest.h>

#include <functional>

#include "thread_governor.hpp"

using granpipe::dem::ThreadGovernor;

namespace {

struct Simulated {
  double fraction_on_one = 0.0;  // of the steps
  int threads_at_end = 0;
};

// Steps until `until` seconds of a simulated clock, each taking step_seconds(threads, now).
Simulated simulate(ThreadGovernor& g, double from, double until,
                   const std::function<double(int, double)>& step_seconds) {
  double now = from;
  long steps = 0, on_one = 0;
  g.step_done(now);
  while (now < until) {
    now += step_seconds(g.threads(), now);
    on_one += g.threads() == 1;
    ++steps;
    g.step_done(now);
  }
  return {static_cast<double>(on_one) / static_cast<double>(steps), g.threads()};
}

// 1 ms a step on two threads, 1.8 ms on one: a quiet machine.
double quiet(int threads, double) { return threads == 2 ? 1e-3 : 1.8e-3; }
// A competing process: two threads stall each other at every barrier.
double busy(int threads, double) { return threads == 2 ? 3.4e-3 : 1.8e-3; }

}  // namespace

TEST(DemGovernor, KeepsAllThreadsOnAQuietMachineAndProbesLessAndLess) {
  ThreadGovernor g(2, true);
  const Simulated run = simulate(g, 0.0, 120.0, quiet);
  EXPECT_EQ(run.threads_at_end, 2);
  // Probes at 0.25, 0.8, 1.85, 3.9, 8, 16.1, 32.2, 48.3, ... s, each 0.05 s on one thread:
  // about 0.6 % of the steps.
  EXPECT_LT(run.fraction_on_one, 0.01);
  EXPECT_GT(run.fraction_on_one, 0.0);
}

TEST(DemGovernor, FallsBackToOneThreadOnABusyMachine) {
  ThreadGovernor g(2, true);
  const Simulated run = simulate(g, 0.0, 120.0, busy);
  EXPECT_EQ(run.threads_at_end, 1);
  // Two threads for the first quarter second and the probes' windows after it.
  EXPECT_GT(run.fraction_on_one, 0.97);
}

// A run of a second (a short pipeline, a test) on a busy machine: with the first probe after
// 1 s it ran on two stalling threads throughout.
TEST(DemGovernor, AShortRunOnABusyMachineFallsBackWithinHalfASecond) {
  ThreadGovernor g(2, true);
  simulate(g, 0.0, 0.5, busy);
  EXPECT_EQ(g.threads(), 1);
  // On one thread from there, but for one probe of two.
  const Simulated rest = simulate(g, 0.5, 1.0, busy);
  EXPECT_GT(rest.fraction_on_one, 0.9);
}

// Other work holding a core at the start (idle_cores()): the run starts on one thread and
// probes two only after a second, so a run of a second never stalls two threads.
TEST(DemGovernor, ARunStartedBesideOtherWorkStartsOnOneThread) {
  ThreadGovernor g(2, true, 1);
  EXPECT_EQ(g.threads(), 1);
  const Simulated first = simulate(g, 0.0, ThreadGovernor::kFirstWaitWhenBusy - 0.01, busy);
  EXPECT_EQ(first.fraction_on_one, 1.0);
  // The load gone, its first probe finds two threads faster and takes them.
  simulate(g, ThreadGovernor::kFirstWaitWhenBusy - 0.01, 1.5, quiet);
  EXPECT_EQ(g.threads(), 2);
  // All cores idle, or a governor that does not adapt: all threads from the start.
  EXPECT_EQ(ThreadGovernor(2, true, 2).threads(), 2);
  EXPECT_EQ(ThreadGovernor(2, false, 0).threads(), 2);
}

// Two threads half as fast again as one: one probe decides (a window's noise is far less).
// A difference within the margins takes two probes in a row.
TEST(DemGovernor, AWideDifferenceSwitchesAfterOneProbe) {
  ThreadGovernor g(2, true);
  simulate(g, 0.0, ThreadGovernor::kFirstWait + 0.12, busy);  // one probe: two windows
  EXPECT_EQ(g.threads(), 1);
  const auto somewhat = [](int threads, double) { return threads == 2 ? 2.4e-3 : 1.8e-3; };
  ThreadGovernor h(2, true);
  simulate(h, 0.0, ThreadGovernor::kFirstWait + 0.12, somewhat);
  EXPECT_EQ(h.threads(), 2);
  simulate(h, ThreadGovernor::kFirstWait + 0.12, 1.0, somewhat);
  EXPECT_EQ(h.threads(), 1);
}

TEST(DemGovernor, ComesBackToAllThreadsWhenTheLoadGoes) {
  ThreadGovernor g(2, true);
  const auto load_for_a_minute = [](int threads, double now) {
    return now < 60.0 ? busy(threads, now) : quiet(threads, now);
  };
  simulate(g, 0.0, 60.0, load_for_a_minute);
  EXPECT_EQ(g.threads(), 1);
  // The next probe comes within the longest wait and its two windows.
  const Simulated after =
      simulate(g, 60.0, 60.0 + ThreadGovernor::kLongestWait + 0.2, load_for_a_minute);
  EXPECT_EQ(after.threads_at_end, 2);
}

TEST(DemGovernor, KeepsItsCountWhenToldNotToAdaptOrGivenOneThread) {
  ThreadGovernor fixed(2, false), single(1, true);
  EXPECT_EQ(simulate(fixed, 0.0, 30.0, busy).fraction_on_one, 0.0);
  EXPECT_EQ(fixed.threads(), 2);
  EXPECT_EQ(simulate(single, 0.0, 30.0, quiet).fraction_on_one, 1.0);
}

TEST(DemGovernor, PausesBetweenRunsAreNotCountedAgainstTheCountTimed) {
  // A busy machine, and every 20 steps a pause of 0.1 s (a frame written): without resume()
  // the pauses would land in the windows and could make either count look slow.
  ThreadGovernor g(2, true);
  double now = 0.0;
  long steps = 0, on_one = 0;
  g.step_done(now);
  while (now < 60.0) {
    if (steps % 20 == 0) {
      now += 0.1;
      g.resume(now);
    }
    now += busy(g.threads(), now);
    on_one += g.threads() == 1;
    ++steps;
    g.step_done(now);
  }
  EXPECT_EQ(g.threads(), 1);
  EXPECT_GT(static_cast<double>(on_one) / static_cast<double>(steps), 0.95);
}

TEST(DemGovernor, AMarginalDifferenceDoesNotSwitch) {
  // One thread 5 % faster: within the margin, so no switch.
  ThreadGovernor g(2, true);
  const Simulated run =
      simulate(g, 0.0, 60.0, [](int threads, double) { return threads == 2 ? 1e-3 : 0.95e-3; });
  EXPECT_EQ(run.threads_at_end, 2);
  EXPECT_LT(run.fraction_on_one, 0.02);
}
