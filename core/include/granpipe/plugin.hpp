#pragma once
// The plugin contract: what a source and an analyzer are, and how a plugin library
// registers them. Include this (and nothing outside granpipe/) to write a plugin.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/frame_cache.hpp"
#include "granpipe/log.hpp"
#include "granpipe/output_files.hpp"
#include "granpipe/params.hpp"
#include "granpipe/progress.hpp"
#include "granpipe/random.hpp"
#include "granpipe/results.hpp"
#include "granpipe/version.hpp"

namespace granpipe {

// What a source's frames carry beyond the required columns (position, radius, id,
// species), or what an analyzer needs of them. dim 0 means "either". `columns` lists
// particle, contact and per-frame (observable) properties; a contact column implies
// contacts.
struct FrameContent {
  int dim = 0;
  bool contacts = false;
  std::vector<Property> columns{};
};

// Everything a plugin instance gets when it is made: its validated parameters, its own
// seeds, the thread budget, the log, progress, and the run's output directory.
struct PluginContext {
  const Params& params;
  Seeds seeds;
  int threads = 1;
  Log& log;
  Progress& progress;
  std::filesystem::path output_dir;  // empty when the run writes nothing
  // The instance's name in the pipeline ("source", or the analyzer's name): files a
  // plugin writes into output_dir start with it, so two instances never collide.
  std::string name;
  // Where the parameters sit in the pipeline, e.g. "source.params" or "analyzers[1].params".
  std::string params_path;
  // "granpipe 0.1.0 commit 3f2a... pipeline tap2d seed 7" (and the sweep point): what a
  // file a plugin writes says of where it came from, as every result file does.
  std::string provenance{};

  // Where the names of the files the run writes are recorded (output_files()).
  FileRecord* file_record = nullptr;

  // Where streamed tables go, and the results group they belong to ("arches",
  // "point_002/arches"); no streams when a pipeline is only checked.
  ResultStreams* streams = nullptr;
  std::string results_group{};

  // A table whose rows reach results.h5 as they are added: for per-frame series, so that
  // a run killed after hours keeps them. Report it in finish() with table() as usual.
  StreamedTable stream_table(const std::string& table, Table empty) const {
    const std::size_t id = streams ? streams->declare(results_group, table, empty) : 0;
    return {std::move(empty), streams, id};
  }

  // Names the files this instance writes into output_dir (<name><suffix>) and records
  // them as the run's: a later --overwrite removes those and leaves any other file there
  // as the user's. Keep it as a member; write no file into output_dir by another name.
  OutputFiles output_files() const { return {file_record, output_dir, name}; }

  // "source.params.cells": the start of a message about one parameter, so that a plugin's
  // own checks read like the core's ("<file>: source.params.cells: expected ..., got ...").
  std::string param(const std::string& name) const {
    return params_path.empty() ? name : params_path + "." + name;
  }
};

// Produces frames until done. Long sources advance ctx.progress by the units they
// declared in work(); otherwise the runner advances it by one per frame.
class Source {
 public:
  virtual ~Source() = default;
  virtual FrameContent content() const = 0;
  // Fills `frame` with the next configuration; false when there are no more.
  virtual bool next(Frame& frame) = 0;
  // Total work for the progress bar, in units the source advances itself, or nothing
  // when it yields one frame per unit of work.
  struct Work {
    double total = 0;
    std::string unit = "frames";
    bool reported_by_source = false;
  };
  virtual Work work() const { return {}; }
  // Source-level results (e.g. run statistics); called once after the last frame.
  virtual void finish(Results&) {}
};

// Measures frames. Reads each frame (never edits it) and reports in finish().
// Must not keep every frame it sees unless it has to.
class Analyzer {
 public:
  virtual ~Analyzer() = default;
  // What a frame must carry for this analyzer (dim 0: either).
  virtual FrameContent needs() const { return {}; }
  virtual void consume(const Frame& frame, FrameCache& cache) = 0;
  virtual void finish(Results& results) = 0;

  // Particle or contact columns this analyzer adds to each frame (arch membership, a local
  // packing fraction, the pass that selected a contact): analyzers after it in the
  // pipeline, and the writers, see them. A frame (observable) column is refused before
  // the run: per-frame values go to the analyzer's results.
  virtual std::vector<Property> publishes() const { return {}; }
  // Called right after consume(), once per scope that publishes() declares columns of:
  // fill `columns` (a table of the frame's particles, or of its contacts, as
  // columns.scope() says, holding exactly the declared columns of that scope, zero-filled).
  // Contact columns are asked for only when the frame has a contact table.
  virtual void publish(PropertyTable& /*columns*/) {}
};

// Saves frames: the H5MD frame store (frames.h5) is one; VTK or extended XYZ others.
// Sees every frame (every output.frame_stride-th and the last) after the analyzers, with the
// columns they published. It names the files it writes with ctx.output_files(); it creates them at
// the first write (plugins are also made to check a pipeline, which writes nothing).
class Writer {
 public:
  virtual ~Writer() = default;
  virtual void write(const Frame& frame) = 0;
  // The run finished: complete the files. A writer that is never closed (a run killed or
  // failed) must leave them marked or named as incomplete.
  virtual void close() = 0;
};

enum class PluginKind : std::uint8_t { Source, Analyzer, Writer };
const char* to_string(PluginKind k);

struct PluginInfo {
  std::string name;
  PluginKind kind = PluginKind::Analyzer;
  std::string summary;
  Schema schema;
  std::function<std::unique_ptr<Source>(const PluginContext&)> make_source{};
  std::function<std::unique_ptr<Analyzer>(const PluginContext&)> make_analyzer{};
  std::function<std::unique_ptr<Writer>(const PluginContext&)> make_writer{};
  std::string library{};  // file it was loaded from; set by the loader
};

// Holds every known plugin. Built-in and external plugins register the same way.
class Registry {
 public:
  template <class S>
  void add_source(std::string name, std::string summary, Schema schema) {
    PluginInfo info{std::move(name), PluginKind::Source, std::move(summary), std::move(schema)};
    info.make_source = [](const PluginContext& c) -> std::unique_ptr<Source> {
      return std::make_unique<S>(c);
    };
    add(std::move(info));
  }
  template <class A>
  void add_analyzer(std::string name, std::string summary, Schema schema) {
    PluginInfo info{std::move(name), PluginKind::Analyzer, std::move(summary), std::move(schema)};
    info.make_analyzer = [](const PluginContext& c) -> std::unique_ptr<Analyzer> {
      return std::make_unique<A>(c);
    };
    add(std::move(info));
  }
  template <class W>
  void add_writer(std::string name, std::string summary, Schema schema) {
    PluginInfo info{std::move(name), PluginKind::Writer, std::move(summary), std::move(schema)};
    info.make_writer = [](const PluginContext& c) -> std::unique_ptr<Writer> {
      return std::make_unique<W>(c);
    };
    add(std::move(info));
  }
  // Registers a plugin; a second plugin of one name is an InternalError.
  void add(PluginInfo info);

  const PluginInfo* find(const std::string& name) const;
  const std::vector<PluginInfo>& plugins() const { return plugins_; }

 private:
  // What the loader saw (plugin_loader.hpp); only the loader writes it.
  friend void load_plugins(Registry&, const std::vector<std::filesystem::path>&);
  friend const struct LoadReport& load_report(const Registry&);
  std::vector<PluginInfo> plugins_;
  std::shared_ptr<struct LoadReport> report_;
};

}  // namespace granpipe

#include "granpipe/abi_fingerprint.hpp"  // of every type above

// The one exported symbol of a plugin library: a plain descriptor the loader reads
// (ABI version first, then the layout of the public types) before it calls anything in
// the library. Every field is 8 bytes, so that the loader reads it right whatever packing
// the plugin was compiled with; from ABI 2 on the first three fields never change.
extern "C" struct granpipe_plugin_entry {
  std::uint64_t abi_version;
  std::uint64_t layout_fingerprint;  // granpipe::kLayoutFingerprint as the plugin saw it
  const char* core_version;
  void (*register_plugins)(granpipe::Registry&);
};

// Use once per plugin library:
//   GRANPIPE_PLUGIN(registry) { registry.add_analyzer<MyAnalyzer>("my", "...", schema()); }
#define GRANPIPE_PLUGIN(registry)                                                                \
  static void granpipe_register_plugins(granpipe::Registry& registry);                           \
  extern "C" __attribute__((visibility("default")))                                              \
  const granpipe_plugin_entry granpipe_plugin = {GRANPIPE_ABI_VERSION,                           \
                                                 granpipe::kLayoutFingerprint, GRANPIPE_VERSION, \
                                                 &granpipe_register_plugins};                    \
  static void granpipe_register_plugins(granpipe::Registry& registry)
