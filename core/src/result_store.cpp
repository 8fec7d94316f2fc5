// results.h5 (one group per producer) and CSV copies of every table, histogram, fit and
// the scalars, each written to a temporary name and renamed when complete.
#include "granpipe/result_store.hpp"

#include <hdf5.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "granpipe/errors.hpp"
#include "output_directory.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

// Closes an HDF5 handle on scope exit.
class H5Handle {
 public:
  H5Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {
    if (id < 0) throw InternalError("HDF5 call failed while writing results");
  }
  ~H5Handle() { close_(id_); }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void attr_string(hid_t obj, const char* name, const std::string& value) {
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, std::max<std::size_t>(1, value.size()));
  H5Tset_cset(type, H5T_CSET_UTF8);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle attr(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  H5Awrite(attr, type, value.empty() ? "" : value.c_str());
}

void attr_double(hid_t obj, const char* name, double value) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle attr(H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
}

void attr_int(hid_t obj, const char* name, long long value) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle attr(H5Acreate2(obj, name, H5T_NATIVE_LLONG, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  H5Awrite(attr, H5T_NATIVE_LLONG, &value);
}

void attr_strings(hid_t obj, const char* name, const std::vector<std::string>& values) {
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  hsize_t n = values.size();
  H5Handle space(n ? H5Screate_simple(1, &n, nullptr) : H5Screate(H5S_NULL), H5Sclose);
  H5Handle attr(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (n) H5Awrite(attr, type, ptrs.data());
}

hid_t make_group(hid_t parent, const std::string& name) {
  H5Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl, 1);
  return H5Gcreate2(parent, name.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
}

void write_vector(hid_t parent, const std::string& name, const std::vector<double>& v) {
  hsize_t n = v.size();
  H5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  H5Handle ds(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT), H5Dclose);
  if (n) H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
}

void write_group(hid_t file, const std::string& group, const Results& r) {
  H5Handle g(make_group(file, group), H5Gclose);
  for (const auto& [name, s] : r.scalars()) {
    H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    H5Handle ds(H5Dcreate2(g, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                           H5P_DEFAULT), H5Dclose);
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &s.value);
    attr_string(ds, "kind", "scalar");
    attr_double(ds, "uncertainty", s.uncertainty);
    attr_string(ds, "unit", s.unit);
    attr_string(ds, "doc", s.doc);
  }
  for (const auto& [name, t] : r.tables()) {
    H5Handle tg(make_group(g, name), H5Gclose);
    attr_string(tg, "kind", "table");
    attr_strings(tg, "columns", t.columns);
    attr_strings(tg, "units", t.units);
    attr_string(tg, "doc", t.doc);
    for (std::size_t c = 0; c < t.columns.size(); ++c) write_vector(tg, t.columns[c], t.data[c]);
  }
  for (const auto& [name, h] : r.histograms()) {
    H5Handle hg(make_group(g, name), H5Gclose);
    attr_string(hg, "kind", "histogram");
    attr_int(hg, "density", h.density);
    attr_string(hg, "xlabel", h.xlabel);
    attr_string(hg, "doc", h.doc);
    write_vector(hg, "edges", h.edges);
    write_vector(hg, "values", h.values);
    if (!h.errors.empty()) write_vector(hg, "errors", h.errors);
  }
  for (const auto& [name, f] : r.fits()) {
    H5Handle fg(make_group(g, name), H5Gclose);
    attr_string(fg, "kind", "fit");
    attr_string(fg, "model", f.model);
    attr_strings(fg, "names", f.names);
    attr_double(fg, "chi2", f.chi2);
    attr_int(fg, "dof", f.dof);
    write_vector(fg, "values", f.values);
    write_vector(fg, "errors", f.errors);
    std::vector<double> cov(f.covariance.data(), f.covariance.data() + f.covariance.size());
    write_vector(fg, "covariance", cov);  // column-major, names x names
  }
  if (!r.plots().empty()) {
    H5Handle pg(make_group(g, "_plots"), H5Gclose);
    for (const auto& [name, pl] : r.plots()) {
      H5Handle one(make_group(pg, name), H5Gclose);
      attr_string(one, "table", pl.table);
      attr_string(one, "x", pl.x);
      attr_strings(one, "y", pl.y);
      attr_string(one, "xlabel", pl.xlabel);
      attr_string(one, "ylabel", pl.ylabel);
      attr_string(one, "title", pl.title);
      attr_int(one, "logx", pl.logx);
      attr_int(one, "logy", pl.logy);
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

std::string csv_header(const Provenance& p) {
  return "# granpipe " + p.version + " commit " + p.commit + " seed " + std::to_string(p.seed) + "\n";
}

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void write_csvs(const fs::path& dir, const std::string& group, const Results& r, const Provenance& p) {
  std::string base = group;
  for (char& c : base)
    if (c == '/') c = '.';
  if (!r.scalars().empty()) {
    std::string csv = csv_header(p) + "name,value,uncertainty,unit\n";
    for (const auto& [name, s] : r.scalars())
      csv += quoted(name) + "," + csv_number(s.value) + "," + csv_number(s.uncertainty) + "," +
             quoted(s.unit) + "\n";
    write_file_atomically(dir / (base + ".scalars.csv"), csv);
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
    write_file_atomically(dir / (base + "." + name + ".csv"), csv);
  }
  for (const auto& [name, h] : r.histograms()) {
    std::string csv = csv_header(p) + "lo,hi,value,error\n";
    for (std::size_t b = 0; b < h.values.size(); ++b)
      csv += csv_number(h.edges[b]) + "," + csv_number(h.edges[b + 1]) + "," + csv_number(h.values[b]) +
             "," + csv_number(h.errors.empty() ? std::nan("") : h.errors[b]) + "\n";
    write_file_atomically(dir / (base + "." + name + ".csv"), csv);
  }
  for (const auto& [name, f] : r.fits()) {
    std::string csv = csv_header(p) + "# model: " + f.model + "\nparameter,value,error\n";
    for (std::size_t k = 0; k < f.names.size(); ++k)
      csv += quoted(f.names[k]) + "," + csv_number(f.values[k]) + "," + csv_number(f.errors[k]) + "\n";
    write_file_atomically(dir / (base + "." + name + ".csv"), csv);
  }
}

}  // namespace

void write_results(const fs::path& dir, const ResultSet& results, const Provenance& provenance) {
  const fs::path final_path = dir / "results.h5", tmp = dir / "results.h5.tmp";
  {
    H5Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    attr_string(file, "granpipe_version", provenance.version);
    attr_string(file, "git_commit", provenance.commit);
    attr_int(file, "seed", static_cast<long long>(provenance.seed));
    attr_int(file, "threads", provenance.threads);
    attr_double(file, "wall_seconds", provenance.wall_seconds);
    attr_string(file, "started", provenance.started);
    attr_int(file, "complete", provenance.complete);
    attr_string(file, "pipeline", provenance.pipeline_json);
    for (const auto& [group, r] : results) write_group(file, group, r);
    H5Fflush(file, H5F_SCOPE_GLOBAL);
  }
  for (const auto& [group, r] : results) write_csvs(dir, group, r, provenance);
  fs::rename(tmp, final_path);
}

}  // namespace granpipe
