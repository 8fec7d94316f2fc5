#pragma once
// A text file's lines, numbered from 1 as an editor shows them, read through zlib so that
// a gzip-compressed file (a dump written as x.dump.gz) reads as its plain text and a
// plain file as itself.
#include <zlib.h>

#include <cstdint>
#include <string>

namespace granpipe::lammps_dump {

class TextLines {
 public:
  // InputError naming `path` when it cannot be opened.
  explicit TextLines(std::string path);
  ~TextLines();
  TextLines(const TextLines&) = delete;
  TextLines& operator=(const TextLines&) = delete;

  // The next line without its end of line ("\n" or "\r\n"); false at the end of the data.
  // InputError naming the file and line when it cannot be read or decompressed.
  bool next(std::string& line);
  long number() const { return number_; }  // of the line last read
  // The last line read had no end of line: the file ends inside it (a write cut short).
  bool cut() const { return cut_; }
  // The compressed data stop before the gzip stream's end: the file was cut.
  bool ended_early() const { return ended_early_; }
  // After the last line of a first reading from the start, without seek(): InputError
  // when bytes follow the gzip data that zlib passed over (text appended to a compressed
  // dump).
  void check_nothing_follows();

  // Where the next line starts, in bytes of the (decompressed) text, to come back to with
  // seek(offset, number of the line before it).
  std::int64_t offset() const;
  void seek(std::int64_t offset, long line_before);
  const std::string& path() const { return path_; }

 private:
  void check_read_error();
  std::string path_;
  gzFile file_;
  long number_ = 0;
  bool cut_ = false, ended_early_ = false;
  std::uint32_t crc_ = 0;  // CRC-32 of the text read so far, for check_nothing_follows
};

}  // namespace granpipe::lammps_dump
