#include "granpipe/huge_pages.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace granpipe::huge_pages {

namespace {

// MADV_COLLAPSE of Linux 6.1, which glibc 2.36's headers do not name yet; an older kernel
// refuses it (EINVAL) and the advice alone stays.
constexpr int kCollapse = 25;

std::size_t rounded_up(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }

// The tunable named among GLIBC_TUNABLES' "name=value:name=value".
bool names_tunable(std::string_view tunables, std::string_view name) {
  while (!tunables.empty()) {
    const std::size_t end = std::min(tunables.find(':'), tunables.size());
    const std::string_view item = tunables.substr(0, end);
    if (item.substr(0, item.find('=')) == name) return true;
    tunables.remove_prefix(std::min(end + 1, tunables.size()));
  }
  return false;
}

// The program's own path, so that the process keeps its name (ps, pgrep, top show the
// file name executed: "exe" for /proc/self/exe).
std::string own_path() {
  std::string path(4096, '\0');
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size());
  if (n <= 0 || static_cast<std::size_t>(n) >= path.size()) return {};
  path.resize(static_cast<std::size_t>(n));
  return path;
}

void restore(const char* name, const char* value) {
  if (value) {
    setenv(name, value, 1);
  } else {
    unsetenv(name);
  }
}

}  // namespace

// Maps one page more than needed and gives back what lies before the first 2 MB boundary
// and after the last page (mmap aligns to 4 kB only).
void* allocate(std::size_t bytes) {
  const std::size_t size = rounded_up(bytes);
  void* mapped =
      mmap(nullptr, size + kPage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + kPage - 1) / kPage * kPage;
  if (aligned > start) munmap(mapped, aligned - start);
  const std::uintptr_t end = start + size + kPage;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - aligned - size);
  // Advice only: a kernel without transparent huge pages leaves 4 kB pages.
  madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}

void deallocate(void* p, std::size_t bytes) noexcept { munmap(p, rounded_up(bytes)); }

void advise(void* data, std::size_t bytes) noexcept {
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (start + kPage - 1) / kPage * kPage;
  const std::uintptr_t last = (start + bytes) / kPage * kPage;
  if (last <= first) return;
  void* pages = reinterpret_cast<void*>(first);
  madvise(pages, last - first, MADV_HUGEPAGE);
  madvise(pages, last - first, kCollapse);
}

// A pores analysis of 10^5 spheres takes about 39 000 page faults with 4 kB pages and 6 000
// with huge pages, 30 % less time on this machine kind (docs/benchmarks.md).
void restart_with_malloc_huge_pages(char** argv) noexcept {
  // Once only, whatever glibc makes of the tunables it is given.
  if (std::getenv("GRANPIPE_MALLOC_RESTARTED")) return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && names_tunable(tunables, "glibc.malloc.hugetlb")) return;
  // Under an address-space limit (ulimit -v, prlimit --as) the heap's 2 MB alignment wastes
  // what the limit leaves, and glibc's huge-page heap crashed (SIGSEGV, about one run in
  // ten) where a run of many threads had exhausted it; the default heap fails cleanly.
  rlimit space{};
  if (getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY) return;
  const std::string path = own_path();
  if (path.empty()) return;
  const std::string before = tunables ? tunables : "";
  const std::string ask = "glibc.malloc.hugetlb=1";
  const std::string value = before.empty() ? ask : before + ":" + ask;
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0 &&
      setenv("GRANPIPE_MALLOC_RESTARTED", "1", 1) == 0) {
    execv(path.c_str(), argv);
  }
  // Not run again (the program gone, an environment too large to pass on): the default heap
  // serves, only slower, and the programs this one starts get the environment it was given.
  restore("GLIBC_TUNABLES", tunables ? before.c_str() : nullptr);
  unsetenv("GRANPIPE_MALLOC_RESTARTED");
}

}  // namespace granpipe::huge_pages
