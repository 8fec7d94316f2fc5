#pragma once
// frames.h5 as a Writer: the core's own frame store, driven like any writer plugin. Frames
// go to frames.partial.h5 (marked incomplete until closed); close() renames it, so a run
// that stops early never leaves a frames.h5 that looks finished.
#include <filesystem>
#include <memory>
#include <string>

#include "granpipe/frame_store.hpp"
#include "granpipe/output_files.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe {

class FramesFileWriter : public Writer {
 public:
  // `path` is the final name (…/frames.h5); the file is created at the first frame. Each
  // name is recorded in `files` (when given) once the file is made under it.
  FramesFileWriter(std::filesystem::path path, std::string provenance_json,
                   FileRecord* files = nullptr);
  void write(const Frame& frame) override;
  void close() override;

 private:
  void open();

  std::filesystem::path final_path_, partial_path_;
  std::string provenance_;
  FileRecord* files_;
  std::unique_ptr<FrameWriter> file_;
};

}  // namespace granpipe
