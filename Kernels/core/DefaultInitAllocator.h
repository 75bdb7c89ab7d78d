// An allocator for large host arrays of trivial types that their owner fills in parallel. Host
// code.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace amrdm
{

/// std::allocator that default-initialises: resize() leaves trivial types untouched, so that
/// their owner first touches them in parallel (the CPU renderer's accumulation buffers: an
/// 8192^2 image has 4 GiB of them and a serial first touch dominated its render time; the
/// gridlet scalars, written once per gridlet by the build).
template<typename T>
struct DefaultInitAllocator : std::allocator<T>
{
  template<typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template<typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  /// Large buffers (>= 64 MiB) are 2 MiB aligned and, on Linux, marked for transparent huge
  /// pages: 512x fewer page faults when they are first touched.
  T* allocate(std::size_t n)
  {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < (std::size_t(64) << 20))
    {
      return std::allocator<T>::allocate(n);
    }
    constexpr std::size_t kHuge = std::size_t(2) << 20;
    void* p = std::aligned_alloc(kHuge, (bytes + kHuge - 1) / kHuge * kHuge);
    if (!p)
    {
      throw std::bad_alloc();
    }
#if defined(__linux__)
    madvise(p, (bytes + kHuge - 1) / kHuge * kHuge, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n)
  {
    if (n * sizeof(T) < (std::size_t(64) << 20))
    {
      std::allocator<T>::deallocate(p, n);
      return;
    }
    std::free(p);
  }
  template<typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template<typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

} // namespace amrdm
