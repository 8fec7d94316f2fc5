#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "granpipe/frame_store.hpp"

namespace granpipe::app {

namespace {

void list_columns(const char* what, const std::vector<Property>& columns) {
  if (columns.empty()) return;
  std::cout << what << ":\n";
  for (const Property& p : columns) {
    std::printf("  %-20s %-22s %-14s %s\n", p.name.c_str(), describe_type(p).c_str(),
                p.unit.empty() ? "-" : p.unit.c_str(), p.doc.c_str());
  }
}

// One value of a one-row observable, for the per-frame table.
std::string observable_text(const Frame& f, const Property& p) {
  const Column* c = f.observables.find(p.name);
  if (!c || p.components != 1) return "-";
  char buf[32];
  if (p.type == ValueType::Real) {
    std::snprintf(buf, sizeof buf, "%.6g", c->as<Eigen::ArrayXd>()[0]);
  } else if (p.type == ValueType::Integer) {
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(c->as<IndexArray>()[0]));
  } else {
    std::snprintf(buf, sizeof buf, "%d", c->as<IntArray>()[0]);
  }
  return buf;
}

// "run: pipeline tap3d_hysteresis, granpipe 0.1.0, commit 9bf6e14..., seed 3005" (and
// ", sweep point 2 (per_point seeds)" in a sweep): what a granpipe file says made it; ""
// for other files.
std::string run_line(const std::string& provenance) {
  if (provenance.empty()) return "";
  const auto p = nlohmann::json::parse(provenance, nullptr, false);
  if (!p.is_object()) return "run: (provenance unreadable)\n";
  std::ostringstream s;
  s << "run: pipeline " << p.value("/pipeline/name"_json_pointer, std::string("?")) << ", granpipe "
    << p.value("granpipe_version", std::string("?")) << ", commit "
    << p.value("git_commit", std::string("?")) << ", seed " << p.value("seed", nlohmann::json());
  if (!p.value("sweep_assignment", nlohmann::json()).empty()) {
    // Files written before the mode was recorded do not say it (shared seeds are older).
    const std::string seeds = p.contains("sweep_seeds")
                                  ? p["sweep_seeds"].get<std::string>() + " seeds"
                                  : "seed mode not recorded";
    s << ", sweep point " << p.value("sweep_point", nlohmann::json()) << " (" << seeds << ")";
  }
  s << "\n";
  return s.str();
}

}  // namespace

void inspect(const std::string& path, long max_rows) {
  FrameReader reader(path);
  const FrameFileInfo& info = reader.info();
  std::cout << info.path << ": " << info.frames << " frame(s), N = " << info.particles
            << ", dim = " << info.dim << ", particles group \"" << info.group << "\""
            << (info.complete ? "" : ", INCOMPLETE (the writer did not finish)") << "\n"
            << "written by: " << (info.creator.empty() ? "unknown" : info.creator)
            << (info.granpipe_file ? " (granpipe layout)" : " (plain H5MD)") << "\n"
            << run_line(info.provenance);
  std::vector<Property> particle{*find_standard("position", Scope::Particle)};
  particle.insert(particle.end(), info.columns.begin(), info.columns.end());
  list_columns("particle columns", particle);
  list_columns("contact columns", info.contact_columns);
  list_columns("observables", info.observables);

  std::printf("%5s %9s %13s", "frame", "step", "time");
  for (const Property& o : info.observables) std::printf(" %12s", o.name.c_str());
  std::printf(" %9s\n", "contacts");
  const long rows = std::min(info.frames, max_rows);
  for (long k = 0; k < rows; ++k) {
    const Frame f = reader.read(k);
    std::printf("%5ld %9lld %13.6g", k, static_cast<long long>(f.step), f.time);
    for (const Property& o : info.observables) std::printf(" %12s", observable_text(f, o).c_str());
    // A frame without a contact table has no count of contacts, which is not 0.
    if (f.contacts) {
      std::printf(" %9lld\n", static_cast<long long>(f.contacts->rows()));
    } else {
      std::printf(" %9s\n", "none");
    }
  }
  if (rows < info.frames)
    std::cout << "... (" << info.frames - rows << " more; --rows N shows more)\n";
}

}  // namespace granpipe::app
