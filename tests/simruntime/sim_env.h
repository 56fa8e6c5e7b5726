// Test helpers: scoped environment variables (the runtime reads its options at xrCreateInstance) and a
// small room written as OBJ, so that something runs without ../shared/rooms.
#pragma once
#include "test_process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace simtest {

class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value->c_str(), 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_.c_str(), old_->c_str(), 1);
    else unsetenv(name_.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// A 4 x 2.5 x 3 m box room, floor and ceiling as grids of `n` x `n` quads (faces point into the room).
inline std::filesystem::path write_box_room(const std::string& name, int n = 8) {
  const std::filesystem::path path = roomsense::test::scratch_dir() / name;
  std::ofstream out(path);
  int base = 1;
  auto grid = [&](double y, bool up) {
    for (int i = 0; i <= n; ++i)
      for (int k = 0; k <= n; ++k) out << "v " << -2.0 + 4.0 * i / n << ' ' << y << ' ' << -1.5 + 3.0 * k / n << '\n';
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) {
        const int a = base + i * (n + 1) + k, b = a + (n + 1), c = b + 1, d = a + 1;
        if (up) out << "f " << a << ' ' << d << ' ' << c << "\nf " << a << ' ' << c << ' ' << b << '\n';
        else out << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
      }
    base += (n + 1) * (n + 1);
  };
  grid(0.0, true);
  grid(2.5, false);
  auto quad = [&](double x0, double z0, double x1, double z1) {
    out << "v " << x0 << " 0 " << z0 << "\nv " << x1 << " 0 " << z1 << "\nv " << x1 << " 2.5 " << z1 << "\nv " << x0 << " 2.5 " << z0 << '\n';
    out << "f " << base << ' ' << base + 1 << ' ' << base + 2 << "\nf " << base << ' ' << base + 2 << ' ' << base + 3 << '\n';
    base += 4;
  };
  quad(-2, -1.5, 2, -1.5);
  quad(2, -1.5, 2, 1.5);
  quad(2, 1.5, -2, 1.5);
  quad(-2, 1.5, -2, -1.5);
  return path;
}

}  // namespace simtest
