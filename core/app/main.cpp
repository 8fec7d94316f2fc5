// The granpipe executable. Exit codes: 0 ok, 2 bad input, 1 internal error.
#include <CLI/CLI.hpp>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

#include "commands.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/file_kind.hpp"
#include "granpipe/huge_pages.hpp"
#include "granpipe/log.hpp"
#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"

namespace {
constexpr int kOk = 0, kInternal = 1, kBadInput = 2;

// More threads than any machine granpipe runs on has cores.
constexpr int kMaxThreads = 1024;

// --threads N: CLI11's own check prints its range as a 309-digit number.
std::string check_threads(const std::string& text) {
  int n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error == std::errc{} && end == text.data() + text.size() && n >= 1 && n <= kMaxThreads)
    return "";
  return "expected an integer in [1, " + std::to_string(kMaxThreads) + "], got \"" + text + "\"";
}

// --rows N: a negative count listed no frame and said that all of them were more.
std::string check_rows(const std::string& text) {
  long n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error == std::errc{} && end == text.data() + text.size() && n >= 0) return "";
  return "expected an integer >= 0, got \"" + text + "\"";
}

// A message is one line whatever the input put in it (a key or a plugin name with a
// newline): control characters are written as escapes.
std::string one_line(const std::string& message) {
  std::string out;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

// granpipe report DIR: a DIR that is no directory was blamed on DIR/pipeline.json, and a
// second line blamed the report script.
void check_run_directory(const std::string& dir) {
  const std::string found = granpipe::what_is_at(dir);
  if (found == "a directory") return;
  throw granpipe::InputError(dir + ": expected a run's output directory, got " +
                             (found == "no such file" ? "no such directory" : found));
}

// --out "": an empty path meant the pipeline's own output directory, which --overwrite
// then replaced. --out --no-report took the next option as the folder's name, and left the
// report written into ./--no-report.
std::string check_out(const std::string& text) {
  if (text.empty()) return "expected a directory path, got \"\"";
  if (text[0] == '-') {
    return "expected a directory path, got \"" + text + "\", an option (a folder named so: ./" +
           text + ")";
  }
  return "";
}

bool is_subcommand(const char* arg) {
  for (const char* s : {"run", "plugins", "describe", "validate", "inspect", "report"})
    if (std::strcmp(arg, s) == 0) return true;
  return false;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace granpipe;
  huge_pages::restart_with_malloc_huge_pages(argv);
  // Under a file-size limit (ulimit -f) a write past it sends SIGXFSZ, which killed the run
  // without a word and left it marked running. Ignored, the write fails (EFBIG) and the run
  // ends as on a full disk: one line, exit 2, marked failed.
  std::signal(SIGXFSZ, SIG_IGN);
  // `granpipe PIPELINE.json ...` is short for `granpipe run PIPELINE.json ...`.
  std::vector<char*> args(argv, argv + argc);
  static char run_word[] = "run";
  if (argc > 1 && argv[1][0] != '-' && !is_subcommand(argv[1]))
    args.insert(args.begin() + 1, run_word);

  CLI::App app{"granpipe: simulate and analyse granular packings"};
  app.set_version_flag("--version",
                       std::string("granpipe ") + version() + " (" + git_commit() + ")");
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "run a pipeline (the default: granpipe PIPELINE.json)");
  std::string pipeline_file;
  std::vector<std::string> sets;
  std::string out_dir;
  int threads = 0;
  bool overwrite = false, quiet = false;
  run->add_option("pipeline", pipeline_file, "pipeline JSON file")->required();
  run->add_option("--set", sets, "override a value: json.path=value (repeatable)");
  run->add_option("--out", out_dir, "output directory (default: the pipeline's output.dir)")
      ->check(CLI::Validator(check_out, ""));
  run->add_option("--threads", threads,
                  "threads, 1 to " + std::to_string(kMaxThreads) + " (default: all cores)")
      ->check(CLI::Validator(check_threads, ""));
  run->add_flag("--overwrite", overwrite, "replace an existing granpipe output directory");
  run->add_flag("--quiet", quiet, "no progress or log on stderr");
  bool no_report = false;
  run->add_flag("--no-report", no_report, "do not write report.html at the end of the run");

  auto* validate = app.add_subcommand("validate", "check a pipeline without running it");
  validate->add_option("pipeline", pipeline_file, "pipeline JSON file")->required();
  validate->add_option("--set", sets, "override a value: json.path=value (repeatable)");

  auto* plugins = app.add_subcommand("plugins", "list the plugins found");
  auto* describe = app.add_subcommand("describe", "print a plugin's parameters");
  std::string plugin_name;
  describe->add_option("plugin", plugin_name, "plugin name")->required();

  auto* inspect = app.add_subcommand("inspect", "summarise a frames file (H5MD)");
  std::string h5_file;
  long rows = 20;
  inspect->add_option("file", h5_file, "H5MD file")->required();
  inspect->add_option("--rows", rows, "frames to list (default 20)")
      ->check(CLI::Validator(check_rows, ""));

  auto* report = app.add_subcommand("report", "write report.html of a run (finished or not)");
  std::string run_dir;
  report->add_option("run_dir", run_dir, "the run's output directory")->required();

  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "granpipe: " << one_line(e.what()) << " (see granpipe --help)\n";
    return kBadInput;
  }

  try {
    if (*inspect) {
      app::inspect(h5_file, rows);
      return kOk;
    }
    if (*report) {
      check_run_directory(run_dir);
      const app::ReportOutcome made = app::write_report(run_dir);
      if (made.written) return kOk;
      if (made.refused) return kBadInput;  // the script's one line said why
      std::cerr << "granpipe: " << made.why_not << "\n";
      return kInternal;
    }
    Registry registry;
    load_plugins(registry, plugin_search_path());
    for (const std::string& w : load_report(registry).warnings()) {
      std::cerr << "granpipe: warning: " << one_line(w) << "\n";
    }
    Log log;
    if (*plugins) {
      app::list_plugins(registry);
    } else if (*describe) {
      app::describe(registry, plugin_name);
    } else if (*validate) {
      const Pipeline p = Pipeline::load(pipeline_file, sets, registry);
      p.check(log);
      std::cout << pipeline_file << ": valid, " << p.points() << " point(s)\n";
    } else if (*run) {
      const Pipeline p = Pipeline::load(pipeline_file, sets, registry);
      RunOptions options;
      if (!out_dir.empty()) options.out = out_dir;
      options.threads = threads;
      options.overwrite = overwrite;
      options.progress = !quiet;
      log.set_quiet(quiet);
      const RunSummary summary = p.run(options, log);
      if (!no_report) {
        const app::ReportOutcome made = app::write_report(summary.output_dir);
        if (!made.written) log.warn(made.why_not);
      }
    }
    return kOk;
  } catch (const InputError& e) {
    std::cerr << "granpipe: " << one_line(e.what()) << "\n";
    return kBadInput;
  } catch (const std::bad_alloc&) {
    // A size the input asked for (a file declaring 4e8 particles in 9 MB, a sweep's points,
    // --threads) past the machine's memory or the process's limit: exit 1 called it ours.
    std::cerr << "granpipe: out of memory: the input asks for more than this machine (or the "
                 "process's memory limit) gives: particles, frames, bins, sweep points or "
                 "--threads\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "granpipe: internal error: " << one_line(e.what()) << "\n";
    return kInternal;
  }
}
