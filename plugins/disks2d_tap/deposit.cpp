#include "deposit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "contact_geometry.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/stop_request.hpp"

namespace granpipe::disks2d_tap {
namespace {

// A contact found this far (in radians) behind a roll's start is taken as touching now:
// only rounding puts it there. Real contacts behind the start would be overlaps.
constexpr double kAngleTolerance = 1e-9;
// A contact this close ahead (relative to the radius of the path: the disk's for a fall,
// the roll's centre path for a roll) is touching already: the disk stays put. Moving it would only
// shift it by rounding, which two disks leaning on each other could repeat forever, each such shift
// releasing the other's support.
constexpr double kStayTolerance = 1e-12;
// Far from the origin a coordinate's rounding outgrows that tolerance (one ulp is 7e-12 at
// x = 32768): a roll to a contact a few ulps ahead then lands where it started, give or
// take an ulp in y, and counts as a move, so the disk rolls there forever. Contacts closer
// than this many ulps of the box's largest coordinate are touching too (at the paper's
// radius, the term takes over beyond coordinates of about 1800).
constexpr double kStayUlps = 4;
// Consecutive moves that leave a disk where it was, with none of its supports moving in
// between, before the engine calls it a cycle.
constexpr std::uint16_t kMaxStalledMoves = 1000;
// Few enough that a signal is answered within a second, many enough to cost nothing.
constexpr std::uint32_t kMovesBetweenStopChecks = 1 << 16;

// KeepTouching: a contact survives a move while the gap stays below this * radius.
constexpr double kTouchTolerance = 1e-9;

// True when the roll starts inside the circle it crosses and heads deeper in: its entry
// lies behind, its exit further ahead than that. Only rounding puts a disk inside, touching
// the other; near a grazing crossing it moves the entry by up to the square root of the
// coordinates' rounding (1e-6 rad at x = 1e5), more than any angle tolerance, and the roll
// would run on into the other disk. A roll nearer the exit is leaving the other disk.
bool inside_already(const RollPath& path, const RollCrossings& c) {
  const double behind = -path.angle_to(c.entry_x, c.entry_y);
  return behind > kAngleTolerance && path.angle_to(c.exit_x, c.exit_y) > behind;
}

// Most disks of radius >= r_min that can touch one disk of radius r_max, plus one.
std::size_t touch_capacity(double r_min, double r_max) {
  const double half_angle = std::asin(r_min / (r_min + r_max));
  return static_cast<std::size_t>(std::floor(std::numbers::pi / half_angle)) + 1;
}

}  // namespace

Deposit::Deposit(DiskPacking& packing, DepositOptions options) : p_(packing), options_(options) {
  reset();
}

void Deposit::reset() {
  const std::size_t n = p_.size();
  max_radius_ = p_.max_radius();
  const double r_min = p_.min_radius();
  unstable_.clear();
  slot_.assign(n, -1);
  stalled_.assign(n, 0);
  cell_.assign(n, 0);
  clearance_.assign(n, 0.0);
  held_count_.assign(n, 0);
  capacity_ = n == 0 ? 1 : touch_capacity(r_min, max_radius_);
  held_.assign(n * capacity_, -1);
  cached_divisor_ = -1;
  position_ulp_ = std::numeric_limits<double>::epsilon() * std::max(p_.width, p_.top());
  if (n == 0) return;

  // Cells just below smallest diameter / sqrt 2 hold at most one disk centre.
  const double cell = std::sqrt(2.0) * r_min * (1.0 - 1e-9);
  lookahead_ = std::max(cell, options_.delta);
  grid_.reset(p_.width, std::max(p_.top(), cell), cell, 2.0 * max_radius_ + lookahead_);
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::int32_t>(k);
    if (!grid_.covers(p_.x[k], p_.y[k])) {
      std::ostringstream s;
      s << "disks2d_tap: disk " << k << " at (" << p_.x[k] << ", " << p_.y[k]
        << ") lies outside the box of width " << p_.width;
      throw InternalError(s.str());
    }
    cell_[k] = grid_.cell_of(p_.x[k], p_.y[k]);
    grid_.put(i, cell_[k]);
    if (p_.y[k] <= p_.r[k]) {
      p_.first[k] = p_.second[k] = kBase;
    } else if (p_.first[k] == kBase) {
      p_.first[k] = p_.second[k] = kNone;  // a label left over from before it was lifted
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::int32_t>(k);
    if (p_.first[k] != kBase) {
      hold(i, p_.first[k]);
      hold(i, p_.second[k]);
    }
    set_unstable(i, !p_.stable(k));
  }
}

double Deposit::stay_distance(double radius) const {
  return std::max(kStayTolerance * radius, kStayUlps * position_ulp_);
}

const std::pair<double, double>& Deposit::roll_rotation(double divisor) {
  if (divisor != cached_divisor_) {
    const double angle = options_.delta / divisor;
    cached_divisor_ = divisor;
    cached_rotation_ = {std::cos(angle), std::sin(angle)};
  }
  return cached_rotation_;
}

Move Deposit::move(std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  if (p_.stable(k)) return Move::None;
  return p_.first[k] == kNone ? fall(i) : roll(i);
}

Move Deposit::fall(std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  const double xi = p_.x[k], yi = p_.y[k], ri = p_.r[k], delta = options_.delta;
  ++stats_.falls;
  // Within the known clearance (with a margin for its rounding) the fall is free.
  if (clearance_[k] > delta * (1.0 + 1e-9)) {
    clearance_[k] -= delta;
    place(i, xi, yi - delta);
    release_held(i);
    stalled_[k] = 0;
    return Move::Fall;
  }

  // The first obstacle below within the lookahead: the one reached after the shortest
  // drop.
  double drop = lookahead_, y_new = yi - delta;
  PartnerCode hit = kNone;
  if (yi - ri <= drop) {
    drop = yi - ri;
    y_new = ri;
    hit = kBase;
  }
  const double reach = ri + max_radius_;
  grid_.for_each_in(xi - reach, xi + reach, yi - lookahead_ - reach, yi, [&](std::int32_t j) {
    if (j == i) return;
    const auto m = static_cast<std::size_t>(j);
    double y_hit;
    if (fall_contact(xi, yi, p_.x[m], p_.y[m], ri + p_.r[m], y_hit) && yi - y_hit < drop) {
      drop = yi - y_hit;
      y_new = y_hit;
      hit = j;
    }
  });
  if (drop > delta) {  // nothing within this fall: remember how far is free
    clearance_[k] = drop - delta;
    hit = kNone;
    y_new = yi - delta;
  } else {
    clearance_[k] = 0.0;
  }
  // Landing on the base is final, so it is always placed exactly.
  const bool moved = (drop > stay_distance(ri) || hit == kBase) && place(i, xi, y_new);
  if (moved) release_held(i);
  note_zero_move(i, moved);

  if (hit == kNone) return Move::Fall;
  if (hit == kBase) {
    p_.first[k] = p_.second[k] = kBase;
    set_unstable(i, false);
    return Move::LandOnBase;
  }
  p_.first[k] = hit;
  hold(i, hit);
  return Move::LandOnDisk;
}

Move Deposit::roll(std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  const PartnerCode s = p_.first[k];
  const auto sk = static_cast<std::size_t>(s);
  const double xi = p_.x[k], yi = p_.y[k], ri = p_.r[k];
  const double xs = p_.x[sk], ys = p_.y[sk], R = ri + p_.r[sk];
  ++stats_.rolls;

  const double vx = xi - xs, vy = yi - ys, len = std::sqrt(vx * vx + vy * vy);
  RollPath path{xs, ys, R, vx / len, vy / len, 0.0};
  if (path.uy <= 0.0) {  // not above its support (only hand-made scenes start so)
    unhold(i, s);
    p_.first[k] = kNone;
    note_zero_move(i, false);
    return Move::RollOff;
  }
  // Downhill is away from the top of the support; from exactly the top, away from the
  // nearer side wall (otherwise a disk perched on one against a wall never settles).
  path.h = path.ux > 0.0 ? 1.0 : path.ux < 0.0 ? -1.0 : (xi < 0.5 * p_.width ? 1.0 : -1.0);

  // The free end of the roll, cut where the centre reaches the support's height.
  const double divisor = options_.measure == RollMeasure::CentrePath ? R : p_.r[sk];
  const auto [c, sn] = roll_rotation(divisor);
  double ex = path.ux * c + path.h * path.uy * sn, ey = path.uy * c - path.h * path.ux * sn;
  double end_angle = options_.delta / divisor;
  const bool off = ey <= 0.0;
  if (off) {
    ex = path.h;
    ey = 0.0;
    end_angle = std::atan2(path.uy, path.h * path.ux);
  }
  const double xe = xs + R * ex, ye = ys + R * ey;
  const double chord = std::sqrt((xe - xi) * (xe - xi) + (ye - yi) * (ye - yi));

  // The first obstacle along the arc.
  double best = end_angle, qx = ex, qy = ey;
  PartnerCode hit = kNone;
  auto consider = [&](PartnerCode who, double ox, double oy) {
    double a = path.angle_to(ox, oy);
    if (a < -kAngleTolerance) return;
    a = std::max(a, 0.0);
    if (a < best) {
      best = a;
      hit = who;
      qx = ox;
      qy = oy;
    }
  };
  double ox, oy;
  auto consider_wall = [&](PartnerCode wall, double x_contact) {
    // Against it already: rounding may put the contact behind the start, by up to the
    // square root of x's rounding when the roll meets the wall at a grazing angle.
    if (std::abs(xi - x_contact) <= stay_distance(ri)) {
      consider(wall, path.ux, path.uy);
      return;
    }
    roll_reach_x(path, x_contact, ox, oy);
    consider(wall, ox, oy);
  };
  if (path.h > 0.0 && xe > p_.width - ri) {
    consider_wall(kRightWall, p_.width - ri);
  } else if (path.h < 0.0 && xe < ri) {
    consider_wall(kLeftWall, ri);
  }
  if (ye < ri) {
    roll_reach_y(path, ri, ox, oy);
    consider(kBase, ox, oy);
  }
  const double reach = ri + max_radius_;
  grid_.for_each_in(std::min(xi, xe) - reach, std::max(xi, xe) + reach, ye - reach, yi + reach,
                    [&](std::int32_t j) {
                      if (j == i || j == s) return;
                      const auto m = static_cast<std::size_t>(j);
                      const double Rj = ri + p_.r[m], dx = p_.x[m] - xi, dy = p_.y[m] - yi;
                      const double limit = Rj + chord;
                      if (dx * dx + dy * dy >= limit * limit) return;
                      RollCrossings c;
                      if (!roll_crossings(path, p_.x[m], p_.y[m], Rj, c)) return;
                      if (inside_already(path, c)) {
                        consider(j, path.ux, path.uy);
                      } else {
                        consider(j, c.entry_x, c.entry_y);
                      }
                    });

  // Rolling off and landing on the base end in exact positions, so they are always made:
  // a disk left a rounding error above its support's height would land on it again.
  const bool rolled_off = off && hit == kNone;
  const double x_new = rolled_off ? xs + path.h * R : xs + R * qx;
  const double y_new = rolled_off ? ys : ys + R * qy;
  const bool exact_end = rolled_off || hit == kBase;
  const bool moved = (best * R > stay_distance(R) || exact_end) && place(i, x_new, y_new);
  if (moved) {
    release_held(i);
    forget_clearance_above(i);
  }
  note_zero_move(i, moved);

  if (hit == kNone) {
    if (!off) return Move::Roll;
    unhold(i, s);
    p_.first[k] = kNone;
    return Move::RollOff;
  }
  if (hit == kBase) {
    unhold(i, s);
    p_.first[k] = p_.second[k] = kBase;
    set_unstable(i, false);
    return Move::RollOntoBase;
  }
  if (pair_stable(i, s, hit)) {
    p_.second[k] = hit;
    hold(i, hit);
    set_unstable(i, false);
    return Move::RollToRest;
  }
  // An unstable pair: the lower contact becomes the first support. Rolling into a
  // contact on the support's side always makes it the lower one.
  if (is_disk(hit) && p_.contact_y(k, hit) < p_.contact_y(k, s)) {
    unhold(i, s);
    p_.first[k] = hit;
    hold(i, hit);
  }
  return Move::RollToNewSupport;
}

void Deposit::forget_clearance_above(std::int32_t i) {
  // A disk whose search reached no lower than lookahead_ below it cannot have missed i
  // if i lies farther down than that.
  const auto k = static_cast<std::size_t>(i);
  const double reach = p_.r[k] + max_radius_;
  grid_.for_each_in(p_.x[k] - reach, p_.x[k] + reach, p_.y[k], p_.y[k] + reach + lookahead_,
                    [&](std::int32_t j) { clearance_[static_cast<std::size_t>(j)] = 0.0; });
}

bool Deposit::pair_stable(std::int32_t i, PartnerCode a, PartnerCode b) const {
  // Stable when the centre's x lies between the two contact points' x (ties included).
  const auto k = static_cast<std::size_t>(i);
  auto side = [&](PartnerCode p) {
    if (p == kLeftWall) return -1.0;
    if (p == kRightWall) return 1.0;
    return p_.x[static_cast<std::size_t>(p)] - p_.x[k];
  };
  const double sa = side(a), sb = side(b);
  return (sa <= 0.0 && sb >= 0.0) || (sa >= 0.0 && sb <= 0.0);
}

bool Deposit::place(std::int32_t i, double x, double y) {
  const auto k = static_cast<std::size_t>(i);
  if (x == p_.x[k] && y == p_.y[k]) return false;
  p_.x[k] = x;
  p_.y[k] = y;
  const int cell = grid_.cell_of(x, y);
  if (cell != cell_[k]) {
    grid_.erase(cell_[k]);
    grid_.put(i, cell);
    cell_[k] = cell;
  }
  return true;
}

void Deposit::release_held(std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  std::int32_t* list = held_.data() + k * capacity_;
  std::uint32_t kept = 0;
  for (std::uint32_t n = 0; n < held_count_[k]; ++n) {
    const std::int32_t j = list[n];
    const auto m = static_cast<std::size_t>(j);
    if (options_.update == SupportUpdate::KeepTouching) {
      const double dx = p_.x[m] - p_.x[k], dy = p_.y[m] - p_.y[k];
      const double gap = std::sqrt(dx * dx + dy * dy) - p_.r[m] - p_.r[k];
      const bool pair_ok = p_.second[m] == kNone || pair_stable(j, p_.first[m], p_.second[m]);
      if (std::abs(gap) <= kTouchTolerance * p_.r[m] && pair_ok) {
        list[kept++] = j;
        continue;
      }
    }
    if (p_.first[m] == i) {
      p_.first[m] = p_.second[m];
      p_.second[m] = kNone;
    } else {
      p_.second[m] = kNone;
    }
    if (is_side_wall(p_.first[m])) p_.first[m] = kNone;  // a wall alone holds nothing up
    set_unstable(j, true);
    // A support really moved: moves of j that find the same contact again (a disk leaning
    // on one that rolls over it) are not a cycle.
    stalled_[m] = 0;
  }
  held_count_[k] = kept;
}

void Deposit::hold(std::int32_t i, PartnerCode by) {
  if (!is_disk(by)) return;
  const auto b = static_cast<std::size_t>(by);
  if (held_count_[b] >= capacity_) {
    throw InternalError("disks2d_tap: disk " + std::to_string(by) + " would support more than " +
                        std::to_string(capacity_) + " disks, more than can touch it");
  }
  held_[b * capacity_ + held_count_[b]++] = i;
}

void Deposit::unhold(std::int32_t i, PartnerCode by) {
  if (!is_disk(by)) return;
  const auto b = static_cast<std::size_t>(by);
  std::int32_t* list = held_.data() + b * capacity_;
  for (std::uint32_t n = 0; n < held_count_[b]; ++n) {
    if (list[n] == i) {
      list[n] = list[--held_count_[b]];
      return;
    }
  }
}

void Deposit::set_unstable(std::int32_t i, bool unstable) {
  auto& slot = slot_[static_cast<std::size_t>(i)];
  if (unstable && slot < 0) {
    slot = static_cast<std::int32_t>(unstable_.size());
    unstable_.push_back(i);
  } else if (!unstable && slot >= 0) {
    const std::int32_t last = unstable_.back();
    unstable_[static_cast<std::size_t>(slot)] = last;
    slot_[static_cast<std::size_t>(last)] = slot;
    unstable_.pop_back();
    slot = -1;
  }
}

void Deposit::note_zero_move(std::int32_t i, bool moved) {
  auto& count = stalled_[static_cast<std::size_t>(i)];
  if (moved) {
    count = 0;
    return;
  }
  if (++count > kMaxStalledMoves) {
    const auto k = static_cast<std::size_t>(i);
    std::ostringstream s;
    s.precision(17);
    s << "disks2d_tap: disk " << i << " at (" << p_.x[k] << ", " << p_.y[k]
      << ") cycles through moves of length zero (first support " << p_.first[k] << ", second "
      << p_.second[k] << ")";
    throw InternalError(s.str());
  }
}

// A deposition of a wide bed may take minutes: a signal is looked for between moves.
void Deposit::run(RandomStream& rng) {
  if (options_.order == MoveOrder::Random) {
    for (std::uint32_t moves = 0; !unstable_.empty(); ++moves) {
      if (moves % kMovesBetweenStopChecks == 0) throw_if_stop_requested();
      move(unstable_[rng.below(unstable_.size())]);
    }
    return;
  }
  while (!unstable_.empty()) {
    throw_if_stop_requested();
    sweep_.assign(unstable_.begin(), unstable_.end());
    rng.shuffle(sweep_);
    for (const std::int32_t i : sweep_) {
      if (slot_[static_cast<std::size_t>(i)] >= 0) move(i);
    }
  }
}

}  // namespace granpipe::disks2d_tap
