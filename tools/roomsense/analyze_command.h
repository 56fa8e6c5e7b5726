#pragma once
#include <string>
#include <vector>

namespace roomsense::cli {

// `roomsense analyze`: returns the process exit status.
int analyze_command(const std::vector<std::string>& args);

}  // namespace roomsense::cli
