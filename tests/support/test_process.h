// What the tests need of the OS, on POSIX systems and on Windows (the MinGW-w64 build, run under Wine): a temporary
// folder per process, removed as it exits; running a program with its stderr in a file; FIFOs and a forked child's
// exit (POSIX only); the process's threads (Linux only).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <system_error>
#include <thread>

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

// This process's folder in gtest's temporary folder, made at its first use and removed with all it holds when the
// process exits: ctest runs each test in a process of its own, several at once, and a run leaves nothing behind.
// A folder of a crashed run whose process id this one reuses is emptied first.
inline const std::filesystem::path& scratch_dir() {
  struct Scratch {
    std::filesystem::path dir;
    Scratch() {
#if defined(_WIN32)
      const int pid = _getpid();
#else
      const int pid = getpid();
#endif
      dir = std::filesystem::path(testing::TempDir()) / ("roomsense_tests_" + std::to_string(pid));
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    ~Scratch() {
      std::error_code ignored;  // a file still open elsewhere stays: nothing to report at exit
      std::filesystem::remove_all(dir, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.dir;
}

// A file name in scratch_dir(): ctest runs a binary's tests in parallel processes.
inline std::string temp_path(const std::string& name) { return (scratch_dir() / name).string(); }

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

// Runs `body` in a forked child that then calls exit(0), as an application that ends with everything open
// (POSIX only: call where kPosix). Returns "" when the child exited with status 0 within `limit`; otherwise what
// happened (a hang is killed at the limit).
inline std::string exit_of_child(const std::function<void()>& body, std::chrono::seconds limit) {
#if defined(_WIN32)
  (void)body, (void)limit;
  return "fork() is POSIX";
#else
  const pid_t child = fork();
  if (child < 0) return "fork failed";
  if (child == 0) {
    body();
    std::exit(0);
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  pid_t done = 0;
  while ((done = waitpid(child, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (done == 0) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    return "still running " + std::to_string(limit.count()) + " s after exit()";
  }
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return WEXITSTATUS(status) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status));
#endif
}

// The process's threads by id, from /proc/self/task (Linux; empty elsewhere): the tests of worker threads kept from
// one compute to the next.
inline constexpr bool kThreadsListed =
#if defined(__linux__)
    true;
#else
    false;
#endif
inline std::set<std::string> process_threads() {
  std::set<std::string> ids;
  if constexpr (kThreadsListed)
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task")) ids.insert(entry.path().filename().string());
  return ids;
}

// process_threads() once it equals `expected`, or after `limit` as it then is. A joined thread's entry leaves
// /proc/self/task a moment after its join returns (the join waits for the thread's id to be cleared, which the kernel
// does before it reaps the thread), so a list read at once may still hold it on a busy machine.
inline std::set<std::string> process_threads_settled(const std::set<std::string>& expected,
                                                     std::chrono::milliseconds limit = std::chrono::seconds(2)) {
  const auto until = std::chrono::steady_clock::now() + limit;
  std::set<std::string> now = process_threads();
  while (now != expected && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    now = process_threads();
  }
  return now;
}

}  // namespace roomsense::test
