// platform.h on Windows (LoadLibraryW, QueryPerformanceCounter, the module list of the process).
#include "roomsense/platform.h"

#ifndef WIN32_LEAN_AND_MEAN
#  define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#  define NOMINMAX
#endif
#include <windows.h>
#include <tlhelp32.h>
#include <unknwn.h>  // IUnknown, which openxr_platform.h's Win32 part names (WIN32_LEAN_AND_MEAN leaves it out)
#define XR_USE_PLATFORM_WIN32
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace roomsense::platform {
namespace {

std::wstring widen(const std::string& utf8) {
  if (utf8.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), nullptr, 0);
  std::wstring out(static_cast<std::size_t>(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), out.data(), n);
  return out;
}

std::string last_error_text() {
  const DWORD code = GetLastError();
  char* text = nullptr;
  constexpr DWORD kFlags = FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS;
  const DWORD n = FormatMessageA(kFlags, nullptr, code, 0, reinterpret_cast<char*>(&text), 0, nullptr);
  std::string message = n != 0 && text != nullptr ? std::string(text, n) : "error " + std::to_string(code);
  if (text != nullptr) LocalFree(text);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r' || message.back() == ' '))
    message.pop_back();
  return message;
}

}  // namespace

SharedLibrary::SharedLibrary(const std::string& name) {
  // LOAD_LIBRARY_SEARCH_DEFAULT_DIRS: the application's folder and System32, never the current directory.
  handle_ = LoadLibraryExW(widen(name).c_str(), nullptr, LOAD_LIBRARY_SEARCH_DEFAULT_DIRS);
  if (handle_ == nullptr) error_ = name + ": " + last_error_text();
}

SharedLibrary::SharedLibrary(SharedLibrary&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), error_(std::move(other.error_)) {}

SharedLibrary& SharedLibrary::operator=(SharedLibrary&& other) noexcept {
  if (this != &other) {
    if (handle_ != nullptr) FreeLibrary(static_cast<HMODULE>(handle_));
    handle_ = std::exchange(other.handle_, nullptr);
    error_ = std::move(other.error_);
  }
  return *this;
}

SharedLibrary::~SharedLibrary() {
  if (handle_ != nullptr) FreeLibrary(static_cast<HMODULE>(handle_));
}

void* SharedLibrary::symbol(const char* name) const {
  if (handle_ == nullptr) return nullptr;
  return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(handle_), name));
}

const char* vulkan_loader_name() { return "vulkan-1.dll"; }

ClockConversion clock_conversion() {
  return {"XR_KHR_win32_convert_performance_counter_time", "xrConvertWin32PerformanceCounterToTimeKHR",
          "xrConvertTimeToWin32PerformanceCounterKHR"};
}

bool xr_time_now(void (*to_xr_time)(), XrInstance_T* instance, std::int64_t& time) {
  LARGE_INTEGER now{};
  if (QueryPerformanceCounter(&now) == 0) return false;
  const auto convert = reinterpret_cast<PFN_xrConvertWin32PerformanceCounterToTimeKHR>(to_xr_time);
  return XR_SUCCEEDED(convert(instance, &now, &time));
}

std::int64_t monotonic_nanoseconds() {
  LARGE_INTEGER count{}, frequency{};
  QueryPerformanceCounter(&count);
  QueryPerformanceFrequency(&frequency);
  // Split, so that count * 1e9 cannot overflow after months of uptime.
  const std::int64_t seconds = count.QuadPart / frequency.QuadPart, rest = count.QuadPart % frequency.QuadPart;
  return seconds * 1000000000 + rest * 1000000000 / frequency.QuadPart;
}

void set_environment(const char* name, const std::string& value) { _putenv_s(name, value.c_str()); }

std::filesystem::path executable_path() {
  std::vector<wchar_t> buffer(MAX_PATH);
  for (;;) {
    const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), static_cast<DWORD>(buffer.size()));
    if (n == 0) throw std::runtime_error("cannot find the program's own file: " + last_error_text());
    if (n < buffer.size()) return std::filesystem::path(std::wstring(buffer.data(), n));
    if (buffer.size() >= 32768) throw std::runtime_error("cannot find the program's own file: its path is too long");
    buffer.resize(buffer.size() * 2);
  }
}

std::string loaded_module_path(const std::string& file_name) {
  const HANDLE snapshot = CreateToolhelp32Snapshot(TH32CS_SNAPMODULE, GetCurrentProcessId());
  if (snapshot == INVALID_HANDLE_VALUE) return "";
  std::string found;
  MODULEENTRY32W entry{};
  entry.dwSize = sizeof(entry);
  for (BOOL more = Module32FirstW(snapshot, &entry); more && found.empty(); more = Module32NextW(snapshot, &entry)) {
    const std::filesystem::path path(entry.szExePath);
    if (path.filename() == std::filesystem::path(file_name)) found = path.string();
  }
  CloseHandle(snapshot);
  return found;
}

}  // namespace roomsense::platform
