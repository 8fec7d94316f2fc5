#include "result_stream.hpp"

#include "granpipe/errors.hpp"
#include "h5_dataset.hpp"
#include "h5_file.hpp"
#include "h5_object.hpp"

namespace granpipe {

namespace {

struct Declared {
  std::string group, name;
  Table empty;
  std::vector<h5::Object> columns;  // one extendable dataset per column, once open
  std::vector<std::string> paths;   // of those datasets, for messages
};

constexpr hsize_t kChunkRows = 256;

}  // namespace

struct ResultStream::Impl {
  std::vector<Declared> tables;
  std::string name;
  h5::Object file;

  void create(const Provenance& provenance);
};

void ResultStream::Impl::create(const Provenance& provenance) {
  file = h5::create_swmr_file(name);
  write_provenance(file.id(), provenance);
  for (Declared& t : tables) {
    const std::string path = "/" + t.group + "/" + t.name;
    h5::Object g = h5::create_group(file.id(), path);
    h5::write_text_attribute(g.id(), "kind", "table");
    h5::write_attribute(g.id(), "columns", t.empty.columns);
    h5::write_attribute(g.id(), "units", t.empty.units);
    h5::write_text_attribute(g.id(), "doc", t.empty.doc);
    for (const std::string& c : t.empty.columns) {
      t.paths.push_back(path + "/" + c);
      t.columns.push_back(
          h5::create_series(file.id(), t.paths.back(), H5T_IEEE_F64LE, {}, kChunkRows));
    }
  }
  h5::check(H5Fstart_swmr_write(file.id()), "cannot start SWMR writing (is the disk full?)");
}

ResultStream::ResultStream() : impl_(std::make_unique<Impl>()) {}
ResultStream::~ResultStream() = default;

std::size_t ResultStream::declare(const std::string& group, const std::string& name,
                                  const Table& empty) {
  std::lock_guard lock(mutex_);
  if (impl_->file.valid())
    throw InternalError(name + ": streamed table declared after the run began");
  impl_->tables.push_back({group, name, empty, {}, {}});
  return impl_->tables.size() - 1;
}

void ResultStream::open(const std::filesystem::path& path, const Provenance& provenance) {
  std::lock_guard lock(mutex_);
  h5::silence_error_stack();
  impl_->name = path.string();
  h5::input_errors_of(impl_->name, [&] { impl_->create(provenance); });
}

void ResultStream::append(std::size_t id, const std::vector<double>& row) {
  std::lock_guard lock(mutex_);
  h5::silence_error_stack();  // rows come from the points' threads
  if (!impl_->file.valid() || !failure_.empty()) return;
  Declared& t = impl_->tables.at(id);
  if (row.size() != t.columns.size()) return;  // Table::add_row has refused it already
  try {
    h5::input_errors_of(impl_->name, [&] {
      for (std::size_t c = 0; c < row.size(); ++c) {
        h5::append_rows(t.columns[c].id(), t.paths[c], H5T_NATIVE_DOUBLE, &row[c], 1);
      }
    });
  } catch (const InputError& e) {
    // Reported by the runner (throw_if_failed), not as the error of the plugin adding the row.
    failure_ = e.what();
  }
  // A source adds rows between its frames (a tap's row, frames thousands of taps apart).
  if (std::chrono::steady_clock::now() - last_flush_ > std::chrono::seconds(1)) flush_locked();
}

void ResultStream::flush() {
  std::lock_guard lock(mutex_);
  h5::silence_error_stack();  // flushed from the points' threads
  flush_locked();
}

void ResultStream::flush_locked() {
  last_flush_ = std::chrono::steady_clock::now();
  if (!impl_->file.valid() || !failure_.empty()) return;
  try {
    h5::input_errors_of(impl_->name, [&] {
      h5::check(H5Fflush(impl_->file.id(), H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
    });
  } catch (const InputError& e) {
    failure_ = e.what();
  }
}

void ResultStream::throw_if_failed() const {
  std::lock_guard lock(mutex_);
  if (!failure_.empty()) throw InputError(failure_);
}

void ResultStream::close() {
  std::lock_guard lock(mutex_);
  for (Declared& t : impl_->tables) {
    t.columns.clear();
    t.paths.clear();
  }
  impl_->file = h5::Object();
}

}  // namespace granpipe
