#pragma once
// An allocator for the arrays a loop streams through on every step (a DEM run's per-pair
// arrays, tens of MB): allocations of 2 MB and more are mapped on 2 MB boundaries and
// marked for transparent huge pages, so that the processor's page-table cache covers them
// (with 4 kB pages it covers 8 MB here, and a step touching a few hundred MB spends its
// time on page walks; with the kernel's default "madvise" mode a process gets huge pages
// only where it asks). Smaller allocations are plain ones. Where the kernel gives no huge
// pages the memory is ordinary: nothing but the speed depends on it.
#include <cstddef>
#include <new>
#include <vector>

namespace granpipe {

namespace huge_pages {
inline constexpr std::size_t kPage = std::size_t{2} << 20;
// Bytes mapped on 2 MB boundaries (and advised) for a request of `bytes` >= kPage.
void* allocate(std::size_t bytes);
void deallocate(void* p, std::size_t bytes) noexcept;
// For memory allocated elsewhere (an Eigen array): asks for huge pages on the whole 2 MB
// pages inside [data, data + bytes), and has the kernel move what is already there onto
// them now (Linux >= 6.1; elsewhere the advice alone, or nothing).
void advise(void* data, std::size_t bytes) noexcept;
// Has glibc's malloc ask for huge pages under the heap too (what no allocator of ours can
// reach: CGAL's cells, Eigen's and the standard library's arrays), by executing the program
// again with GLIBC_TUNABLES=glibc.malloc.hugetlb=1, a setting glibc reads at start only.
// Call first thing in main: returns without it where the environment names the tunable
// already (the user's choice), after the restart (GRANPIPE_MALLOC_RESTARTED), or where the
// program cannot be run again.
void restart_with_malloc_huge_pages(char** argv) noexcept;
}  // namespace huge_pages

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_pages::kPage) return std::allocator<T>().allocate(n);
    return static_cast<T*>(huge_pages::allocate(bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_pages::kPage) return std::allocator<T>().deallocate(p, n);
    huge_pages::deallocate(p, bytes);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace granpipe
