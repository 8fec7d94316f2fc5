#pragma once
// The columns analyzers publish (Analyzer::publishes and publish): checked against what
// the frames carry before a run, and joined to each frame after the analyzer consumed it.
// The rules are in docs/pipelines.md, "Published columns".
#include <string>
#include <vector>

#include "granpipe/plugin.hpp"

namespace granpipe {

// What the frames carry at one place in the pipeline, and who provides each column.
class FrameColumns {
 public:
  // `source` names the source plugin.
  FrameColumns(const FrameContent& source_content, const std::string& source);

  // What `need` asks that the frames lack, as the tail of "analyzer X needs ...", or "".
  std::string lacks(const FrameContent& need) const;

  // Adds what the analyzer `title` ("analyzer \"packing\"") at `at` ("analyzers[1]")
  // publishes. Throws InputError, starting with `at`, for a frame column, a required one,
  // one that an earlier analyzer publishes, or one of another type than the standard
  // column or the source's column of its name. Returns a warning, starting with `at`, for
  // each source column it replaces.
  std::vector<std::string> publish(const std::vector<Property>& columns, const std::string& at,
                                   const std::string& title);

 private:
  struct Provided {
    Property property;
    std::string by;  // "the source \"h5md\"", "analyzer \"packing\" at analyzers[0]"
    bool published;
  };
  const Provided* find(const Property& column) const;
  // " (did you mean \"x\"?)" among the frames' columns of `column`'s scope.
  std::string suggestion(const Property& column) const;

  FrameContent content_;  // dim and contacts; the columns are in columns_
  std::string source_;    // "source \"h5md\""
  std::vector<Provided> columns_;
};

// Asks `analyzer` to fill the columns it declares (`declared`) and joins them to `frame`,
// each in place of a source column of its name. Throws InputError starting with `who`
// ("analyzer \"packing\"") when publish() leaves a column unfilled, gives it another size,
// or asks for a column it did not declare.
void publish_columns(Analyzer& analyzer, const std::vector<Property>& declared,
                     const std::string& who, Frame& frame);

// Removes what publish_columns added.
void remove_published(const std::vector<Property>& declared, Frame& frame);

}  // namespace granpipe
