// results.h5 (one group per producer) and CSV copies of every table, histogram, fit and
// the scalars, each written to a temporary name and renamed when complete.
#include "granpipe/result_store.hpp"

#include <hdf5.h>

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "granpipe/atomic_file.hpp"
#include "granpipe/errors.hpp"
#include "h5_dataset.hpp"
#include "h5_file.hpp"
#include "h5_object.hpp"
#include "result_stream.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

using h5::Object;
using h5::owned;
using h5::write_attribute;
using h5::write_text_attribute;

void write_vector(hid_t parent, const std::string& name, const std::vector<double>& v) {
  hsize_t n = v.size();
  Object space = owned(H5Screate_simple(1, &n, nullptr), name + ": cannot make the dataspace");
  Object ds = owned(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT),
                    name + ": cannot make the dataset");
  if (n)
    h5::check(H5Dwrite(ds.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
              name + ": cannot write");
}

// A group for one result, tagged with what kind of result it holds.
Object result_group(hid_t parent, const std::string& name, const char* kind) {
  Object group = h5::create_group(parent, name);
  write_text_attribute(group.id(), "kind", kind);
  return group;
}

void write_group(hid_t file, const std::string& group, const Results& r) {
  const Object g = h5::create_group(file, group);
  for (const auto& [name, s] : r.scalars()) {
    Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
    Object ds = owned(H5Dcreate2(g.id(), name.c_str(), H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT),
                      name + ": cannot make the dataset");
    h5::check(H5Dwrite(ds.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &s.value),
              name + ": cannot write");
    write_text_attribute(ds.id(), "kind", "scalar");
    write_attribute(ds.id(), "uncertainty", s.uncertainty);
    write_text_attribute(ds.id(), "unit", s.unit);
    write_text_attribute(ds.id(), "doc", s.doc);
  }
  for (const auto& [name, t] : r.tables()) {
    const Object tg = result_group(g.id(), name, "table");
    write_attribute(tg.id(), "columns", t.columns);
    write_attribute(tg.id(), "units", t.units);
    write_text_attribute(tg.id(), "doc", t.doc);
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      write_vector(tg.id(), t.columns[c], t.data[c]);
  }
  for (const auto& [name, h] : r.histograms()) {
    const Object hg = result_group(g.id(), name, "histogram");
    write_attribute(hg.id(), "density", static_cast<int>(h.density));
    write_text_attribute(hg.id(), "xlabel", h.xlabel);
    write_text_attribute(hg.id(), "doc", h.doc);
    write_vector(hg.id(), "edges", h.edges);
    write_vector(hg.id(), "values", h.values);
    if (!h.errors.empty()) write_vector(hg.id(), "errors", h.errors);
  }
  for (const auto& [name, f] : r.fits()) {
    const Object fg = result_group(g.id(), name, "fit");
    write_text_attribute(fg.id(), "model", f.model);
    write_attribute(fg.id(), "names", f.names);
    write_attribute(fg.id(), "chi2", f.chi2);
    write_attribute(fg.id(), "dof", f.dof);
    write_vector(fg.id(), "values", f.values);
    write_vector(fg.id(), "errors", f.errors);
    const std::vector<double> cov(f.covariance.data(), f.covariance.data() + f.covariance.size());
    write_vector(fg.id(), "covariance", cov);  // column-major, names x names
  }
  if (!r.plots().empty()) {
    const Object plots = h5::create_group(g.id(), "_plots");
    for (const auto& [name, pl] : r.plots()) {
      const Object one = h5::create_group(plots.id(), name);
      write_text_attribute(one.id(), "table", pl.table);
      write_text_attribute(one.id(), "x", pl.x);
      write_attribute(one.id(), "y", pl.y);
      write_text_attribute(one.id(), "xlabel", pl.xlabel);
      write_text_attribute(one.id(), "ylabel", pl.ylabel);
      write_text_attribute(one.id(), "title", pl.title);
      write_attribute(one.id(), "logx", static_cast<int>(pl.logx));
      write_attribute(one.id(), "logy", static_cast<int>(pl.logy));
    }
  }
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "nan";
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

std::string csv_header(const Provenance& p) { return "# " + run_label(p) + "\n"; }

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

using TextFiles = std::vector<std::pair<fs::path, std::string>>;

void collect_csvs(const fs::path& dir, const std::string& group, const Results& r,
                  const Provenance& p, TextFiles& csvs) {
  std::string base = group;
  for (char& c : base)
    if (c == '/') c = '.';
  if (!r.scalars().empty()) {
    std::string csv = csv_header(p) + "name,value,uncertainty,unit\n";
    for (const auto& [name, s] : r.scalars())
      csv += quoted(name) + "," + csv_number(s.value) + "," + csv_number(s.uncertainty) + "," +
             quoted(s.unit) + "\n";
    csvs.emplace_back(dir / (base + ".scalars.csv"), csv);
  }
  for (const auto& [name, t] : r.tables()) {
    std::string csv = csv_header(p);
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      if (c) csv += ',';
      csv += quoted(t.columns[c]);
    }
    csv += "\n";
    for (std::size_t row = 0; row < t.rows(); ++row) {
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        if (c) csv += ',';
        csv += csv_number(t.data[c][row]);
      }
      csv += "\n";
    }
    csvs.emplace_back(dir / (base + "." + name + ".csv"), csv);
  }
  for (const auto& [name, h] : r.histograms()) {
    std::string csv = csv_header(p) + "lo,hi,value,error\n";
    for (std::size_t b = 0; b < h.values.size(); ++b)
      csv += csv_number(h.edges[b]) + "," + csv_number(h.edges[b + 1]) + "," +
             csv_number(h.values[b]) + "," +
             csv_number(h.errors.empty() ? std::nan("") : h.errors[b]) + "\n";
    csvs.emplace_back(dir / (base + "." + name + ".csv"), csv);
  }
  for (const auto& [name, f] : r.fits()) {
    std::string csv = csv_header(p) + "# model: " + f.model + "\nparameter,value,error\n";
    for (std::size_t k = 0; k < f.names.size(); ++k)
      csv +=
          quoted(f.names[k]) + "," + csv_number(f.values[k]) + "," + csv_number(f.errors[k]) + "\n";
    csvs.emplace_back(dir / (base + "." + name + ".csv"), csv);
  }
}

// Created exclusively, like write_new_file: what is at the temporary name already (a
// planted symlink) is refused, not followed, and left; what this made is removed on failure.
void write_h5(const fs::path& tmp, const fs::path& final_path, const ResultSet& results,
              const Provenance& provenance) {
  h5::silence_error_stack();
  h5::input_errors_of(final_path.string(), [&] {
    std::error_code ec;
    if (fs::symlink_status(tmp, ec).type() != fs::file_type::not_found) {
      throw InputError(tmp.string() +
                       ": expected no file at this temporary name, got one (not granpipe's "
                       "now: left as it is)");
    }
    Object file_object = h5::create_file(tmp.string(), H5F_ACC_EXCL, H5P_DEFAULT);
    try {
      const hid_t file = file_object.id();
      write_provenance(file, provenance);
      for (const auto& [group, r] : results) write_group(file, group, r);
      h5::check(H5Fflush(file, H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
      h5::check(H5Fclose(file_object.release()), "cannot close (is the disk full?)");
    } catch (...) {
      file_object.reset();
      fs::remove(tmp, ec);
      throw;
    }
  });
}

fs::path temporary(const fs::path& path) { return path.string() + ".tmp"; }

void rename_into_place(const fs::path& path) { move_into_place(temporary(path), path); }

}  // namespace

void write_provenance(hid_t file, const Provenance& provenance) {
  write_text_attribute(file, "granpipe_version", provenance.version);
  write_text_attribute(file, "git_commit", provenance.commit);
  write_attribute(file, "seed", provenance.seed);
  write_attribute(file, "threads", provenance.threads);
  write_attribute(file, "wall_seconds", provenance.wall_seconds);
  write_text_attribute(file, "started", provenance.started);
  write_attribute(file, "complete", static_cast<int>(provenance.complete));
  write_text_attribute(file, "pipeline", provenance.pipeline_json);
  write_text_attribute(file, "pipeline_name", provenance.pipeline_name);
  if (!provenance.stage_names.empty()) {
    write_attribute(file, "stage_names", provenance.stage_names);
    write_attribute(file, "stage_seconds", provenance.stage_seconds);
  }
}

// Every file is written under a temporary name and renamed only once all are written,
// so a run that fails here (a full disk) leaves no results file under its final name. Each
// name is recorded once the file is made under it, never before (a user's file found at
// that name is not the run's, and --overwrite must not remove it): what a failure leaves (a
// temporary, or CSVs renamed before it) is the run's too.
void write_results(const fs::path& dir, const ResultSet& results, const Provenance& provenance,
                   FileRecord& record) {
  const fs::path final_path = dir / "results.h5";
  TextFiles csvs;
  for (const auto& [group, r] : results) collect_csvs(dir, group, r, provenance, csvs);
  std::vector<fs::path> written;
  const auto made = [&](const fs::path& file) {
    record.add(temporary(file));
    written.push_back(temporary(file));
  };
  try {
    write_h5(temporary(final_path), final_path, results, provenance);
    made(final_path);
    for (const auto& [path, text] : csvs) {
      write_new_file(temporary(path), text);
      made(path);
    }
  } catch (...) {
    std::error_code ignored;
    for (const fs::path& f : written) fs::remove(f, ignored);
    throw;
  }
  const auto moved = [&](const fs::path& file) {
    rename_into_place(file);
    record.add(file);
  };
  for (const auto& csv : csvs) moved(csv.first);
  moved(final_path);
}

std::string run_label(const Provenance& p) {
  return "granpipe " + p.version + " commit " + p.commit + " pipeline " + p.pipeline_name +
         " seed " + std::to_string(p.seed);
}

}  // namespace granpipe
