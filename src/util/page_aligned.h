// Vectors whose storage starts on a page boundary. The scene's arrays live in them so an
// OpenCL device on the host's CPU can render straight from them (CL_MEM_USE_HOST_PTR,
// src/device/cl/cl_scene_buffers.cpp): a runtime uses a host pointer as the buffer only when it is
// aligned as the device asks (CL_DEVICE_MEM_BASE_ADDR_ALIGN; PoCL: 128 bytes), and a page
// is a multiple of what any device asks; otherwise it keeps a second copy of the scene.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

namespace rt {

template <class T>
struct PageAlignedAllocator {
  using value_type = T;
  static constexpr std::size_t kAlignment = 4096;

  PageAlignedAllocator() = default;
  template <class U>
  PageAlignedAllocator(const PageAlignedAllocator<U>&) {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T) - kAlignment) throw std::bad_alloc();
    // aligned_alloc wants a size that is a multiple of the alignment.
    std::size_t bytes = (n * sizeof(T) + kAlignment - 1) / kAlignment * kAlignment;
    void* p = std::aligned_alloc(kAlignment, bytes);
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }

  template <class U>
  bool operator==(const PageAlignedAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const PageAlignedAllocator<U>&) const {
    return false;
  }
};

template <class T>
using PageAlignedVector = std::vector<T, PageAlignedAllocator<T>>;

}  // namespace rt
