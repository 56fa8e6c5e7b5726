#pragma once
#include <string>
#include <vector>

namespace roomsense::cli {

// `roomsense place`: where an object fits in the analysed room (queries.h); returns the process exit status.
int place_command(const std::vector<std::string>& args);

extern const char* const kPlaceUsage;

}  // namespace roomsense::cli
