#include "granpipe/contact_rows.hpp"

#include "granpipe/property.hpp"

namespace granpipe {

namespace {

template <class T>
T& column(PropertyTable& table, const char* name) {
  return table.add<T>(*find_standard(name, Scope::Contact));
}

}  // namespace

ContactTableWriter::ContactTableWriter(Frame& frame, Eigen::Index count, bool tangential)
    : frame_(frame),
      table_(frame.add_contacts(count)),
      overlap_(column<Eigen::ArrayXd>(table_, "overlap")),
      normal_(column<Coordinates>(table_, "normal_force")),
      point_(column<Coordinates>(table_, "point")),
      tangential_(tangential ? &column<Coordinates>(table_, "tangential_force") : nullptr) {}

void ContactTableWriter::set(Eigen::Index r, const ContactRow& row) {
  frame_.contact_i()[r] = row.i;
  frame_.contact_j()[r] = row.j;
  overlap_[r] = row.overlap;
  normal_.row(r) = row.normal.transpose();
  point_.row(r) = row.point.transpose();
  if (tangential_) tangential_->row(r) = row.tangential.transpose();
}

void fill_contact_table(const std::vector<ContactRow>& rows, bool tangential, Frame& frame) {
  ContactTableWriter table(frame, static_cast<Eigen::Index>(rows.size()), tangential);
  for (std::size_t k = 0; k < rows.size(); ++k) table.set(static_cast<Eigen::Index>(k), rows[k]);
}

}  // namespace granpipe
