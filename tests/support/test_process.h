// What the tests need of the OS, on POSIX systems and on Windows (the MinGW-w64 build, run under Wine):
// per-process temporary file names, running a program with its stderr in a file, and FIFOs (POSIX only).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#if defined(_WIN32)
#  include <process.h>
#else
#  include <sys/stat.h>
#  include <sys/wait.h>
#  include <unistd.h>
#endif

namespace roomsense::test {

// FIFOs, /dev/zero and ulimit exist: the tests of such paths and limits run (not on Windows).
#if defined(_WIN32)
inline constexpr bool kPosix = false;
#else
inline constexpr bool kPosix = true;
#endif

// A file name in gtest's temporary folder, unique to this process: ctest runs a binary's tests in parallel.
inline std::string temp_path(const std::string& name) {
#if defined(_WIN32)
  const int pid = _getpid();
#else
  const int pid = getpid();
#endif
  return testing::TempDir() + "/" + std::to_string(pid) + "_" + name;
}

// Runs `program args` with stderr written to `stderr_path` and stdout to `stdout_path` (empty: discarded);
// returns its exit status, or -1 when it did not exit (a signal). `shell_prefix` runs first in the same POSIX
// shell, e.g. a ulimit.
inline int run_program(const std::string& program, const std::string& args, const std::string& stderr_path,
                       const std::string& shell_prefix = "", const std::string& stdout_path = "") {
#if defined(_WIN32)
  std::string exe = program;
  std::replace(exe.begin(), exe.end(), '/', '\\');  // cmd.exe takes /x for a switch
  // cmd /c drops the first and last quote of a line that starts with one: hence the outer pair.
  const std::string out = stdout_path.empty() ? std::string("NUL") : "\"" + stdout_path + "\"";
  const std::string line = "\"\"" + exe + "\" " + args + " >" + out + " 2>\"" + stderr_path + "\"\"";
  (void)shell_prefix;
  return std::system(line.c_str());
#else
  const std::string out = stdout_path.empty() ? std::string("/dev/null") : stdout_path;
  const std::string line = shell_prefix + program + " " + args + " >" + out + " 2>" + stderr_path;
  const int raw = std::system(line.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
#endif
}

// Makes a FIFO at `path` (POSIX only: call where kPosix).
inline bool make_fifo(const std::string& path) {
#if defined(_WIN32)
  (void)path;
  return false;
#else
  return mkfifo(path.c_str(), 0600) == 0;
#endif
}

}  // namespace roomsense::test
