// The heap a benchmark's iteration needs at its peak: this program's operator new and delete count the live
// bytes every allocation through them holds (all of roomsense's: containers, results, thread state), and keep
// the highest count since the last reset. Memory taken by malloc directly or by thread stacks is not counted.
#pragma once
#include <cstddef>

namespace roomsense::bench {

std::size_t live_heap_bytes();
// The highest live count since reset_heap_peak(), which sets it to the live count now.
std::size_t peak_heap_bytes();
void reset_heap_peak();

}  // namespace roomsense::bench
