#include "granpipe/loaded_pair_contacts.hpp"

#include <cmath>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

namespace {

void check_force(const ValueTable<double>& force, Eigen::Index row, const std::string& where) {
  for (Eigen::Index a = 0; a < force.cols(); ++a) {
    if (!std::isfinite(force(row, a))) {
      throw InputError(where + ": contact " + std::to_string(row) +
                       ": expected a finite normal_force, got " + format_number(force(row, a)) +
                       " in component " + "xyz"[a]);
    }
  }
}

void check_partners(const Frame& f, Eigen::Index row, const std::string& where) {
  if (f.contact_i()[row] == f.contact_j()[row]) {
    throw InputError(where + ": contact " + std::to_string(row) +
                     ": expected two different particles, got particle " +
                     std::to_string(f.contact_i()[row]) + " twice");
  }
}

}  // namespace

std::vector<Eigen::Index> loaded_pair_contacts(const Frame& frame, const std::string& where) {
  std::vector<Eigen::Index> rows;
  if (!frame.contacts) return rows;
  const PropertyTable& table = *frame.contacts;
  const ValueTable<double>* force =
      table.has("normal_force") ? &table.get<ValueTable<double>>("normal_force") : nullptr;
  for (Eigen::Index row = 0; row < table.rows(); ++row) {
    if (force) check_force(*force, row, where);
    if (!partner::is_particle(frame.contact_j()[row])) continue;
    check_partners(frame, row, where);
    if (!force || (force->row(row) != 0.0).any()) rows.push_back(row);
  }
  return rows;
}

bool MostLoadedFrame::offer(long frame, std::int64_t loaded) {
  if (loaded <= loaded_) return false;
  frame_ = frame;
  loaded_ = loaded;
  return true;
}

}  // namespace granpipe
