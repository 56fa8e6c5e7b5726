// xrResultToString and xrStructureTypeToString, from the registry's reflection lists.
#include "functions.h"
#include "runtime.h"
#include "validate.h"

#include <openxr/openxr_reflection.h>

#include <cstdio>
#include <algorithm>
#include <cstring>

namespace roomsense::sim {
namespace {

const char* result_name(XrResult value) {
  switch (value) {
#define SIM_CASE(name, val) \
  case name:                \
    return #name;
    XR_LIST_ENUM_XrResult(SIM_CASE)
#undef SIM_CASE
    default:
      return nullptr;
  }
}

const char* structure_name(XrStructureType value) {
  switch (value) {
#define SIM_CASE(name, val) \
  case name:                \
    return #name;
    XR_LIST_ENUM_XrStructureType(SIM_CASE)
#undef SIM_CASE
    default:
      return nullptr;
  }
}

// Copies text into buffer, truncated to size - 1 characters and always terminated.
void copy_out(char* buffer, std::size_t size, const char* text) {
  const std::size_t n = std::min(std::strlen(text), size - 1);
  std::memcpy(buffer, text, n);
  buffer[n] = '\0';
}

}  // namespace

XrResult XRAPI_CALL xrResultToString(XrInstance instance, XrResult value, char buffer[XR_MAX_RESULT_STRING_SIZE]) {
  return guarded("xrResultToString", [&]() -> XrResult {
    {
      std::lock_guard lock(runtime().mutex);
      if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    }
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (const char* name = result_name(value)) {
      copy_out(buffer, XR_MAX_RESULT_STRING_SIZE, name);
    } else {
      // The spec's fallback for values this runtime does not know.
      std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, value >= 0 ? "XR_UNKNOWN_SUCCESS_%d" : "XR_UNKNOWN_FAILURE_%d",
                    static_cast<int>(value));
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrStructureTypeToString(XrInstance instance, XrStructureType value,
                                            char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
  return guarded("xrStructureTypeToString", [&]() -> XrResult {
    {
      std::lock_guard lock(runtime().mutex);
      if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    }
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (const char* name = structure_name(value)) copy_out(buffer, XR_MAX_STRUCTURE_NAME_SIZE, name);
    else std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XR_UNKNOWN_STRUCTURE_TYPE_%d", static_cast<int>(value));
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
