// platform.h on POSIX systems: Linux and Android (dlopen, CLOCK_MONOTONIC, /proc/self).
#include "roomsense/platform.h"

#include <dlfcn.h>
#include <time.h>
#define XR_USE_TIMESPEC
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace roomsense::platform {

SharedLibrary::SharedLibrary(const std::string& name) {
  handle_ = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle_ == nullptr) {
    const char* why = dlerror();
    error_ = why != nullptr ? why : "unknown error";
  }
}

SharedLibrary::SharedLibrary(SharedLibrary&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), error_(std::move(other.error_)) {}

SharedLibrary& SharedLibrary::operator=(SharedLibrary&& other) noexcept {
  if (this != &other) {
    if (handle_ != nullptr) dlclose(handle_);
    handle_ = std::exchange(other.handle_, nullptr);
    error_ = std::move(other.error_);
  }
  return *this;
}

SharedLibrary::~SharedLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

void* SharedLibrary::symbol(const char* name) const { return handle_ != nullptr ? dlsym(handle_, name) : nullptr; }

const char* vulkan_loader_name() {
#if defined(__ANDROID__)
  return "libvulkan.so";  // the NDK's name: Android has no versioned libvulkan
#else
  return "libvulkan.so.1";
#endif
}

ClockConversion clock_conversion() {
  return {"XR_KHR_convert_timespec_time", "xrConvertTimespecTimeToTimeKHR", "xrConvertTimeToTimespecTimeKHR"};
}

bool xr_time_now(void (*to_xr_time)(), XrInstance_T* instance, std::int64_t& time) {
  timespec now{};
  if (clock_gettime(CLOCK_MONOTONIC, &now) != 0) return false;
  const auto convert = reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(to_xr_time);
  return XR_SUCCEEDED(convert(instance, &now, &time));
}

std::int64_t monotonic_nanoseconds() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

void set_environment(const char* name, const std::string& value) { setenv(name, value.c_str(), 1); }

std::filesystem::path executable_path() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the program's own file (/proc/self/exe): " + ec.message());
  return self;
}

std::string loaded_module_path(const std::string& file_name) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    const auto at = line.find('/');
    if (at == std::string::npos) continue;
    const std::string path = line.substr(at);
    if (std::filesystem::path(path).filename() == file_name) return path;
  }
  return "";
}

}  // namespace roomsense::platform
