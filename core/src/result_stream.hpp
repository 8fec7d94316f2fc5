#pragma once
// results.partial.h5 while a run goes. Streamed tables are declared while the plugins are
// made; open() creates the file with every one of them (as extendable datasets, in the
// layout of the final results.h5) and starts HDF5's SWMR mode, in which the file is
// consistent on disk after every flush; append() adds one row, and flush() (after each
// frame) writes the rows out. The file is
// marked incomplete; a run that finishes writes results.h5 whole and removes it.
#include <hdf5.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "granpipe/result_store.hpp"
#include "granpipe/results.hpp"

namespace granpipe {

// The provenance attributes of results.h5 (result_store.cpp), shared by the streamed and
// the final file.
void write_provenance(hid_t file, const Provenance& provenance);

class ResultStream : public ResultStreams {
 public:
  ResultStream();
  ~ResultStream() override;
  std::size_t declare(const std::string& group, const std::string& name,
                      const Table& empty) override;
  // Safe from several threads (sweep points run in parallel); rows are dropped until
  // open(), as when a pipeline is only checked.
  void append(std::size_t id, const std::vector<double>& row) override;
  // Creates `path` (results.h5 of the output directory) with every declared table;
  // `provenance.complete` should be false.
  void open(const std::filesystem::path& path, const Provenance& provenance);
  // Puts the rows appended so far on disk, for readers and for a run killed after it.
  // Once a frame (and, between frames far apart, once a second), not once a row: a flush
  // goes through every open table, so a frame of 1e6 histogram rows took 226 s.
  void flush();
  // Closes the file, which stays marked incomplete.
  void close();
  // A write that failed (a full disk) stops the streaming; this throws its InputError.
  void throw_if_failed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  mutable std::mutex mutex_;
  std::string failure_;
  std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
  void flush_locked();
};

}  // namespace granpipe
