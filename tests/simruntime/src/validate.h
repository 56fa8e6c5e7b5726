// Input checks shared by every entry point, mirroring the spec's implicit valid usage.
#pragma once
#include "log.h"

#include <openxr/openxr.h>

#include <cstdint>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace roomsense::sim {

// Every entry point runs its body through this: no exception ever crosses into the application.
template <typename Body>
XrResult guarded(const char* function, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return XR_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    log_error(std::string(function) + ": " + e.what());
    return XR_ERROR_RUNTIME_FAILURE;
  } catch (...) {
    log_error(std::string(function) + ": unknown exception");
    return XR_ERROR_RUNTIME_FAILURE;
  }
}

inline bool has_type(const void* structure, XrStructureType type) {
  return structure != nullptr && static_cast<const XrBaseInStructure*>(structure)->type == type;
}

// The first structure of `type` in a next chain, or null.
template <typename T>
T* find_next(const void* next, XrStructureType type) {
  for (auto* s = static_cast<const XrBaseInStructure*>(next); s != nullptr; s = s->next)
    if (s->type == type) return const_cast<T*>(reinterpret_cast<const T*>(s));
  return nullptr;
}

// A fixed-size string field must hold a terminator within its size.
inline bool terminated(const char* text, std::size_t size) { return std::memchr(text, '\0', size) != nullptr; }

// The two-call idiom for plain arrays: count query, then XR_ERROR_SIZE_INSUFFICIENT if the capacity is short.
template <typename T>
XrResult two_call(std::uint32_t capacity, std::uint32_t* count_out, T* out, const std::vector<T>& items) {
  if (count_out == nullptr || (capacity > 0 && out == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
  *count_out = static_cast<std::uint32_t>(items.size());
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < items.size()) return XR_ERROR_SIZE_INSUFFICIENT;
  for (std::size_t i = 0; i < items.size(); ++i) out[i] = items[i];
  return XR_SUCCESS;
}

// The same for arrays of typed output structures: every element's type is checked before anything is written.
template <typename T, typename Fill>
XrResult two_call_typed(std::uint32_t capacity, std::uint32_t* count_out, T* out, std::size_t count,
                        XrStructureType type, Fill&& fill) {
  if (count_out == nullptr || (capacity > 0 && out == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
  if (capacity > 0)
    for (std::uint32_t i = 0; i < capacity; ++i)
      if (out[i].type != type) return XR_ERROR_VALIDATION_FAILURE;
  *count_out = static_cast<std::uint32_t>(count);
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < count) return XR_ERROR_SIZE_INSUFFICIENT;
  for (std::size_t i = 0; i < count; ++i) fill(out[i], i);
  return XR_SUCCESS;
}

}  // namespace roomsense::sim
