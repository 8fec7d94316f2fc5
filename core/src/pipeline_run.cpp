// Running a validated pipeline: output directory, plugins per sweep point, frames to
// frames.h5, results to results.h5, points in parallel.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <ctime>
#include <exception>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "frames_file_writer.hpp"
#include "granpipe/atomic_file.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/result_store.hpp"
#include "interruption_record.hpp"
#include "output_directory.hpp"
#include "pipeline_impl.hpp"
#include "published_columns.hpp"
#include "result_stream.hpp"
#include "stage_clock.hpp"
#include "thread_probe.hpp"

namespace granpipe {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct PointPlugins {
  // First, so that it outlives the plugins that hold it.
  std::unique_ptr<Log> log;  // a sweep point's, naming it in each line; else none
  std::unique_ptr<Source> source;
  std::vector<std::unique_ptr<Analyzer>> analyzers;
  std::vector<std::unique_ptr<Writer>> writers;  // the pipeline's
  std::vector<std::string> warnings;             // for the run's log
  FileRecord* files = nullptr;                   // what the run writes, as it writes it
};

// "analyzer \"packing\"", or "analyzer \"top\" (packing)" when named otherwise.
std::string analyzer_title(const PluginSpec& spec) {
  const std::string title = "analyzer \"" + spec.name + "\"";
  return spec.name == spec.info->name ? title : title + " (" + spec.info->name + ")";
}

// Analyzer `a` publishes `c`; an analyzer before it that reads `c` as the source saved it
// would measure the old values while the frames written carry the new ones.
void refuse_stale_reader(const Pipeline::Impl& p,
                         const std::vector<std::pair<std::size_t, Property>>& read_as_saved,
                         std::size_t a, const Property& c) {
  for (const auto& [reader, column] : read_as_saved) {
    if (reader == a || column.name != c.name || column.scope != c.scope) continue;
    const PluginSpec &spec = p.analyzers[a], &earlier = p.analyzers[reader];
    throw InputError(
        spec.where + ": analyzer \"" + spec.info->name + "\" recomputes the " + to_string(c.scope) +
        " column \"" + c.name + "\", which analyzers[" + std::to_string(reader) + "] (\"" +
        earlier.info->name + "\") before it reads as the source saved it: put \"" +
        spec.info->name +
        "\" first to use the recomputed values, or leave it out to use the saved ones");
  }
}

// The directory a point's plugins write into: the output directory, or a folder per
// point in a sweep so that points never write the same file.
fs::path point_directory(const Pipeline::Impl& p, std::size_t k, const fs::path& out) {
  if (out.empty() || p.points.size() == 1) return out;
  char buf[32];
  std::snprintf(buf, sizeof buf, "point_%03zu", k);
  return out / buf;
}

std::string point_prefix(const Pipeline::Impl& p, std::size_t k) {
  if (p.points.size() == 1) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "point_%03zu/", k);
  return buf;
}

// The run as the files its plugins write name it, with the sweep point.
std::string point_label(const Pipeline::Impl& p, std::size_t k) {
  Provenance run;
  run.pipeline_name = p.name;
  run.version = version();
  run.commit = git_commit();
  run.seed = p.seed;
  return run_label(run) + (p.points.size() > 1 ? " sweep point " + std::to_string(k) : "");
}

PointPlugins make_plugins(const Pipeline::Impl& p, std::size_t k, int threads, Log& log,
                          Progress& progress, const fs::path& out, ResultStreams* streams,
                          FileRecord* files) {
  const fs::path dir = point_directory(p, k, out);
  const PointSpec& point = p.points[k];
  const Seeds seeds = Seeds(p.seed).derive("point", p.shared_seeds ? 0 : k);
  PointPlugins made;
  made.files = files;
  if (p.points.size() > 1) {
    made.log = std::make_unique<Log>(log, "point " + std::to_string(k) + ": ");
    if (files) files->add(dir);  // the run's, not any point_NNN found in the folder
  }
  Log& point_log = made.log ? *made.log : log;
  const std::string provenance = point_label(p, k);
  // Plugins check what the schema cannot (one parameter against another, a file's
  // content); their messages name the parameter (ctx.param) and get the file in front.
  auto context = [&](const Params& params, Seeds s, const std::string& name,
                     const std::string& params_path) {
    PluginContext c{params, s, threads, point_log, progress, dir, name, params_path};
    c.provenance = provenance;
    c.streams = streams;
    c.file_record = files;
    c.results_group = point_prefix(p, k) + name;
    return c;
  };
  try {
    made.source = p.source->make_source(context(
        point.source_params, seeds.derive("source:" + p.source->name), "source", "source.params"));
  } catch (const InputError& e) {
    throw InputError(located_message(p.top(), e.what()) + sweep_point_note(point, k));
  }
  FrameColumns frames(made.source->content(), p.source->name);
  // Columns an analyzer reads as the source saved them, by analyzer index, and the columns
  // analyzers publish: a later analyzer that recomputes a column read as saved would leave
  // the earlier reader on stale values.
  std::vector<std::pair<std::size_t, Property>> read_as_saved;
  std::vector<Property> published;
  for (std::size_t a = 0; a < p.analyzers.size(); ++a) {
    const PluginSpec& spec = p.analyzers[a];
    const std::string at = "analyzers[" + std::to_string(a) + "]";
    try {
      made.analyzers.push_back(spec.info->make_analyzer(
          context(point.analyzer_params[a], seeds.derive("analyzer:" + spec.name), spec.name,
                  at + ".params")));
    } catch (const InputError& e) {
      throw InputError(located_message(p.top(), e.what()) + sweep_point_note(point, k));
    }
    const std::string missing = frames.lacks(made.analyzers.back()->needs());
    if (!missing.empty())
      throw InputError(spec.where + ": " + analyzer_title(spec) + " needs " + missing +
                       sweep_point_note(point, k));
    for (const Property& c : made.analyzers.back()->needs().columns) {
      const bool by_analyzer =
          std::any_of(published.begin(), published.end(),
                      [&](const Property& q) { return q.name == c.name && q.scope == c.scope; });
      if (!is_required(c) && !by_analyzer) read_as_saved.emplace_back(a, c);
    }
    if (!spec.publish) continue;
    for (const Property& c : made.analyzers.back()->publishes()) {
      refuse_stale_reader(p, read_as_saved, a, c);
      published.push_back(c);
    }
    try {
      for (const std::string& w :
           frames.publish(made.analyzers.back()->publishes(), at, analyzer_title(spec))) {
        made.warnings.push_back(p.origin + ": " + w);
      }
    } catch (const InputError& e) {
      throw InputError(p.origin + ": " + e.what() + sweep_point_note(point, k));
    }
  }
  for (std::size_t w = 0; w < p.writers.size(); ++w) {
    const PluginSpec& spec = p.writers[w];
    try {
      made.writers.push_back(spec.info->make_writer(
          context(point.writer_params[w], seeds.derive("writer:" + spec.name), spec.name,
                  "writers[" + std::to_string(w) + "].params")));
    } catch (const InputError& e) {
      throw InputError(located_message(p.top(), e.what()) + sweep_point_note(point, k));
    }
  }
  return made;
}

// frames.h5 of a point, when the pipeline saves frames.
std::unique_ptr<Writer> frames_file(const Pipeline::Impl& p, std::size_t k, const fs::path& out,
                                    FileRecord* files) {
  if (!p.save_frames) return nullptr;
  json provenance = {{"pipeline", p.points[k].resolved},
                     {"granpipe_version", version()},
                     {"git_commit", git_commit()},
                     {"seed", p.seed},
                     {"sweep_point", k},
                     {"sweep_assignment", p.points[k].assignment},
                     // The point's pipeline has no sweep: its seeds (point k's, or point 0's
                     // when shared) are told by these two.
                     {"sweep_seeds", p.shared_seeds ? "shared" : "per_point"}};
  return std::make_unique<FramesFileWriter>(point_directory(p, k, out) / "frames.h5",
                                            provenance.dump(), files);
}

struct PointOutcome {
  ResultSet results;
  long frames = 0;
  std::vector<double> stage_seconds;  // in the order of stage_names()
};

// The stages a point's time is measured in: the source, the analyzers, the writers, and
// the frames file when the run saves frames.
std::vector<std::string> stage_names(const Pipeline::Impl& p) {
  std::vector<std::string> names{"source " + p.source->name};
  for (const PluginSpec& a : p.analyzers) names.push_back("analyzer " + a.name);
  for (const PluginSpec& w : p.writers) names.push_back("writer " + w.name);
  if (p.save_frames) names.push_back("frames file");
  return names;
}

PointOutcome run_point(const Pipeline::Impl& p, std::size_t k, PointPlugins plugins,
                       ResultStream& stream, Progress& progress, const fs::path& out) {
  const bool source_reports = plugins.source->work().reported_by_source;
  const auto frames_h5 = frames_file(p, k, out, plugins.files);  // none when not saved

  PointOutcome outcome;
  Frame frame;
  FrameCache cache;
  const std::string where = p.origin + ": source \"" + p.source->name + "\"";
  // A plugin's complaint about the data names the pipeline part it came from, once: a
  // message that starts with the part's own path (ctx.param("x")) gets only the file.
  auto located = [&](const std::string& part, auto&& step) {
    try {
      return step();
    } catch (const InputError& e) {
      const std::string m = e.what();
      const bool names_part = m.rfind(part + ".", 0) == 0 || m.rfind(part + ":", 0) == 0;
      throw InputError(p.origin + ": " + (names_part ? m : part + ": " + m) +
                       sweep_point_note(p.points[k], k));
    } catch (const InternalError& e) {  // a plugin's bug: still say whose
      throw InternalError(p.origin + ": " + part + ": " + e.what());
    }
  };
  // What each analyzer publishes, asked once rather than every frame.
  std::vector<std::vector<Property>> published;
  for (std::size_t a = 0; a < plugins.analyzers.size(); ++a) {
    published.push_back(p.analyzers[a].publish ? plugins.analyzers[a]->publishes()
                                               : std::vector<Property>{});
  }
  const std::size_t n_analyzers = plugins.analyzers.size(), n_writers = plugins.writers.size();
  const std::size_t first_writer = 1 + n_analyzers, frames_stage = first_writer + n_writers;
  StageClock clock(frames_stage + (frames_h5 ? 1 : 0));  // as many as stage_names(p)
  const auto fetch = [&](Frame& into) {
    throw_if_stop_requested();  // a SIGINT or SIGTERM: stop between frames, files whole
    // The frame before goes first: a source that computes between frames (a DEM run) then
    // holds one frame beside its own state, not two.
    into = Frame();
    return clock.time(
        0, [&] { return located("source", [&] { return plugins.source->next(into); }); });
  };
  // With a stride, a frame between the saved ones is saved when it is the last: the next one
  // is fetched before deciding (a run of 375 frames at stride 10 left out its final state).
  Frame ahead;
  for (bool more = fetch(frame); more;) {
    frame.check(where + " frame " + std::to_string(outcome.frames));
    cache.clear();
    for (std::size_t a = 0; a < n_analyzers; ++a) {
      clock.time(1 + a, [&] {
        located("analyzers[" + std::to_string(a) + "]", [&] {
          plugins.analyzers[a]->consume(frame, cache);
          publish_columns(*plugins.analyzers[a], published[a], analyzer_title(p.analyzers[a]),
                          frame);
        });
      });
    }
    const bool looked_ahead = outcome.frames % p.frame_stride != 0;
    if (looked_ahead) more = fetch(ahead);
    if (!looked_ahead || !more) {
      for (std::size_t w = 0; w < n_writers; ++w) {
        clock.time(first_writer + w, [&] {
          located("writers[" + std::to_string(w) + "]", [&] { plugins.writers[w]->write(frame); });
        });
      }
      // The frames file names itself in its messages.
      if (frames_h5) clock.time(frames_stage, [&] { frames_h5->write(frame); });
    }
    for (const auto& columns : published) remove_published(columns, frame);
    stream.flush();
    stream.throw_if_failed();  // a full disk is the output's fault, not an analyzer's
    ++outcome.frames;
    if (!source_reports) progress.advance(1);
    if (looked_ahead) {
      std::swap(frame, ahead);
    } else {
      more = fetch(frame);
    }
  }

  const std::string prefix = point_prefix(p, k);
  Results source_results;
  clock.time(0, [&] { located("source", [&] { plugins.source->finish(source_results); }); });
  if (!source_results.empty()) outcome.results[prefix + "source"] = std::move(source_results);
  for (std::size_t a = 0; a < n_analyzers; ++a) {
    Results r;
    clock.time(1 + a, [&] {
      located("analyzers[" + std::to_string(a) + "]", [&] { plugins.analyzers[a]->finish(r); });
    });
    outcome.results[prefix + p.analyzers[a].name] = std::move(r);
  }
  for (std::size_t w = 0; w < n_writers; ++w)
    clock.time(first_writer + w, [&] { plugins.writers[w]->close(); });
  if (frames_h5) clock.time(frames_stage, [&] { frames_h5->close(); });
  outcome.stage_seconds = clock.seconds();
  return outcome;
}

// One row per sweep point: the swept values, then every scalar of every producer.
Results sweep_summary(const Pipeline::Impl& p, const ResultSet& all) {
  std::vector<std::string> cols{"point"};
  std::vector<std::string> swept;
  for (const auto& path : p.sweep_paths) {
    cols.push_back(path);
    swept.push_back(path);
  }
  // Every scalar some point gave: a point may give one the others do not (a parameter
  // swept from 0 turns a measurement on), and the column must still be there.
  std::vector<std::pair<std::string, std::string>> scalars;  // producer, scalar
  std::set<std::pair<std::string, std::string>> seen;
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    const std::string prefix = point_prefix(p, k);
    for (auto it = all.lower_bound(prefix); it != all.end() && it->first.rfind(prefix, 0) == 0;
         ++it) {
      const std::string producer = it->first.substr(prefix.size());
      for (const auto& [name, s] : it->second.scalars()) {
        if (!seen.emplace(producer, name).second) continue;
        scalars.emplace_back(producer, name);
        cols.push_back(producer + "." + name);
        cols.push_back(producer + "." + name + "_err");
      }
    }
  }
  Table table(cols,
              "one row per sweep point; true/false parameters as 1/0, other values that are "
              "not numbers as the index in their list; NaN where a point gave no such result");
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    std::vector<double> row{static_cast<double>(k)};
    for (const auto& path : swept) {
      const json& v = p.points[k].assignment[path];
      if (v.is_number()) {
        row.push_back(v.get<double>());
      } else if (v.is_boolean()) {
        row.push_back(v.get<bool>() ? 1.0 : 0.0);
      } else {
        const json& list = p.resolved["sweep"]["parameters"][path];
        row.push_back(static_cast<double>(std::find(list.begin(), list.end(), v) - list.begin()));
      }
    }
    for (const auto& [producer, name] : scalars) {
      auto it = all.find(point_prefix(p, k) + producer);
      const bool has = it != all.end() && it->second.scalars().count(name);
      row.push_back(has ? it->second.scalar(name).value : std::nan(""));
      row.push_back(has ? it->second.scalar(name).uncertainty : std::nan(""));
    }
    table.add_row(row);
  }
  Results r;
  r.add_table("points", std::move(table));
  return r;
}

// Every file the run reads: the pipeline file and each parameter of type path.
std::vector<InputFile> input_files(const Pipeline::Impl& p) {
  std::vector<InputFile> files;
  if (!p.file.empty()) files.push_back({p.origin, p.file});
  auto add = [&](const Schema& schema, const Params& params, const std::string& at) {
    for (const ParamSpec& s : schema.specs()) {
      if (!params.has(s.name)) continue;
      // A --set of the path is named, not the file that no longer says it.
      const auto where = [&](const std::string& path) {
        return JsonLocation{p.origin, path, &p.overrides}.str();
      };
      const std::string path = at + "." + s.name;
      if (s.type == ParamType::Path) files.push_back({where(path), params.string(s.name)});
      if (s.type != ParamType::PathList) continue;
      const std::vector<std::string>& list = params.paths(s.name);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string entry = path + "[" + std::to_string(k) + "]";
        files.push_back({where(entry), list[k]});
      }
    }
  };
  for (const PointSpec& point : p.points) {
    add(p.source->schema, point.source_params, "source.params");
    for (std::size_t a = 0; a < p.analyzers.size(); ++a) {
      const std::string at = "analyzers[" + std::to_string(a) + "].params";
      add(p.analyzers[a].info->schema, point.analyzer_params[a], at);
    }
  }
  return files;
}

void create_point_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the directory: " + ec.message());
}

// A point's warnings not given yet by another point (`warned`).
void warn_once(const PointPlugins& point, std::set<std::string>& warned, Log& log) {
  for (const std::string& w : point.warnings) {
    if (warned.insert(w).second) log.warn(w);
  }
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

// Closes the run's log when the run ends, whichever way.
struct ClosesLog {
  Log& log;
  ~ClosesLog() { log.close_file(); }
};

}  // namespace

void Pipeline::check(Log& log) const {
  Progress quiet;
  quiet.set_enabled(false);
  std::set<std::string> warned;
  for (std::size_t k = 0; k < impl_->points.size(); ++k) {
    warn_once(make_plugins(*impl_, k, 1, log, quiet, {}, nullptr, nullptr), warned, log);
  }
}

namespace {

// "time per stage: source spheres3d_tap 81.2 s, analyzer stereology 3.07 s, ...".
std::string stage_times_line(const Provenance& p, std::size_t points) {
  std::string line = points > 1 ? "time per stage, summed over the points:" : "time per stage:";
  for (std::size_t s = 0; s < p.stage_names.size(); ++s)
    line += (s ? ", " : " ") + p.stage_names[s] + " " + format_number(p.stage_seconds[s], 3) + " s";
  return line;
}

RunSummary run_in_directory(const Pipeline::Impl& p, const RunOptions& options, Log& log) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  RunSummary summary;
  OutputDirectory out(p.output_dir, options.overwrite, input_files(p));
  summary.output_dir = out.final_path();
  const fs::path dir = out.work_path();  // beside output_dir while replacing an earlier run

  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int asked = options.threads > 0 ? options.threads : hw;
  const int startable = startable_threads(asked);
  // Short of the threads asked, the stacks filled what the limit left, and the run's own
  // memory came after them (175 started under prlimit --as 1.5 GB; OpenMP's team then
  // failed): half of them leaves the other half's room to the run.
  const int threads = startable < asked ? std::max(1, startable / 2) : asked;
  if (threads < asked) {
    log.warn("--threads " + std::to_string(asked) + ": this process could start only " +
             std::to_string(startable) + " threads at once (its limits: ulimit -v, prlimit); " +
             "the run uses " + std::to_string(threads) + ", leaving memory for its data");
  }
  const std::size_t workers = std::min<std::size_t>(threads, p.points.size());
  // Points share the thread budget; a single point gets all of it.
  const int per_point = std::max(1, threads / static_cast<int>(workers));

  // Every plugin of every point is made (and so checked) before anything is written.
  Progress progress;
  progress.set_enabled(options.progress);
  std::vector<PointPlugins> plugins;
  ResultStream stream;
  double total_work = 0;
  std::string unit = "frames";
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    plugins.push_back(make_plugins(p, k, per_point, log, progress, dir, &stream, &out.files()));
    const Source::Work w = plugins.back().source->work();
    total_work += w.total;
    unit = w.unit;
  }

  out.claim();
  try {
    for (std::size_t k = 0; k < p.points.size(); ++k)
      create_point_directory(point_directory(p, k, dir));
    log.open_file((dir / "run.log").string(),
                  "granpipe " + std::string(version()) + " (" + git_commit() + "): " + p.name +
                      ", " + std::to_string(p.points.size()) + " point(s), seed " +
                      std::to_string(p.seed) + ", " + std::to_string(threads) +
                      " thread(s), output " + summary.output_dir.string());
    // The next run's early lines (its plugins' checks) must not land in this run's log.
    const ClosesLog closing{log};
    const std::string resolved = p.resolved.dump(2);
    const auto provenance = [&](double seconds, bool complete) {
      return Provenance{p.name,  resolved, version(), git_commit(), p.seed, threads,
                        seconds, started,  complete,  {},           {}};
    };
    write_file_atomically(dir / "pipeline.json", resolved + "\n");
    // Until the run ends the streamed tables go to results.partial.h5, marked incomplete
    // (as frames.partial.h5): a file named results.h5 is always a finished one.
    stream.open(dir / "results.partial.h5", provenance(0.0, false));
    std::set<std::string> warned;
    for (const PointPlugins& point : plugins) warn_once(point, warned, log);

    progress.start(p.name, total_work, unit);

    std::vector<PointOutcome> outcomes(p.points.size());
    std::vector<std::exception_ptr> errors(p.points.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (std::size_t k; (k = next++) < p.points.size();) {
        try {
          outcomes[k] = run_point(p, k, std::move(plugins[k]), stream, progress, dir);
        } catch (...) {
          errors[k] = std::current_exception();
          next = p.points.size();  // stop handing out points after a failure
        }
      }
    };
    std::vector<std::thread> pool;
    try {
      for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(worker);
    } catch (const std::exception& e) {
      // Past the process's limits (its memory under prlimit, --threads 128) the pool's
      // threads joined nothing and the run aborted; the points run on the threads it has.
      // (std::thread throws system_error, or bad_alloc for its state; so may the warning.)
      try {
        log.warn("--threads " + std::to_string(threads) + ": started " +
                 std::to_string(pool.size() + 1) + " of " + std::to_string(workers) +
                 " threads for the points (" + e.what() + "); the points run on those");
      } catch (...) {
      }
    }
    worker();
    for (auto& t : pool) t.join();
    progress.finish(std::none_of(errors.begin(), errors.end(),
                                 [](const std::exception_ptr& e) { return e != nullptr; }));
    stream.close();
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);

    Provenance ended = provenance(0.0, true);
    ended.stage_names = stage_names(p);
    ended.stage_seconds.assign(ended.stage_names.size(), 0.0);
    for (auto& o : outcomes) {
      summary.frames += o.frames;
      for (auto& [group, r] : o.results) summary.results.emplace(group, std::move(r));
      for (std::size_t s = 0; s < o.stage_seconds.size(); ++s)
        ended.stage_seconds[s] += o.stage_seconds[s];
    }
    if (p.points.size() > 1) summary.results["sweep"] = sweep_summary(p, summary.results);
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    ended.wall_seconds = summary.seconds;
    log.info(stage_times_line(ended, p.points.size()));
    summary.stage_names = ended.stage_names;
    summary.stage_seconds = ended.stage_seconds;
    write_results(dir, summary.results, ended, out.files());
    fs::remove(dir / "results.partial.h5");
    log.info("done: " + std::to_string(summary.frames) + " frame(s) in " +
             std::to_string(summary.seconds) + " s; results in " +
             (summary.output_dir / "results.h5").string());
    out.complete(log);
  } catch (const StopRequested&) {
    throw;  // the signal's handler marked the run interrupted
  } catch (const std::exception& e) {
    out.fail(e.what());
    throw;
  } catch (...) {
    out.fail("an unknown error");
    throw;
  }
  return summary;
}

// The pipeline as run in `dir`: an --out replaces output.dir in what the run records too
// (pipeline.json, every file's provenance), which otherwise named a folder never written.
Pipeline::Impl written_to(const Pipeline::Impl& p, const fs::path& dir) {
  Pipeline::Impl as_run = p;
  as_run.output_dir = dir;
  as_run.resolved["output"]["dir"] = dir.string();
  for (PointSpec& point : as_run.points) point.resolved["output"]["dir"] = dir.string();
  return as_run;
}

}  // namespace

RunSummary Pipeline::run(const RunOptions& options, Log& log) const {
  try {
    if (options.out) return run_in_directory(written_to(*impl_, *options.out), options, log);
    return run_in_directory(*impl_, options, log);
  } catch (const StopRequested& stop) {
    // Every file of the run is closed by now (frames.partial.h5 opens without SWMR).
    end_by_signal(stop.signal);
    throw InputError(std::string("interrupted by ") +
                     (stop.signal == SIGINT ? "SIGINT" : "SIGTERM"));
  }
}

}  // namespace granpipe
