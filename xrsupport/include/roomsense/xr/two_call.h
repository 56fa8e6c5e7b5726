// The spec's two-call idiom ("Buffer Size Parameters"), from both sides: serving an array (the runtime) and
// reading one (the layer's queries).
#pragma once
#include <openxr/openxr.h>
#include <openxr/openxr_reflection.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace roomsense::xr {

// Serving plain arrays: count query, then XR_ERROR_SIZE_INSUFFICIENT if the capacity is short.
template <typename T>
XrResult two_call(std::uint32_t capacity, std::uint32_t* count_out, T* out, const std::vector<T>& items) {
  if (count_out == nullptr || (capacity > 0 && out == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
  *count_out = static_cast<std::uint32_t>(items.size());
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < items.size()) return XR_ERROR_SIZE_INSUFFICIENT;
  for (std::size_t i = 0; i < items.size(); ++i) out[i] = items[i];
  return XR_SUCCESS;
}

// Serving arrays of typed output structures: every element's type is checked before anything is written.
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

// An XrResult's name (XR_ERROR_SESSION_LOST), or its number for one this header does not know.
inline std::string result_name(XrResult result) {
  switch (result) {
#define ROOMSENSE_XR_RESULT_CASE(name, value) \
  case name:                                 \
    return #name;
    XR_LIST_ENUM_XrResult(ROOMSENSE_XR_RESULT_CASE)
#undef ROOMSENSE_XR_RESULT_CASE
    default: return "XrResult " + std::to_string(result);
  }
}

// A failed OpenXR call: its message names the call and the result; `result` tells callers which.
struct CallFailed : std::runtime_error {
  CallFailed(const char* what, XrResult r) : std::runtime_error(std::string(what) + " failed (" + result_name(r) + ")"), result(r) {}
  XrResult result;
};

// Throws CallFailed (a std::runtime_error naming the call and its result) when an OpenXR call failed.
inline void check(XrResult result, const char* what) {
  if (XR_FAILED(result)) throw CallFailed(what, result);
}

// Reading: `call(capacity, &count, data)` twice, with at most `limit` elements (a runtime that reports absurd
// counts gets an error, not an allocation of its choosing). T is default-constructed, or copied from `proto`
// for typed structures.
template <typename T, typename Call>
std::vector<T> read_two_call(const char* what, Call&& call, std::size_t limit, const T& proto = T{}) {
  std::uint32_t count = 0;
  check(call(0u, &count, static_cast<T*>(nullptr)), what);
  if (count > limit) throw std::runtime_error(std::string(what) + " reported " + std::to_string(count) + " elements, over the limit");
  std::vector<T> items(count, proto);
  if (count == 0) return items;
  check(call(count, &count, items.data()), what);
  items.resize(std::min<std::size_t>(items.size(), count));
  return items;
}

}  // namespace roomsense::xr
