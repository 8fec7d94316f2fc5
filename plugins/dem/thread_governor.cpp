#include "thread_governor.hpp"

#include <algorithm>

namespace granpipe::dem {

ThreadGovernor::ThreadGovernor(int allowed, bool adapt, int idle)
    : allowed_(allowed), adapt_(adapt && allowed > 1), chosen_(allowed), current_(allowed) {
  if (!adapt_ || idle >= allowed) return;
  chosen_ = current_ = 1;
  wait_ = kFirstWaitWhenBusy;
}

void ThreadGovernor::start(Phase phase, int threads, double now) {
  phase_ = phase;
  current_ = threads;
  phase_start_ = now;
  phase_steps_ = 0;
}

void ThreadGovernor::step_done(double now) {
  if (!adapt_) return;
  if (phase_start_ < 0.0) {
    phase_start_ = last_step_ = now;
    return;
  }
  last_step_ = now;
  ++phase_steps_;
  const double elapsed = now - phase_start_;
  const bool window_done = elapsed >= kWindow && phase_steps_ >= kWindowSteps;
  const double per_step = elapsed / static_cast<double>(phase_steps_);
  switch (phase_) {
    case Phase::Running:
      if (elapsed >= wait_) start(Phase::TimingChosen, chosen_, now);
      break;
    case Phase::TimingChosen:
      if (window_done) {
        chosen_per_step_ = per_step;
        start(Phase::TimingOther, chosen_ == 1 ? allowed_ : 1, now);
      }
      break;
    case Phase::TimingOther:
      if (window_done) decide(per_step, now);
      break;
  }
}

void ThreadGovernor::resume(double now) {
  if (phase_start_ < 0.0) return;
  phase_start_ += now - last_step_;
  last_step_ = now;
}

void ThreadGovernor::decide(double other_per_step, double now) {
  if (other_per_step < kMargin * chosen_per_step_) {
    // Two windows in a row must say so: a busy machine's windows are noisy (a thread that
    // lost its core for a time slice, or a competitor that paused), and a wrong switch
    // costs the whole wait before the next probe.
    if (!other_won_once_ && other_per_step >= kClearMargin * chosen_per_step_) {
      other_won_once_ = true;
      start(Phase::TimingChosen, chosen_, now);
      return;
    }
    chosen_ = current_;
    wait_ = kFirstWait;
  } else {
    wait_ = std::min(2.0 * wait_, kLongestWait);
  }
  other_won_once_ = false;
  start(Phase::Running, chosen_, now);
}

}  // namespace granpipe::dem
