#include "roomsense/kept_threads.h"

#include "parallel.h"
#include "worker_pool.h"

namespace roomsense {

KeptThreads::KeptThreads(unsigned threads) : threads_(detail::resolve_threads(threads)) {
  detail::pool_for(pool_, threads_);
}

KeptThreads::~KeptThreads() = default;

}  // namespace roomsense
