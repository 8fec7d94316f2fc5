#include "granpipe/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>

namespace granpipe::huge_pages {

namespace {

// MADV_COLLAPSE of Linux 6.1, which glibc 2.36's headers do not name yet; an older kernel
// refuses it (EINVAL) and the advice alone stays.
constexpr int kCollapse = 25;

std::size_t rounded_up(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }

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

}  // namespace granpipe::huge_pages
