// The loader's way in: negotiation (the library's only exported symbol), xrCreateApiLayerInstance,
// xrGetInstanceProcAddr, and the instance and session hooks.
#include "analyzer.h"
#include "capture.h"
#include "functions.h"
#include "guard.h"
#include "roomsense/platform.h"
#include "roomsense/xr/loader_interface.h"
#include "log.h"
#include "state.h"
#include "spatial/spatial_api.h"
#include "spatial/spatial_instance.h"
#include "spatial/spatial_service.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace roomsense::layer {
namespace {

constexpr std::size_t kMaxTrackedSpaces = 4096;  // reference spaces remembered for baseSpace checks

enum class HookGroup { Always, Session, Spaces, Events, Frame, Extx };

// The runtime's clock conversion: XR_KHR_convert_timespec_time, or its Win32 performance-counter twin.
const platform::ClockConversion kClock = platform::clock_conversion();

struct Hook {
  PFN_xrVoidFunction function;
  HookGroup group;
};

const std::unordered_map<std::string_view, Hook>& hooks() {
  static const std::unordered_map<std::string_view, Hook> table = [] {
    std::unordered_map<std::string_view, Hook> t;
#define ROOMSENSE_ENTRY(name, group) t.emplace(#name, Hook{reinterpret_cast<PFN_xrVoidFunction>(&layer::name), group});
#define ROOMSENSE_ALWAYS(name) ROOMSENSE_ENTRY(name, HookGroup::Always)
#define ROOMSENSE_SESSION(name) ROOMSENSE_ENTRY(name, HookGroup::Session)
#define ROOMSENSE_SPACES(name) ROOMSENSE_ENTRY(name, HookGroup::Spaces)
#define ROOMSENSE_EVENTS(name) ROOMSENSE_ENTRY(name, HookGroup::Events)
#define ROOMSENSE_FRAME(name) ROOMSENSE_ENTRY(name, HookGroup::Frame)
#define ROOMSENSE_EXTX(name) ROOMSENSE_ENTRY(name, HookGroup::Extx)
    ROOMSENSE_HOOKS_ALWAYS(ROOMSENSE_ALWAYS)
    ROOMSENSE_HOOKS_SESSION(ROOMSENSE_SESSION)
    ROOMSENSE_HOOKS_SPACES(ROOMSENSE_SPACES)
    ROOMSENSE_HOOKS_EVENTS(ROOMSENSE_EVENTS)
    ROOMSENSE_HOOKS_FRAME(ROOMSENSE_FRAME)
    ROOMSENSE_EXTX_FUNCTIONS(ROOMSENSE_EXTX)
#undef ROOMSENSE_ENTRY
#undef ROOMSENSE_ALWAYS
#undef ROOMSENSE_SESSION
#undef ROOMSENSE_SPACES
#undef ROOMSENSE_EVENTS
#undef ROOMSENSE_FRAME
#undef ROOMSENSE_EXTX
    return t;
  }();
  return table;
}

// A mesh source's hook for `name`, or null.
const std::pair<const SourceInfo*, PFN_xrVoidFunction>* source_hook(std::string_view name) {
  static const std::unordered_map<std::string_view, std::pair<const SourceInfo*, PFN_xrVoidFunction>> table = [] {
    std::unordered_map<std::string_view, std::pair<const SourceInfo*, PFN_xrVoidFunction>> t;
    for (const SourceInfo* info : mesh_sources())
      for (const HookEntry& hook : info->hooks) t.emplace(hook.name, std::make_pair(info, hook.function));
    return t;
  }();
  const auto it = table.find(name);
  return it == table.end() ? nullptr : &it->second;
}

// Extension -> its functions, of every extension a source may enable.
const std::unordered_map<std::string_view, const char*>& source_function_extensions() {
  static const std::unordered_map<std::string_view, const char*> table = [] {
    std::unordered_map<std::string_view, const char*> t;
    for (const SourceInfo* info : mesh_sources())
      for (const ExtensionFunctions& e : info->extensions)
        for (const char* f : e.functions) t.emplace(f, e.extension);
    return t;
  }();
  return table;
}

bool enabled(const XrInstanceCreateInfo& info, const char* extension) {
  for (uint32_t i = 0; i < info.enabledExtensionCount; ++i)
    if (info.enabledExtensionNames[i] != nullptr && std::strcmp(info.enabledExtensionNames[i], extension) == 0) return true;
  return false;
}

bool addressed_to_us(const XrApiLayerNextInfo* info) {
  return info != nullptr && info->structType == XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO &&
         std::strncmp(info->layerName, kLayerName, XR_MAX_API_LAYER_NAME_SIZE) == 0;
}

template <typename PFN>
void load(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, const char* name, PFN& out) {
  PFN_xrVoidFunction f = nullptr;
  if (XR_SUCCEEDED(gipa(instance, name, &f))) out = reinterpret_cast<PFN>(f);
}

// What of the standard spatial-entity API the application asked for and the runtime has.
struct SpatialRequest {
  bool wanted = false;           // the application enabled XR_EXT_spatial_entity
  bool planes = false;           // the layer serves plane tracking: the application asked, the runtime has none
  bool clock = false;            // XR_KHR_convert_timespec_time is enabled below (by the application or the layer)
};

void register_instance(XrInstance instance, PFN_xrGetInstanceProcAddr next_gipa, const XrInstanceCreateInfo& info,
                       bool extx, bool capture, const std::vector<const SourceInfo*>& sources,
                       const std::vector<std::string>& added, const Config& config, const SpatialRequest& spatial);

bool layer_enabled(const InstanceState& state, const char* extension) {
  const auto& added = state.layer_enabled_extensions;
  return std::find(added.begin(), added.end(), extension) != added.end();
}

bool offers(const std::optional<std::vector<std::string>>& offered, const char* extension) {
  return !offered || std::find(offered->begin(), offered->end(), extension) != offered->end();
}

// The runtime's instance extensions, through the chain below us (a null instance reaches the runtime's
// xrEnumerateInstanceExtensionProperties); nothing when a layer below does not pass the call on.
std::optional<std::vector<std::string>> runtime_extensions(PFN_xrGetInstanceProcAddr next_gipa) {
  PFN_xrEnumerateInstanceExtensionProperties enumerate = nullptr;
  load(next_gipa, XR_NULL_HANDLE, "xrEnumerateInstanceExtensionProperties", enumerate);
  if (enumerate == nullptr) return std::nullopt;
  try {
    const auto properties = xr::read_two_call<XrExtensionProperties>(
        "xrEnumerateInstanceExtensionProperties",
        [&](std::uint32_t capacity, std::uint32_t* count, XrExtensionProperties* out) {
          return enumerate(nullptr, capacity, count, out);
        },
        4096, xr_struct<XrExtensionProperties>(XR_TYPE_EXTENSION_PROPERTIES));
    std::vector<std::string> names;
    for (const auto& p : properties) names.emplace_back(p.extensionName, strnlen(p.extensionName, sizeof p.extensionName));
    return names;
  } catch (const std::exception& e) {
    log_debug([&] { return std::string("the runtime's extensions cannot be listed: ") + e.what(); });
    return std::nullopt;
  }
}

XrResult XRAPI_CALL xrCreateApiLayerInstance(const XrInstanceCreateInfo* info, const XrApiLayerCreateInfo* layerInfo,
                                             XrInstance* instance) {
  return guarded("xrCreateApiLayerInstance", [&]() -> XrResult {
    if (info == nullptr || instance == nullptr || layerInfo == nullptr ||
        layerInfo->structType != XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO ||
        layerInfo->structVersion != XR_API_LAYER_CREATE_INFO_STRUCT_VERSION ||
        layerInfo->structSize != sizeof(XrApiLayerCreateInfo) || !addressed_to_us(layerInfo->nextInfo))
      return XR_ERROR_INITIALIZATION_FAILED;
    if (info->enabledExtensionCount > 0 && info->enabledExtensionNames == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    configure_log();
    const Config config = read_config();

    // The chain below us, with any further copy of this layer taken out: the same manifest found in two
    // search directories puts the layer into the chain twice. The copy nearest the application does the
    // work; the layer above a skipped copy calls what that copy would have called.
    const XrApiLayerNextInfo& ours = *layerInfo->nextInfo;
    PFN_xrGetInstanceProcAddr next_gipa = ours.nextGetInstanceProcAddr;
    PFN_xrCreateApiLayerInstance next_create = ours.nextCreateApiLayerInstance;
    std::vector<XrApiLayerNextInfo> below;
    std::size_t skipped = 0;
    for (const XrApiLayerNextInfo* e = ours.next; e != nullptr; e = e->next) {
      if (addressed_to_us(e)) {
        (below.empty() ? next_gipa : below.back().nextGetInstanceProcAddr) = e->nextGetInstanceProcAddr;
        (below.empty() ? next_create : below.back().nextCreateApiLayerInstance) = e->nextCreateApiLayerInstance;
        ++skipped;
        continue;
      }
      below.push_back(*e);
    }
    for (std::size_t i = 0; i < below.size(); ++i) below[i].next = i + 1 < below.size() ? &below[i + 1] : nullptr;
    if (next_gipa == nullptr || next_create == nullptr) return XR_ERROR_INITIALIZATION_FAILED;
    XrApiLayerCreateInfo down_layer_info = *layerInfo;
    down_layer_info.nextInfo = below.empty() ? nullptr : below.data();

    // Our extension is ours alone: the loader passes it down unfiltered, so take it out. An analysis needs the
    // runtime's scene meshes, so enable every mesh source's extensions the runtime has (sources/).
    // The spatial-entity extensions are the layer's to serve where the runtime lacks them (spatial/): then they
    // are taken out too.
    const bool extx = enabled(*info, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME);
    SpatialRequest spatial;
    spatial.wanted = enabled(*info, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME);
    const bool capture = extx || spatial.wanted || !config.export_dir.empty();
    // Only an instance the layer captures for asks the runtime: a pass-through one costs nothing.
    const std::optional<std::vector<std::string>> offered = capture ? runtime_extensions(next_gipa) : std::nullopt;
    spatial.planes = enabled(*info, XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME) &&
                     !offers(offered, XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME);
    const auto served_by_layer = [&](const char* name, bool chain_has_them) {
      if (!spatial.wanted) return false;
      for (const char* served : {XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
                                 XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME})
        if (std::strcmp(name, served) == 0 && !(chain_has_them && offers(offered, served))) return true;
      return false;
    };
    const auto ours_alone = [&](const char* name) {
      return std::strcmp(name, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME) == 0 || served_by_layer(name, true);
    };
    std::vector<const char*> extensions;
    for (uint32_t i = 0; i < info->enabledExtensionCount; ++i)
      if (const char* name = info->enabledExtensionNames[i]; name == nullptr || !ours_alone(name))
        extensions.push_back(name);  // a null name is the layers' and runtime's to reject below
    // The layer's own analyses need the runtime's clock where it has one.
    std::vector<std::string> clock;
    if (spatial.wanted && offered && offers(offered, kClock.extension) && !enabled(*info, kClock.extension)) {
      clock.emplace_back(kClock.extension);
      extensions.push_back(kClock.extension);
    }
    std::vector<const SourceInfo*> candidates;
    if (capture)
      for (const SourceInfo* source : mesh_sources())
        if (!offered || std::all_of(source->extensions.begin(), source->extensions.end(), [&](const ExtensionFunctions& e) {
              return std::find(offered->begin(), offered->end(), e.extension) != offered->end();
            }))
          candidates.push_back(source);
    XrInstanceCreateInfo down = *info;
    std::vector<std::string> added;
    auto create_with = [&](const std::vector<const SourceInfo*>& sources) {
      std::vector<const char*> names = extensions;
      added.clear();
      for (const SourceInfo* source : sources)
        for (const ExtensionFunctions& e : source->extensions)
          if (!enabled(*info, e.extension) && std::find(added.begin(), added.end(), e.extension) == added.end()) {
            added.emplace_back(e.extension);
            names.push_back(e.extension);
          }
      down.enabledExtensionCount = static_cast<uint32_t>(names.size());
      down.enabledExtensionNames = names.empty() ? nullptr : names.data();
      return next_create(&down, &down_layer_info, instance);
    };
    // Where the runtime's extension list could not be read, ask for every source and drop the least preferred
    // until the chain accepts (a layer below may answer an extension it does not know with another error than
    // XR_ERROR_EXTENSION_NOT_PRESENT). The application's own request is tried last, unchanged.
    const std::vector<const SourceInfo*> all_candidates = candidates;
    const auto create_dropping_sources = [&] {
      XrResult r = create_with(candidates);
      while (XR_FAILED(r) && !added.empty()) {
        candidates.pop_back();
        r = create_with(candidates);
      }
      return r;
    };
    XrResult result = create_dropping_sources();
    // An unreadable list sent the spatial-entity extensions down as asked; where the chain refuses them, the
    // layer serves them itself.
    if (XR_FAILED(result) && !offered && spatial.wanted) {
      std::erase_if(extensions, [&](const char* name) { return name != nullptr && served_by_layer(name, false); });
      spatial.planes = enabled(*info, XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME);
      candidates = all_candidates;
      result = create_dropping_sources();
    }
    if (XR_FAILED(result)) return result;
    try {
      added.insert(added.end(), clock.begin(), clock.end());
      spatial.clock = !clock.empty() || enabled(*info, kClock.extension);
      register_instance(*instance, next_gipa, *info, extx, capture, candidates, added, config, spatial);
    } catch (...) {  // the application gets an error, so the instance must not outlive this call
      {
        Registry& r = registry();
        std::lock_guard lock(r.mutex);
        r.instances.erase(*instance);
      }
      PFN_xrDestroyInstance destroy = nullptr;
      load(next_gipa, *instance, "xrDestroyInstance", destroy);
      if (destroy != nullptr) destroy(*instance);
      throw;
    }
    if (skipped > 0) log_info(std::to_string(skipped) + " more copy of the layer skipped");
    return result;
  });
}

// Where the spatial-entity calls the layer does not answer go: a mesh source's hook when it watches the
// application's calls, else the next layer (nothing where the runtime lacks the function's extension).
std::shared_ptr<const SpatialInstance> make_spatial_instance(const InstanceState& state, const SpatialRequest& request) {
  auto spatial = std::make_shared<SpatialInstance>();
  spatial->planes = request.planes;
  const auto below = [&](const char* name) -> PFN_xrVoidFunction {
    for (const EnabledSource& s : state.sources)
      if (s.app_enabled)
        for (const HookEntry& hook : s.info->hooks)
          if (std::strcmp(hook.name, name) == 0) return hook.function;
    PFN_xrVoidFunction f = nullptr;
    return XR_SUCCEEDED(state.next.xrGetInstanceProcAddr(state.handle, name, &f)) ? f : nullptr;
  };
  // Each function on its own: a runtime may have XR_EXT_future (for its mesh extension) without
  // XR_EXT_spatial_entity, and the application's futures of that extension go down through the layer's hook.
#define ROOMSENSE_FORWARD(name) spatial->forward.name = reinterpret_cast<PFN_##name>(below(#name));
  ROOMSENSE_SPATIAL_FUNCTIONS(ROOMSENSE_FORWARD)
#undef ROOMSENSE_FORWARD
  // Only where the extension is enabled: a layer below may hand out a function that has nothing behind it
  // (Debian's core validation does, and calling it crashes).
  PFN_xrVoidFunction convert = nullptr;
  if (request.clock && XR_SUCCEEDED(state.next.xrGetInstanceProcAddr(state.handle, kClock.to_xr_time, &convert)))
    spatial->convert_time = convert;
  return spatial;
}

void register_instance(XrInstance instance, PFN_xrGetInstanceProcAddr next_gipa, const XrInstanceCreateInfo& info,
                       bool extx, bool capture, const std::vector<const SourceInfo*>& sources,
                       const std::vector<std::string>& added, const Config& config, const SpatialRequest& spatial) {
  auto state = std::make_shared<InstanceState>();
  state->handle = instance;
  state->extx = extx;
  state->capture = capture;
  state->config = config;
  state->layer_enabled_extensions = added;
  for (const SourceInfo* source : sources)
    for (const ExtensionFunctions& e : source->extensions)
      if (std::find(added.begin(), added.end(), e.extension) != added.end())
        state->hidden_events.insert(state->hidden_events.end(), e.events.begin(), e.events.end());
  NextDispatch& next = state->next;
  next.xrGetInstanceProcAddr = next_gipa;
#define ROOMSENSE_LOAD(name)                                                                       \
  load(next_gipa, instance, #name, next.name);                                                     \
  if (next.name == nullptr) throw std::runtime_error("the next layer or the runtime has no " #name);
  ROOMSENSE_NEXT_CORE_FUNCTIONS(ROOMSENSE_LOAD)
#undef ROOMSENSE_LOAD
  std::string used;
  for (const SourceInfo* source : sources) {
    try {
      EnabledSource e{source, source->create(next_gipa, instance), true};
      e.source->name = source->name;
      for (const ExtensionFunctions& x : source->extensions) e.app_enabled = e.app_enabled && enabled(info, x.extension);
      state->sources.push_back(std::move(e));
      used += std::string(used.empty() ? "" : ", ") + source->name;
    } catch (const std::exception& e) {
      log_warn(std::string(source->name) + " left out: " + e.what());
    }
  }
  if (spatial.wanted) state->spatial = make_spatial_instance(*state, spatial);
  log_info(std::string("instance created: ") + (extx ? "XR_EXTX_room_understanding enabled" : "extension not enabled") +
           (capture ? ", capturing scene meshes; mesh sources: " + (used.empty() ? std::string("none") : used)
                    : std::string(", pass-through")));
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.instances[instance] = std::move(state);
}

}  // namespace

// ---- xrGetInstanceProcAddr: our hooks, or the next layer's function itself

XrResult XRAPI_CALL xrGetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
  return guarded("xrGetInstanceProcAddr", [&]() -> XrResult {
    if (name == nullptr || function == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state) return XR_ERROR_HANDLE_INVALID;  // the loader asks layers for instance functions only
    const std::string_view wanted(name);
    const auto it = hooks().find(wanted);
    if (it != hooks().end()) {
      const HookGroup g = it->second.group;
      const bool spatial = state->spatial != nullptr;
      const bool ours = g == HookGroup::Always || (g == HookGroup::Extx && state->extx) ||
                        (g == HookGroup::Session && state->capture) || (g == HookGroup::Spaces && state->extx) ||
                        (g == HookGroup::Events && (!state->hidden_events.empty() || spatial)) ||
                        (g == HookGroup::Frame && spatial && state->spatial->convert_time == nullptr);
      if (g == HookGroup::Extx && !state->extx) return XR_ERROR_FUNCTION_UNSUPPORTED;
      if (ours) {
        *function = it->second.function;
        return XR_SUCCESS;
      }
    }
    if (state->spatial)
      if (const PFN_xrVoidFunction f = spatial_hook(wanted); f != nullptr) {
        *function = f;
        return XR_SUCCESS;
      }
    if ((wanted == kClock.to_xr_time || wanted == kClock.from_xr_time) && layer_enabled(*state, kClock.extension))
      return XR_ERROR_FUNCTION_UNSUPPORTED;  // the layer's clock, not enabled by the application
    if (const auto* hook = source_hook(wanted); hook != nullptr && state->capture)
      for (const EnabledSource& s : state->sources)
        if (s.info == hook->first && s.app_enabled) {
          *function = hook->second;
          return XR_SUCCESS;
        }
    // Enabled below us by the layer, not by the application: not the application's to call.
    if (const auto it = source_function_extensions().find(wanted); it != source_function_extensions().end())
      if (layer_enabled(*state, it->second)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    return state->next.xrGetInstanceProcAddr(instance, name, function);
  });
}

// ---- xrPollEvent (when the layer enabled an extension with events of its own, or serves spatial entities)

XrResult XRAPI_CALL xrPollEvent(XrInstance instance, XrEventDataBuffer* eventData) {
  return guarded("xrPollEvent", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state) return XR_ERROR_HANDLE_INVALID;
    if (eventData == nullptr) return state->next.xrPollEvent(instance, eventData);  // the runtime's to reject
    if (state->spatial && has_type(eventData, XR_TYPE_EVENT_DATA_BUFFER) && next_spatial_event(instance, *eventData))
      return XR_SUCCESS;
    const XrEventDataBuffer asked = *eventData;
    // Bounded: a queue of nothing but the layer's events cannot keep the application in here.
    for (int skipped = 0; skipped < 1024; ++skipped) {
      const XrResult result = state->next.xrPollEvent(instance, eventData);
      const auto& hidden = state->hidden_events;
      if (result != XR_SUCCESS || std::find(hidden.begin(), hidden.end(), eventData->type) == hidden.end()) return result;
      eventData->type = asked.type;
      eventData->next = asked.next;
    }
    return XR_EVENT_UNAVAILABLE;
  });
}

XrResult XRAPI_CALL xrDestroyInstance(XrInstance instance) {
  return guarded("xrDestroyInstance", [&]() -> XrResult {
    std::shared_ptr<InstanceState> state;
    std::vector<std::pair<std::shared_ptr<SessionState>, std::vector<std::shared_ptr<Analyzer>>>> sessions;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.instances.find(instance);
      if (it == r.instances.end()) return XR_ERROR_HANDLE_INVALID;
      state = it->second;
      std::vector<std::shared_ptr<SessionState>> mine;
      for (const auto& [handle, s] : r.sessions)
        if (s->instance == state) mine.push_back(s);
      for (const auto& s : mine) sessions.emplace_back(s, forget_session_locked(r, s->handle));
      r.instances.erase(it);
    }
    // Its sessions go with it: stop their analyses first (they call into the runtime).
    for (auto& [session, analyzers] : sessions) shut_down_session(*session, analyzers);
    log_info("instance destroyed");
    return state->next.xrDestroyInstance(instance);
  });
}

// ---- xrWaitFrame (only when the layer serves spatial entities and the runtime has no clock to ask)

XrResult XRAPI_CALL xrWaitFrame(XrSession session, const XrFrameWaitInfo* frameWaitInfo, XrFrameState* frameState) {
  return guarded("xrWaitFrame", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = s->instance->next.xrWaitFrame(session, frameWaitInfo, frameState);
    if (XR_SUCCEEDED(result) && frameState != nullptr) s->frame_time.store(frameState->predictedDisplayTime);
    return result;
  });
}

// ---- sessions (when the layer captures)

XrResult XRAPI_CALL xrCreateSession(XrInstance instance, const XrSessionCreateInfo* createInfo, XrSession* session) {
  return guarded("xrCreateSession", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = state->next.xrCreateSession(instance, createInfo, session);
    if (XR_SUCCEEDED(result)) {
      auto s = std::make_shared<SessionState>();
      s->handle = *session;
      s->instance = state;
      s->system = createInfo->systemId;
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      r.sessions[*session] = std::move(s);
    }
    return result;
  });
}

XrResult XRAPI_CALL xrDestroySession(XrSession session) {
  return guarded("xrDestroySession", [&]() -> XrResult {
    std::shared_ptr<SessionState> state;
    std::vector<std::shared_ptr<Analyzer>> analyzers;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.sessions.find(session);
      if (it == r.sessions.end()) return XR_ERROR_HANDLE_INVALID;
      state = it->second;
      analyzers = forget_session_locked(r, session);
    }
    // Analyses of this session stop (and are waited for) before the session goes away below us.
    shut_down_session(*state, analyzers);
    return state->instance->next.xrDestroySession(session);
  });
}

// ---- reference spaces (when the application enabled the extension)

XrResult XRAPI_CALL xrCreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* createInfo, XrSpace* space) {
  return guarded("xrCreateReferenceSpace", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = s->instance->next.xrCreateReferenceSpace(session, createInfo, space);
    if (XR_SUCCEEDED(result)) {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      // Spaces are not tracked to their destruction (xrDestroySpace stays the runtime's): the oldest are
      // forgotten, so an application creating spaces all the time cannot grow this without bound.
      r.spaces[*space] = {session, createInfo->referenceSpaceType, createInfo->poseInReferenceSpace};
      r.space_order.push_back(*space);
      while (r.space_order.size() > kMaxTrackedSpaces) {
        r.spaces.erase(r.space_order.front());
        r.space_order.pop_front();
      }
    }
    return result;
  });
}

}  // namespace roomsense::layer

extern "C" ROOMSENSE_PLUGIN_EXPORT XrResult XRAPI_CALL
xrNegotiateLoaderApiLayerInterface(const XrNegotiateLoaderInfo* loaderInfo, const char* layerName,
                                   XrNegotiateApiLayerRequest* apiLayerRequest) {
  using namespace roomsense::layer;
  if (loaderInfo == nullptr || apiLayerRequest == nullptr) return XR_ERROR_INITIALIZATION_FAILED;
  if (loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != XR_LOADER_INFO_STRUCT_VERSION || loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo))
    return XR_ERROR_INITIALIZATION_FAILED;
  if (apiLayerRequest->structType != XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST ||
      apiLayerRequest->structVersion != XR_API_LAYER_INFO_STRUCT_VERSION ||
      apiLayerRequest->structSize != sizeof(XrNegotiateApiLayerRequest))
    return XR_ERROR_INITIALIZATION_FAILED;
  if (layerName == nullptr || std::strcmp(layerName, kLayerName) != 0) return XR_ERROR_INITIALIZATION_FAILED;
  constexpr uint32_t kInterface = XR_CURRENT_LOADER_API_LAYER_VERSION;
  if (loaderInfo->minInterfaceVersion > kInterface || loaderInfo->maxInterfaceVersion < kInterface)
    return XR_ERROR_INITIALIZATION_FAILED;
  if (XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1 || XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1)
    return XR_ERROR_INITIALIZATION_FAILED;
  apiLayerRequest->layerInterfaceVersion = kInterface;
  apiLayerRequest->layerApiVersion = XR_MAKE_VERSION(1, 0, XR_VERSION_PATCH(XR_CURRENT_API_VERSION));
  apiLayerRequest->getInstanceProcAddr = &roomsense::layer::xrGetInstanceProcAddr;
  apiLayerRequest->createApiLayerInstance = &roomsense::layer::xrCreateApiLayerInstance;
  return XR_SUCCESS;
}
