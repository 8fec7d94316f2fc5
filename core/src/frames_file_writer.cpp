#include "frames_file_writer.hpp"

#include "granpipe/atomic_file.hpp"

namespace granpipe {

FramesFileWriter::FramesFileWriter(std::filesystem::path path, std::string provenance_json,
                                   FileRecord* files)
    : final_path_(std::move(path)), provenance_(std::move(provenance_json)), files_(files) {
  partial_path_ = final_path_;
  partial_path_.replace_extension(".partial.h5");
}

void FramesFileWriter::write(const Frame& frame) {
  if (!file_) open();
  file_->append(frame);
}

void FramesFileWriter::open() {
  file_ = std::make_unique<FrameWriter>(partial_path_, provenance_);
  if (files_) files_->add(partial_path_);
}

void FramesFileWriter::close() {
  // A run of no frame still leaves a (frameless) frames.h5, as readers expect one.
  if (!file_) open();
  file_->close();
  move_into_place(partial_path_, final_path_);
  if (files_) files_->add(final_path_);
}

}  // namespace granpipe
