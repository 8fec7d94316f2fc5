#include "gzip_members.hpp"

#include <zlib.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "granpipe/errors.hpp"

namespace granpipe::lammps_dump {

namespace {

struct Close {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, Close>;

File open_again(const std::string& path) {
  File f(std::fopen(path.c_str(), "rb"));
  if (!f) throw InputError(path + ": cannot open again: " + std::strerror(errno));
  return f;
}

// The gzip trailer: the member's CRC-32 and its text length modulo 2^32, little-endian.
bool last_member_holds(std::FILE* f, std::int64_t text_bytes, std::uint32_t text_crc) {
  std::array<unsigned char, 8> b{};
  if (std::fseek(f, -8, SEEK_END) != 0 || std::fread(b.data(), 1, 8, f) != 8) return false;
  const auto word = [&](int at) {
    return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (std::uint32_t(b[at + 3]) << 24);
  };
  return word(0) == text_crc && word(4) == static_cast<std::uint32_t>(text_bytes);
}

// Inflates member after member (the text is thrown away) up to the first byte that is not
// part of one.
class MemberWalk {
 public:
  explicit MemberWalk(std::FILE* f) : file_(f) {
    stream_.zalloc = Z_NULL;
    stream_.zfree = Z_NULL;
    stream_.opaque = Z_NULL;
    ready_ = inflateInit2(&stream_, 15 + 16) == Z_OK;  // a gzip header and trailer
  }
  ~MemberWalk() {
    if (ready_) inflateEnd(&stream_);
  }
  MemberWalk(const MemberWalk&) = delete;
  MemberWalk& operator=(const MemberWalk&) = delete;

  std::optional<std::int64_t> first_stray_byte() {
    if (!ready_) throw InternalError("zlib: cannot start inflating (out of memory?)");
    std::rewind(file_);
    while (inflate_member()) {
      if (!refill()) return std::nullopt;  // the members end with the file
      if (!starts_member()) return only_zeros_follow() ? std::nullopt : std::optional(consumed_);
      inflateReset(&stream_);
    }
    return std::nullopt;  // corrupt or cut data: gzread has said so already
  }

 private:
  // True at a member's end; false when the data stop or are corrupt before it.
  bool inflate_member() {
    for (;;) {
      if (!refill()) return false;
      stream_.next_out = out_.data();
      stream_.avail_out = static_cast<uInt>(out_.size());
      const uInt before = stream_.avail_in;
      const int code = inflate(&stream_, Z_NO_FLUSH);
      consumed_ += before - stream_.avail_in;
      if (code == Z_STREAM_END) return true;
      if (code != Z_OK) return false;
    }
  }
  bool refill() {
    if (stream_.avail_in > 0) return true;
    stream_.avail_in = static_cast<uInt>(std::fread(in_.data(), 1, in_.size(), file_));
    stream_.next_in = in_.data();
    return stream_.avail_in > 0;
  }
  // A member opens with the magic bytes 0x1f 0x8b; one byte left is already not a member.
  bool starts_member() {
    if (stream_.avail_in < 2) {
      std::memmove(in_.data(), stream_.next_in, stream_.avail_in);
      stream_.avail_in += static_cast<uInt>(
          std::fread(in_.data() + stream_.avail_in, 1, in_.size() - stream_.avail_in, file_));
      stream_.next_in = in_.data();
    }
    return stream_.avail_in >= 2 && stream_.next_in[0] == 0x1f && stream_.next_in[1] == 0x8b;
  }
  // Zero bytes padding the file to a block size (tapes, some archivers): gzip ignores them,
  // and they cannot hide text.
  bool only_zeros_follow() {
    do {
      for (uInt i = 0; i < stream_.avail_in; ++i) {
        if (stream_.next_in[i] != 0) return false;
      }
      stream_.avail_in = 0;
    } while (refill());
    return true;
  }

  std::FILE* file_;
  z_stream stream_{};
  bool ready_ = false;
  std::vector<unsigned char> in_ = std::vector<unsigned char>(1 << 16);
  std::vector<unsigned char> out_ = std::vector<unsigned char>(1 << 18);
  std::int64_t consumed_ = 0;  // bytes of the file given to inflate
};

}  // namespace

std::optional<std::int64_t> bytes_after_gzip(const std::string& path, std::int64_t text_bytes,
                                             std::uint32_t text_crc) {
  File f = open_again(path);
  if (last_member_holds(f.get(), text_bytes, text_crc)) return std::nullopt;
  return MemberWalk(f.get()).first_stray_byte();
}

}  // namespace granpipe::lammps_dump
