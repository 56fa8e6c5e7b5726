// Shared by every entry point: no exception ever leaves the layer, and the spec's implicit valid usage
// (structure types, next chains) is checked the same way everywhere.
#pragma once
#include "log.h"

#include <openxr/openxr.h>

#include <new>
#include <string>

namespace roomsense::layer {

// Every entry point runs its body through this and returns an XrResult whatever happens inside.
template <typename Body>
XrResult guarded(const char* function, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    log_error(std::string(function) + ": out of memory");
    return XR_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    log_error(std::string(function) + ": " + e.what());
    return XR_ERROR_RUNTIME_FAILURE;
  } catch (...) {
    log_error(std::string(function) + ": unknown exception");
    return XR_ERROR_RUNTIME_FAILURE;
  }
}

// An OpenXR structure with its type set and everything else zero (next included).
template <typename T>
T xr_struct(XrStructureType type) {
  T s{};
  s.type = type;
  return s;
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

}  // namespace roomsense::layer
