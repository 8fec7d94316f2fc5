#include "granpipe/contact_rows.hpp"

#include "granpipe/property.hpp"

namespace granpipe {

void fill_contact_table(const std::vector<ContactRow>& rows, bool tangential, Frame& frame) {
  PropertyTable& table = frame.add_contacts(static_cast<Eigen::Index>(rows.size()));
  auto& overlap = table.add<Eigen::ArrayXd>(*find_standard("overlap", Scope::Contact));
  auto& normal = table.add<Coordinates>(*find_standard("normal_force", Scope::Contact));
  auto& point = table.add<Coordinates>(*find_standard("point", Scope::Contact));
  Coordinates* tangent =
      tangential ? &table.add<Coordinates>(*find_standard("tangential_force", Scope::Contact))
                 : nullptr;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    frame.contact_i()[r] = rows[k].i;
    frame.contact_j()[r] = rows[k].j;
    overlap[r] = rows[k].overlap;
    normal.row(r) = rows[k].normal.transpose();
    point.row(r) = rows[k].point.transpose();
    if (tangent) tangent->row(r) = rows[k].tangential.transpose();
  }
}

}  // namespace granpipe
