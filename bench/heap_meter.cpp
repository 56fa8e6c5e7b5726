// Counting replacements of the global operator new and delete (heap_meter.h). Each block starts with a
// header as large as its alignment (at least 16 bytes) whose last two words, just before the pointer handed
// out, hold the size asked for and the alignment: every delete, sized or not, subtracts what its new added.
#include "heap_meter.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<std::size_t> live{0};
std::atomic<std::size_t> peak{0};

void* allocate(std::size_t size, std::size_t align) {
  align = std::max(align, alignof(std::max_align_t));
  const std::size_t total = ((size + align + align - 1) / align) * align;  // aligned_alloc wants a multiple
  // malloc where its own alignment serves: aligned_alloc takes another path through glibc, whose heaps then grow
  // and shrink otherwise than a program's (and roomsense's in it) do.
  void* block = align <= alignof(std::max_align_t) ? std::malloc(total) : std::aligned_alloc(align, total);
  if (block == nullptr) return nullptr;
  std::size_t* const words = reinterpret_cast<std::size_t*>(static_cast<char*>(block) + align);
  words[-2] = size;
  words[-1] = align;
  const std::size_t now = live.fetch_add(size, std::memory_order_relaxed) + size;
  std::size_t high = peak.load(std::memory_order_relaxed);
  while (now > high && !peak.compare_exchange_weak(high, now, std::memory_order_relaxed)) {
  }
  return static_cast<char*>(block) + align;
}

void release(void* p) {
  if (p == nullptr) return;
  const std::size_t* const words = static_cast<const std::size_t*>(p);
  live.fetch_sub(words[-2], std::memory_order_relaxed);
  std::free(static_cast<char*>(p) - words[-1]);
}

void* allocate_or_throw(std::size_t size, std::size_t align) {
  void* p = allocate(size, align);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

namespace roomsense::bench {

std::size_t live_heap_bytes() { return live.load(std::memory_order_relaxed); }
std::size_t peak_heap_bytes() { return peak.load(std::memory_order_relaxed); }
void reset_heap_peak() { peak.store(live.load(std::memory_order_relaxed), std::memory_order_relaxed); }

}  // namespace roomsense::bench

void* operator new(std::size_t n) { return allocate_or_throw(n, alignof(std::max_align_t)); }
void* operator new[](std::size_t n) { return allocate_or_throw(n, alignof(std::max_align_t)); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate_or_throw(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate_or_throw(n, std::size_t(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, alignof(std::max_align_t)); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, alignof(std::max_align_t)); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return allocate(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return allocate(n, std::size_t(a)); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
