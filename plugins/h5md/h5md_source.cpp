#include "h5md_source.hpp"

#include <cmath>

namespace granpipe::h5md {

Schema schema() {
  Schema s;
  s.path("file", std::nullopt, "the H5MD file to read (a granpipe frames.h5 or another tool's)");
  s.integer("first", 0, "index of the first frame read (0: the first in the file)").min(0);
  s.integer("last", -1, "index of the last frame read, inclusive (-1: the last in the file)")
      .min(-1);
  s.integer("stride", 1, "read every stride-th frame from first on").min(1);
  s.string("group", std::string(""),
           "particles group of the file (/particles/<group>); empty: \"all\" or the only one");
  s.real("radius", 0.5, "radius of every particle when the file stores none (other tools' files)")
      .min(0.0, true)
      .unit("length");
  return s;
}

H5mdSource::H5mdSource(const PluginContext& ctx)
    : reader_(ctx.params.string("file"), ctx.params.string("group"), ctx.params.real("radius")),
      first_(static_cast<long>(ctx.params.integer("first"))),
      last_(static_cast<long>(ctx.params.integer("last"))),
      stride_(static_cast<long>(ctx.params.integer("stride"))) {
  const FrameFileInfo& info = reader_.info();
  const long frames = info.frames;
  const std::string held = " (" + info.path + " holds " + std::to_string(frames) + " frames)";
  if (frames == 0) throw InputError("h5md.file: expected a file with frames, got none" + held);
  if (first_ >= frames) {
    throw InputError("h5md.first: expected a frame index below " + std::to_string(frames) +
                     ", got " + std::to_string(first_) + held);
  }
  if (last_ == -1) last_ = frames - 1;
  if (last_ >= frames) {
    throw InputError("h5md.last: expected -1 or a frame index below " + std::to_string(frames) +
                     ", got " + std::to_string(last_) + held);
  }
  if (last_ < first_) {
    throw InputError("h5md.last: expected -1 or an index >= first (" + std::to_string(first_) +
                     "), got " + std::to_string(last_));
  }
  if (!info.complete) {
    ctx.log.warn(info.path + ": the writer never finished this file (stopped or crashed); "
                 "reading the " + std::to_string(frames) + " frames it completed");
  }
  next_ = first_;
}

FrameContent H5mdSource::content() const {
  const FrameFileInfo& info = reader_.info();
  return {info.dim, info.has_velocity, info.has_contacts, info.has_supports};
}

Source::Work H5mdSource::work() const {
  return {static_cast<double>((last_ - first_) / stride_ + 1), "frames", false};
}

bool H5mdSource::next(Frame& frame) {
  if (next_ > last_) return false;
  frame = reader_.read(next_);
  next_ += stride_;
  ++read_;
  return true;
}

void H5mdSource::finish(Results& results) {
  results.add_scalar("frames_read", static_cast<double>(read_), std::nan(""), "",
                     "frames read from " + reader_.info().path);
  results.add_scalar("particles", static_cast<double>(reader_.info().particles), std::nan(""),
                     "", "particles per frame");
}

}  // namespace granpipe::h5md
