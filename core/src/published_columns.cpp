#include "published_columns.hpp"

#include <algorithm>

#include "did_you_mean.hpp"

namespace granpipe {

namespace {

std::string column_name(const Property& c) {
  return std::string(to_string(c.scope)) + " column \"" + c.name + "\"";
}

// "3 rows x 1 component": what a column holds.
std::string describe_size(Eigen::Index rows, int components) {
  return std::to_string(rows) + " rows x " + std::to_string(components) +
         (components == 1 ? " component" : " components");
}

}  // namespace

FrameColumns::FrameColumns(const FrameContent& source_content, const std::string& source)
    : content_{source_content.dim, source_content.contacts, {}},
      source_("source \"" + source + "\"") {
  for (const Property& p : source_content.columns) columns_.push_back({p, "the " + source_, false});
}

const FrameColumns::Provided* FrameColumns::find(const Property& column) const {
  for (const Provided& p : columns_) {
    if (p.property.name == column.name && p.property.scope == column.scope) return &p;
  }
  return nullptr;
}

std::string FrameColumns::suggestion(const Property& column) const {
  std::vector<std::string> names;
  for (const Provided& p : columns_) {
    if (p.property.scope == column.scope) names.push_back(p.property.name);
  }
  return did_you_mean(column.name, names);
}

std::string FrameColumns::lacks(const FrameContent& need) const {
  const std::string source_note = " (" + source_ + ")";
  if (need.dim && content_.dim && need.dim != content_.dim) {
    return std::to_string(need.dim) + "D frames, but the source gives " +
           std::to_string(content_.dim) + "D" + source_note;
  }
  if (need.contacts && !content_.contacts)
    return "contacts, which the source does not provide" + source_note;
  for (const Property& c : need.columns) {
    if (is_required(c)) continue;
    const Provided* got = find(c);
    if (!got) {
      return column_name(c) + suggestion(c) +
             ", which neither the source nor an analyzer before it provides" + source_note;
    }
    if (!got->property.matches(c)) {
      return column_name(c) + " as " + describe_type(c) + ", but " + got->by +
             (got->published ? " publishes" : " provides") + " it as " +
             describe_type(got->property);
    }
  }
  return "";
}

std::vector<std::string> FrameColumns::publish(const std::vector<Property>& columns,
                                               const std::string& at, const std::string& title) {
  std::vector<std::string> warnings;
  const std::string start = at + ": " + title + " publishes the ";
  for (const Property& c : columns) {
    if (c.scope == Scope::Frame) {  // publish() is never asked for them
      throw InputError(start + "frame column \"" + c.name +
                       "\": expected particle or contact columns only");
    }
    if (is_required(c)) {
      throw InputError(start + column_name(c) + ", which every frame carries: choose another name");
    }
    const Property* standard = find_standard(c.name, c.scope);
    if (standard && !standard->matches(c)) {
      throw InputError(start + column_name(c) + " as " + describe_type(c) +
                       ", but the standard column of "
                       "that name is " +
                       describe_type(*standard) + ": choose another name");
    }
    const Provided* earlier = find(c);
    if (earlier && earlier->published) {
      throw InputError(start + column_name(c) + ", which " + earlier->by +
                       " publishes too; give one of "
                       "them \"publish\": false (docs/pipelines.md, \"Published columns\")");
    }
    if (earlier && !earlier->property.matches(c)) {
      throw InputError(start + column_name(c) + " as " + describe_type(c) + ", but " + earlier->by +
                       " provides it as " + describe_type(earlier->property) +
                       ": choose another name");
    }
    if (earlier) {
      warnings.push_back(at + ": " + title + " replaces the " + column_name(c) + " that " +
                         earlier->by + " provides (an earlier run's, read back) with its own");
    }
    std::erase_if(columns_, [&](const Provided& p) {
      return p.property.name == c.name && p.property.scope == c.scope;
    });
    columns_.push_back({c, title + " at " + at, true});
  }
  return warnings;
}

namespace {

// Fills `columns` by the analyzer's publish(), saying who broke its contract.
void ask_to_publish(Analyzer& analyzer, PropertyTable& columns, const std::string& who) {
  try {
    analyzer.publish(columns);
  } catch (const InternalError& e) {
    throw InputError(who + ": publish(): " + e.what() +
                     "; publish() fills only the columns publishes() declares");
  }
}

// The columns an analyzer publishes of one scope join the frame, for the analyzers after
// it and the writers; the runner removes them before the source fills the next frame.
void publish_scope(Analyzer& analyzer, const std::vector<Property>& declared,
                   const std::string& who, Scope scope, PropertyTable& table, int dim) {
  PropertyTable columns(scope, table.rows(), dim);
  for (const Property& c : declared) {
    if (c.scope == scope) columns.add(c);
  }
  if (columns.size() == 0) return;
  ask_to_publish(analyzer, columns, who);
  const std::string rows_are =
      scope == Scope::Particle ? " (one row per particle)" : " (one row per contact)";
  for (std::size_t k = 0; k < columns.size(); ++k) {
    Column& c = columns.column(k);
    const std::string name = column_name(c.property());
    // Zeros with the author's unit and description would pass for a result.
    if (!c.handed_out())
      throw InputError(who + ": publish() never filled the " + name + " it declares");
    const int components = c.property().components_in(dim);
    if (c.rows() != table.rows() || c.components() != components) {
      throw InputError(who + ": publish() gave the " + name + " " +
                       describe_size(c.rows(), c.components()) + ", expected " +
                       describe_size(table.rows(), components) + rows_are);
    }
    table.remove(c.name());  // the source's column of that name, if any
    table.add(c.property()).storage() = std::move(c.storage());
  }
}

}  // namespace

void publish_columns(Analyzer& analyzer, const std::vector<Property>& declared,
                     const std::string& who, Frame& frame) {
  if (declared.empty()) return;
  publish_scope(analyzer, declared, who, Scope::Particle, frame.particles, frame.dim);
  if (frame.contacts)
    publish_scope(analyzer, declared, who, Scope::Contact, *frame.contacts, frame.dim);
}

void remove_published(const std::vector<Property>& declared, Frame& frame) {
  for (const Property& c : declared) {
    if (c.scope == Scope::Particle) frame.particles.remove(c.name);
    if (c.scope == Scope::Contact && frame.contacts) frame.contacts->remove(c.name);
  }
}

}  // namespace granpipe
