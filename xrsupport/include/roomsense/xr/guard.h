// What every entry point of the layer and of the simulated runtime shares: no exception ever crosses into the
// application, and the spec's implicit valid usage (structure types, next chains, fixed strings) is checked
// the same way everywhere.
#pragma once
#include <openxr/openxr.h>

#include <cstring>
#include <exception>
#include <new>
#include <string>

namespace roomsense::xr {

// Runs an entry point's body and returns an XrResult whatever happens inside; `report` gets one line for
// anything thrown (its product's log).
template <typename Report, typename Body>
XrResult guarded(const char* function, Report&& report, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    try {
      report(std::string(function) + ": out of memory");
    } catch (...) {
    }
    return XR_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    try {
      report(std::string(function) + ": " + e.what());
    } catch (...) {
    }
    return XR_ERROR_RUNTIME_FAILURE;
  } catch (...) {
    try {
      report(std::string(function) + ": unknown exception");
    } catch (...) {
    }
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

// A fixed-size string field must hold a terminator within its size.
inline bool terminated(const char* text, std::size_t size) { return std::memchr(text, '\0', size) != nullptr; }

inline bool same_bytes(const void* a, const void* b, std::size_t size) { return std::memcmp(a, b, size) == 0; }

}  // namespace roomsense::xr
