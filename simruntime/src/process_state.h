// The simulated runtime's process-wide objects (the runtime's handles, each extension's state, the room and scan
// caches), each made at its first use but all owned by one holder that the loader's negotiation makes first.
// exit() destroys statics in the reverse order of their making: the loader negotiates with the runtime before any
// API layer's first call, so these go after every layer's statics, and a layer's thread that still calls the
// runtime while its layer's statics are destroyed (roomsense's analyzer joins its worker there) finds them whole.
// Statics of their own, made at first use during such a call, were destroyed first: a use-after-free of the Meta
// extension's state under ASan (LayerLifecycle.AProcessExitingMidComputeEndsCleanly). The loader's unloading of
// the runtime (dlclose) destroys them with the holder, as before.
#pragma once
#include <memory>
#include <mutex>
#include <vector>

namespace roomsense::sim {

class ProcessState {
 public:
  static ProcessState& holder() {
    static ProcessState state;
    return state;
  }
  ProcessState(const ProcessState&) = delete;
  ProcessState& operator=(const ProcessState&) = delete;
  ~ProcessState() {
    while (!objects_.empty()) objects_.pop_back();  // the latest made first, as statics go
  }

  template <class T>
  T& make() {
    auto object = std::make_shared<T>();
    T& made = *object;
    std::lock_guard lock(mutex_);
    objects_.push_back(std::move(object));
    return made;
  }

 private:
  ProcessState() = default;
  std::mutex mutex_;
  std::vector<std::shared_ptr<void>> objects_;
};

// The one T of the process, made at the first call and owned by ProcessState's holder.
template <class T>
T& process_wide() {
  static T* const object = &ProcessState::holder().make<T>();  // a pointer: nothing of its own to destroy at exit
  return *object;
}

}  // namespace roomsense::sim
