#include "run_marker.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr RunStatus kStatuses[] = {RunStatus::Running, RunStatus::Complete, RunStatus::Failed,
                                   RunStatus::Interrupted};

std::string utc_now(const char* format) {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, format, &tm);
  return buf;
}

RunMarker parse(const std::string& text) {
  const json j = json::parse(text);
  RunMarker m;
  m.run_id = j.at("run_id").get<std::string>();
  m.pid = j.at("pid").get<long>();
  m.started = j.at("started").get<std::string>();
  const std::string status = j.at("status").get<std::string>();
  for (RunStatus s : kStatuses)
    if (status == to_string(s)) {
      m.status = s;
      return m;
    }
  throw std::invalid_argument("unknown status");
}

}  // namespace

const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::Running:
      return "running";
    case RunStatus::Complete:
      return "complete";
    case RunStatus::Failed:
      return "failed";
    case RunStatus::Interrupted:
      return "interrupted";
  }
  return "?";
}

RunMarker new_run_marker() {
  // Time and process tell runs apart on one machine; the random part across machines
  // sharing a file system.
  std::random_device entropy;
  char tag[16];
  std::snprintf(tag, sizeof tag, "%04x", static_cast<unsigned>(entropy() & 0xffffu));
  RunMarker m;
  m.pid = static_cast<long>(getpid());
  m.started = utc_now("%Y-%m-%dT%H:%M:%SZ");
  m.run_id = utc_now("%Y%m%dT%H%M%SZ") + "-" + std::to_string(m.pid) + "-" + tag;
  return m;
}

std::optional<RunMarker> read_run_marker(const fs::path& dir) {
  const fs::path file = dir / kRunMarkerName;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(file, ec))) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  try {
    return parse(text.str());
  } catch (const std::exception&) {
    throw InputError(file.string() +
                     ": expected a granpipe run marker (JSON with run_id, pid, started, "
                     "status), got something else; granpipe leaves this directory alone");
  }
}

std::string run_marker_text(const RunMarker& m) {
  const json j{{"run_id", m.run_id},
               {"pid", m.pid},
               {"started", m.started},
               {"status", to_string(m.status)}};
  std::string text = j.dump();
  if (text.size() < kRunMarkerSize - 1) text.resize(kRunMarkerSize - 1, ' ');
  return text + "\n";
}

// Rewritten in place: a status change needs no new disk block, so a full disk still
// lets a run record that it failed.
void write_run_marker(const fs::path& dir, const RunMarker& marker) {
  const fs::path file = dir / kRunMarkerName;
  const std::string text = run_marker_text(marker);
  const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  bool ok = fd >= 0 &&
            pwrite(fd, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()) &&
            ftruncate(fd, static_cast<off_t>(text.size())) == 0;
  const int err = errno;
  if (fd >= 0) ok = close(fd) == 0 && ok;
  if (!ok) throw InputError(file.string() + ": cannot write the run marker: " + std::strerror(err));
}

}  // namespace granpipe
