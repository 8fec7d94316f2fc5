#include "text_lines.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

#include "granpipe/errors.hpp"
#include "gzip_members.hpp"

namespace granpipe::lammps_dump {

namespace {

// Large reads: a dump is read from start to end, and zlib's default buffer is 8 KiB.
constexpr unsigned kBufferBytes = 1u << 18;

}  // namespace

TextLines::TextLines(std::string path)
    : path_(std::move(path)), file_(gzopen(path_.c_str(), "rb")) {
  if (!file_) throw InputError(path_ + ": cannot open: " + std::strerror(errno));
  gzbuffer(file_, kBufferBytes);
}

TextLines::~TextLines() { gzclose(file_); }

bool TextLines::next(std::string& line) {
  line.clear();
  char chunk[4096];
  bool ended = false;
  while (!ended && gzgets(file_, chunk, sizeof chunk)) {
    const std::size_t n = std::strlen(chunk);
    crc_ = static_cast<std::uint32_t>(
        crc32(crc_, reinterpret_cast<const Bytef*>(chunk), static_cast<uInt>(n)));
    ended = n > 0 && chunk[n - 1] == '\n';
    line.append(chunk, ended ? n - 1 : n);
  }
  if (!ended) check_read_error();
  if (!ended && line.empty()) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++number_;
  cut_ = !ended;
  return true;
}

void TextLines::check_read_error() {
  int code = Z_OK;
  const char* message = gzerror(file_, &code);
  if (code == Z_OK) return;
  // zlib's "unexpected end of file": the compressed stream was cut.
  if (code == Z_BUF_ERROR) {
    ended_early_ = true;
    return;
  }
  if (code == Z_ERRNO) {
    throw InputError(path_ + ": line " + std::to_string(number_ + 1) +
                     ": cannot read: " + std::strerror(errno));
  }
  // zlib reads ahead in large blocks, so the fault lies somewhere after the last line read,
  // not necessarily in the next; its message repeats the path.
  std::string why = message;
  if (why.starts_with(path_ + ": ")) why.erase(0, path_.size() + 2);
  const std::string where =
      number_ == 0 ? "before its first line" : "after line " + std::to_string(number_);
  throw InputError(path_ + ": the gzip data are corrupt (" + why + "), found " + where);
}

void TextLines::check_nothing_follows() {
  if (gzdirect(file_)) return;
  const auto stray = bytes_after_gzip(path_, gztell(file_), crc_);
  if (!stray) return;
  throw InputError(path_ + ": expected nothing after the gzip data, got bytes that are not " +
                   "gzip from byte " + std::to_string(*stray) +
                   " on (text appended to a compressed file?): decompress it, append, compress "
                   "it again");
}

std::int64_t TextLines::offset() const { return gztell(file_); }

void TextLines::seek(std::int64_t offset, long line_before) {
  if (gzseek(file_, offset, SEEK_SET) != offset) {
    throw InputError(path_ + ": cannot go back to line " + std::to_string(line_before + 1) +
                     " (the file changed while it was read?)");
  }
  number_ = line_before;
  cut_ = false;
}

}  // namespace granpipe::lammps_dump
