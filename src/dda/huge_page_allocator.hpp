#pragma once
// An allocator for the step's large arrays (the factor's blocks, the contact springs, the
// contacts): arrays of 256 KiB or more are placed on 2 MiB boundaries, their size rounded up
// to whole 2 MiB, and advised for transparent huge pages, so that their first touch costs one
// page fault per 2 MiB instead of one per 4 KiB page. The rounding costs at most 2 MiB for
// each of the few arrays that use it. On a virtual machine a fault costs microseconds: the
// 1,601-block wall's first step spent most of its time in them (bench_dda, BM_BrickWall;
// docs/performance.md).
// Where the kernel keeps huge pages off the advice is ignored and ordinary pages are used.
// Smaller arrays come from the ordinary allocator.

#include <cstdlib>
#include <memory>
#include <new>

#include <sys/mman.h>

namespace hydrodda::dda {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static constexpr std::size_t kLarge = std::size_t{256} << 10;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kLarge) return std::allocator<T>{}.allocate(n);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p == nullptr) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint; its failure leaves ordinary pages
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kLarge)
      std::allocator<T>{}.deallocate(p, n);
    else
      std::free(p);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept { return true; }
};

// Room for n elements in `v`, with a quarter more when it must grow: the step's arrays grow a
// little at a time as contacts come (a factor's fill, the contact list), and doubling each
// time, with the old values copied, touches fresh pages the size of the array again.
template <class Vector>
void reserve_with_headroom(Vector& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 4);
}

// `v` sized to n elements whose old values are not wanted (the caller overwrites them all):
// grown without copying them, with the headroom above.
template <class Vector>
void resize_for_overwrite(Vector& v, std::size_t n) {
  if (n > v.capacity()) v.clear();
  reserve_with_headroom(v, n);
  v.resize(n);
}

}  // namespace hydrodda::dda
