// The demo's OpenXR calls, checked: a failure throws std::runtime_error naming the call and its result.
#pragma once
#include <openxr/openxr.h>

#include <stdexcept>
#include <string>

namespace roomsense::demo {

// The result's name: the extensions' results the demo can meet, else the loader's xrResultToString.
std::string result_name(XrInstance instance, XrResult result);

struct Checker {
  XrInstance instance = XR_NULL_HANDLE;
  void operator()(XrResult result, const char* what) const {
    if (XR_FAILED(result)) throw std::runtime_error(std::string(what) + " failed: " + result_name(instance, result));
  }
};

// A function of the instance, or an error when the loader has none.
template <typename PFN>
PFN proc(const Checker& check, XrInstance instance, const char* name) {
  PFN_xrVoidFunction f = nullptr;
  check(xrGetInstanceProcAddr(instance, name, &f), (std::string("xrGetInstanceProcAddr(") + name + ")").c_str());
  if (f == nullptr) throw std::runtime_error(std::string("xrGetInstanceProcAddr(") + name + ") returned no function");
  return reinterpret_cast<PFN>(f);
}

}  // namespace roomsense::demo
