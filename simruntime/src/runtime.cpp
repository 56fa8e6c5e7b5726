// The global state and the destruction cascades (instance -> sessions -> spaces, observers -> scenes).
#include "runtime.h"
#include "process_state.h"

#include "extensions/served_extension.h"

#include "roomsense/platform.h"

namespace roomsense::sim {

Runtime& runtime() {
  return process_wide<Runtime>();  // lives until the library is unloaded, or exit's end (process_state.h)
}

XrTime now_time() { return platform::monotonic_nanoseconds(); }

void Runtime::push_state(SessionState& session, std::uint64_t session_id, XrSessionState state) {
  session.state = state;
  InstanceState* owner = find(instances, session.instance);
  if (owner != nullptr) owner->events.push_back({session_id, state, now_time()});
}

void Runtime::destroy_observer(std::uint64_t id, Graveyard& graveyard) {
  auto it = observers.find(id);
  if (it == observers.end()) return;
  it->second->end_compute();
  for (auto s = scenes.begin(); s != scenes.end();) s = s->second->observer == id ? scenes.erase(s) : std::next(s);
  graveyard.observers.push_back(std::move(it->second));
  observers.erase(it);
}

void Runtime::destroy_session(std::uint64_t id, Graveyard& graveyard) {
  for (auto it = spaces.begin(); it != spaces.end();) it = it->second->session == id ? spaces.erase(it) : std::next(it);
  std::vector<std::uint64_t> owned;
  for (const auto& [oid, observer] : observers)
    if (observer->session == id) owned.push_back(oid);
  for (std::uint64_t oid : owned) destroy_observer(oid, graveyard);
  if (auto it = sessions.find(id); it != sessions.end()) {
    // Events about a destroyed session must not reach the application.
    if (InstanceState* owner = find(instances, it->second->instance))
      std::erase_if(owner->events, [id](const SessionEvent& e) { return e.session == id; });
    sessions.erase(it);
    input.forget_session(id);
    graveyard.sessions.push_back(id);
  }
}

void Runtime::destroy_instance(std::uint64_t id, Graveyard& graveyard) {
  std::vector<std::uint64_t> owned;
  for (const auto& [sid, session] : sessions)
    if (session->instance == id) owned.push_back(sid);
  for (std::uint64_t sid : owned) destroy_session(sid, graveyard);
  input.forget_instance(id);
  if (instances.erase(id) > 0) graveyard.instances.push_back(id);
}

Runtime::Graveyard::~Graveyard() {
  observers.clear();
  for (const ServedExtension* e : served_extensions()) {
    if (e->forget_session != nullptr)
      for (std::uint64_t id : sessions) e->forget_session(id);
    if (e->forget_instance != nullptr)
      for (std::uint64_t id : instances) e->forget_instance(id);
  }
}

}  // namespace roomsense::sim
