#pragma once
// How many of the allowed threads the loops use, chosen by measuring. Every step has
// several barriers (forces, kicks, list rebuilds), and on a machine shared with other work
// a thread that loses its core stalls the others at each: with one competing process on 2
// cores, the Brazil-nut scene took 1.9 times as long on 2 threads as on 1 (issue 22).
// Results are bit-identical for any thread count (kernels.hpp), so the count can change at
// any step and only the speed depends on it.
//
// The governor runs on the count it chose, and now and then times a short window on it
// and one on the other count (1 when it runs on all, all when it runs on 1); the other
// count wins when it is faster by a margin in two probes in a row, or by a wide one in one. A probe
// that confirms the choice doubles the wait before the next, up to kLongestWait, so that a quiet
// machine pays for few probes and a load that comes or goes is noticed within it.
namespace granpipe::dem {

class ThreadGovernor {
 public:
  // Seconds on the chosen count before a probe. Short: beside one other process, runs of 1000
  // and 5000 steps took 1.7 times as long on 2 threads as on 1 with the first probe after
  // 1 s, 1.4 and 1.2 times with it after 0.25 s.
  static constexpr double kFirstWait = 0.25;
  // ... and when the run starts on fewer threads because other work holds the cores
  // (idle_cores.hpp): the evidence is already there, and a probe of all threads costs a
  // stalled window (a run of 1000 steps is over in about a second).
  static constexpr double kFirstWaitWhenBusy = 1.0;
  static constexpr double kLongestWait = 16.0;
  static constexpr double kWindow = 0.05;  // seconds of each timed window, and
  static constexpr long kWindowSteps = 3;  // at least this many steps
  static constexpr double kMargin = 0.9;   // the other count must take < 0.9 x as long
  // ... in two probes in a row, or < 0.6 x in one: a window's noise (a thread off its core
  // for a time slice) is a tenth, not a half, and a wrong switch costs only kFirstWait.
  static constexpr double kClearMargin = 0.6;

  // allowed: the most threads the run may use; adapt = false keeps to them. idle: the cores
  // other work leaves idle at the start (idle_cores()): with fewer than allowed, the run
  // starts on one thread.
  ThreadGovernor(int allowed, bool adapt, int idle);
  ThreadGovernor(int allowed, bool adapt) : ThreadGovernor(allowed, adapt, allowed) {}

  // The count for the next step.
  int threads() const { return current_; }
  // A step ended at `now` (seconds on a steady clock); the first call starts the clock.
  void step_done(double now);
  // Steps go on at `now` after a pause (frames written, analyses run): the time since the
  // last step is not counted against the count that was timed then.
  void resume(double now);

 private:
  enum class Phase { Running, TimingChosen, TimingOther };
  void start(Phase phase, int threads, double now);
  void decide(double other_per_step, double now);

  int allowed_;
  bool adapt_;
  int chosen_;
  int current_;
  Phase phase_ = Phase::Running;
  double phase_start_ = -1.0;  // < 0: not started yet (the first step starts the clock)
  double last_step_ = 0.0;
  long phase_steps_ = 0;
  double wait_ = kFirstWait;
  double chosen_per_step_ = 0.0;
  bool other_won_once_ = false;  // the last probe's other count was faster: probe again
};

}  // namespace granpipe::dem
