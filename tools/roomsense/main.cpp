// roomsense: the command-line front end of the room pipeline.
#include "analyze_command.h"
#include "options.h"
#include "place_command.h"

#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Command {
  const char* name;
  const char* usage;
  int (*run)(const std::vector<std::string>&);
};
const Command kCommands[] = {{"analyze", roomsense::cli::kUsage, roomsense::cli::analyze_command},
                             {"place", roomsense::cli::kPlaceUsage, roomsense::cli::place_command}};

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    for (const Command& c : kCommands) std::fprintf(args.empty() ? stderr : stdout, "%s%s", &c == kCommands ? "" : "\n", c.usage);
    return args.empty() ? 2 : 0;
  }
  for (const Command& c : kCommands) {
    if (args[0] != c.name) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const std::string& a : rest)
      if (a == "-h" || a == "--help") {
        std::fputs(c.usage, stdout);
        return 0;
      }
    return c.run(rest);
  }
  std::fprintf(stderr, "roomsense: unknown command '%s' (try roomsense --help)\n", args[0].c_str());
  return 2;
}

}  // namespace

// Nothing may end the process with an abort: whatever escapes the command is one line and status 1.
int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("roomsense: out of memory\n", stderr);
  } catch (const std::length_error&) {
    std::fputs("roomsense: out of memory\n", stderr);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomsense: %s\n", e.what());
  }
  return 1;
}
