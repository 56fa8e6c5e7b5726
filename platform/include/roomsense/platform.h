// The operating system, in the few places roomsense needs it. Implemented once per OS family: src/posix.cpp
// (Linux, Android) and src/windows.cpp. No product code outside platform/ includes an OS header (the tests'
// own helpers are in tests/support/test_process.h).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

struct XrInstance_T;  // OpenXR's instance handle (XrInstance), declared here so that OpenXR's header is not needed

// The entry point a plugin (the layer, the simulated runtime) exports; everything else stays hidden
// (-fvisibility=hidden on ELF; on Windows, the module-definition file made from the same version script).
#if defined(_WIN32)
#  define ROOMSENSE_PLUGIN_EXPORT __declspec(dllexport)
#else
#  define ROOMSENSE_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

namespace roomsense::platform {

// A shared library, loaded for this object's lifetime (dlopen, LoadLibraryW). Move-only.
class SharedLibrary {
 public:
  // Searched for as the OS searches; on failure loaded() is false and error() says why.
  explicit SharedLibrary(const std::string& name);
  SharedLibrary(SharedLibrary&& other) noexcept;
  SharedLibrary& operator=(SharedLibrary&& other) noexcept;
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;
  ~SharedLibrary();

  bool loaded() const { return handle_ != nullptr; }
  const std::string& error() const { return error_; }
  void* symbol(const char* name) const;  // nullptr when the library has no such symbol

 private:
  void* handle_ = nullptr;
  std::string error_;
};

// A library's process-wide object (a function-local static) whose destructor joins threads. Where exit() destroys
// statics while other threads still run (POSIX), it is destroyed, and its destructor stops and joins them before
// the statics they use go. A Windows DLL's statics are destroyed at its DLL_PROCESS_DETACH, which at a process's
// exit comes after ExitProcess ended every other thread in whatever it was doing: a join there never returned (the
// thesis API's jobs, capi.c.exit_without_cleanup, hung in every run under Wine). There it is never
// destroyed: the system ends the threads, and a DLL unloaded while they live leaves them waiting.
template <class T>
union ProcessWide {
  T value;
  ProcessWide() : value() {}
  ProcessWide(const ProcessWide&) = delete;
  ProcessWide& operator=(const ProcessWide&) = delete;
  ~ProcessWide() {
#if !defined(_WIN32)
    value.~T();
#endif
  }
};

// The Vulkan loader's file name: libvulkan.so.1 (Linux), libvulkan.so (Android), vulkan-1.dll (Windows).
const char* vulkan_loader_name();

// The monotonic clock that OpenXR runtimes convert to XrTime, and the extension that converts it:
// XR_KHR_convert_timespec_time (CLOCK_MONOTONIC as a timespec) on POSIX systems,
// XR_KHR_win32_convert_performance_counter_time (QueryPerformanceCounter as a LARGE_INTEGER) on Windows.
struct ClockConversion {
  const char* extension;
  const char* to_xr_time;    // xrConvertTimespecTimeToTimeKHR, xrConvertWin32PerformanceCounterToTimeKHR
  const char* from_xr_time;  // xrConvertTimeToTimespecTimeKHR, xrConvertTimeToWin32PerformanceCounterKHR
};
ClockConversion clock_conversion();
// The clock now as the runtime's XrTime: read, then converted by `to_xr_time` (the runtime's function as
// xrGetInstanceProcAddr gave it), called through its own type (a timespec or a LARGE_INTEGER pointer; a call through
// any other type is undefined behaviour, which clang's -fsanitize=function reports). False when the OS refuses or
// the function fails.
bool xr_time_now(void (*to_xr_time)(), XrInstance_T* instance, std::int64_t& time);
// The same clock in nanoseconds (the simulated runtime's XrTime).
std::int64_t monotonic_nanoseconds();

// Sets a variable of this process's environment (seen by libraries it loads later).
void set_environment(const char* name, const std::string& value);
// The running program's own file. Throws std::runtime_error when the OS cannot say.
std::filesystem::path executable_path();
// The full path of a module (shared library) loaded into this process whose file name is `file_name`, or "".
std::string loaded_module_path(const std::string& file_name);

}  // namespace roomsense::platform
