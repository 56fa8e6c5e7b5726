// xrStringToPath / xrPathToString: paths are interned per instance; XrPath n is the n-th distinct string.
#include "functions.h"
#include "runtime.h"
#include "validate.h"

#include <cstring>
#include <string_view>

namespace roomsense::sim {
namespace {

// The spec's well-formed path: "/" then components of [a-z0-9-_.], no empty, "." or ".." component, no
// trailing slash, shorter than XR_MAX_PATH_LENGTH.
bool well_formed(std::string_view path) {
  if (path.size() < 2 || path.size() >= XR_MAX_PATH_LENGTH || path.front() != '/' || path.back() == '/') return false;
  std::size_t start = 1;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string_view::npos) end = path.size();
    const std::string_view component = path.substr(start, end - start);
    if (component.empty() || component == "." || component == "..") return false;
    for (char c : component)
      if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.')) return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

XrResult XRAPI_CALL xrStringToPath(XrInstance instance, const char* pathString, XrPath* path) {
  return guarded("xrStringToPath", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (pathString == nullptr || path == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const std::size_t length = strnlen(pathString, XR_MAX_PATH_LENGTH);
    if (length >= XR_MAX_PATH_LENGTH) return XR_ERROR_PATH_FORMAT_INVALID;
    const std::string text(pathString, length);
    if (!well_formed(text)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (auto it = state->path_ids.find(text); it != state->path_ids.end()) {
      *path = it->second;
      return XR_SUCCESS;
    }
    state->paths.push_back(text);
    const XrPath id = state->paths.size();
    state->path_ids.emplace(text, id);
    *path = id;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrPathToString(XrInstance instance, XrPath path, uint32_t capacity, uint32_t* countOutput, char* buffer) {
  return guarded("xrPathToString", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (path == XR_NULL_PATH || path > state->paths.size()) return XR_ERROR_PATH_INVALID;
    if (countOutput == nullptr || (capacity > 0 && buffer == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
    const std::string& text = state->paths[path - 1];
    *countOutput = static_cast<uint32_t>(text.size() + 1);  // the count includes the terminator
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < text.size() + 1) return XR_ERROR_SIZE_INSUFFICIENT;
    std::memcpy(buffer, text.c_str(), text.size() + 1);
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
