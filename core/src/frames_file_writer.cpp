#include "frames_file_writer.hpp"

#include "granpipe/atomic_file.hpp"

namespace granpipe {

FramesFileWriter::FramesFileWriter(std::filesystem::path path, std::string provenance_json)
    : final_path_(std::move(path)), provenance_(std::move(provenance_json)) {
  partial_path_ = final_path_;
  partial_path_.replace_extension(".partial.h5");
}

void FramesFileWriter::write(const Frame& frame) {
  if (!file_) file_ = std::make_unique<FrameWriter>(partial_path_, provenance_);
  file_->append(frame);
}

void FramesFileWriter::close() {
  // A run of no frame still leaves a (frameless) frames.h5, as readers expect one.
  if (!file_) file_ = std::make_unique<FrameWriter>(partial_path_, provenance_);
  file_->close();
  move_into_place(partial_path_, final_path_);
}

}  // namespace granpipe
