#include "granpipe/frame.hpp"

#include <cmath>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe {

void Contacts::resize(Eigen::Index m, int dim) {
  i.resize(m);
  j.resize(m);
  overlap.resize(m);
  normal_force.resize(m, dim);
  tangential_force.resize(m, dim);
  point.resize(m, dim);
}

void Frame::resize(Eigen::Index n, int dimension) {
  dim = dimension;
  position = Coordinates::Zero(n, dimension);
  radius = Eigen::ArrayXd::Zero(n);
  id = IndexArray::LinSpaced(n, 0, n - 1);
  species = IntArray::Zero(n);
  velocity.reset();
  angular_velocity.reset();
  contacts.reset();
  supports.reset();
}

namespace {
std::string describe_particle(const Frame& f, Eigen::Index k) {
  std::ostringstream s;
  s << "particle " << k << " (id " << f.id[k] << ")";
  return s.str();
}
}  // namespace

void Frame::check(const std::string& where) const {
  if (dim != 2 && dim != 3) {
    throw InputError(where + ": expected dimension 2 or 3, got " + std::to_string(dim));
  }
  const Eigen::Index n = position.rows();
  auto sized = [&](Eigen::Index rows, const char* what) {
    if (rows != n) {
      throw InputError(where + ": " + what + " has " + std::to_string(rows) +
                       " entries, expected " + std::to_string(n) + " (one per particle)");
    }
  };
  if (n > 0 && position.cols() != dim) {
    throw InputError(where + ": positions have " + std::to_string(position.cols()) +
                     " coordinates, expected " + std::to_string(dim));
  }
  sized(radius.size(), "radius");
  sized(id.size(), "id");
  sized(species.size(), "species");
  if (velocity) sized(velocity->rows(), "velocity");
  if (angular_velocity) sized(angular_velocity->rows(), "angular velocity");
  if (supports) {
    sized(supports->left.size(), "left supports");
    sized(supports->right.size(), "right supports");
  }
  if (contacts) {
    const Eigen::Index m = contacts->size();
    const bool consistent = contacts->j.size() == m && contacts->overlap.size() == m &&
                            contacts->normal_force.rows() == m && contacts->tangential_force.rows() == m &&
                            contacts->point.rows() == m;
    if (!consistent) {
      throw InputError(where + ": contact arrays have different lengths (" + std::to_string(m) +
                       " contacts in i)");
    }
    for (Eigen::Index k = 0; k < m; ++k) {
      const auto a = contacts->i[k], b = contacts->j[k];
      if (a < 0 || a >= n || b >= n || b == partner::none) {
        throw InputError(where + ": contact " + std::to_string(k) + ": expected particle indices below " +
                         std::to_string(n) + " (or a wall as second partner), got " + std::to_string(a) +
                         " and " + std::to_string(b));
      }
    }
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    for (int a = 0; a < dim; ++a) {
      if (!std::isfinite(position(k, a))) {
        std::ostringstream s;
        s << where << ": " << describe_particle(*this, k) << ": expected a finite position, got "
          << position(k, a) << " in coordinate " << a;
        throw InputError(s.str());
      }
    }
    if (!(radius[k] > 0.0) || !std::isfinite(radius[k])) {
      std::ostringstream s;
      s << where << ": " << describe_particle(*this, k) << ": expected a finite radius > 0, got "
        << radius[k];
      throw InputError(s.str());
    }
  }
}

}  // namespace granpipe
