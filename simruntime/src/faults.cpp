// ROOMSENSE_SIM_FAULTS: parsing and the decisions (faults.h; the grammar is in ../README.md, "Faults").
#include "faults.h"
#include "process_state.h"

#include "extensions/served_extension.h"
#include "functions.h"
#include "runtime.h"

#include <openxr/openxr_reflection.h>

#include <atomic>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace roomsense::sim::faults {
namespace {

constexpr const char* kGrammar =
    "error:FUNCTION=XR_RESULT, pending[:EXTENSION], mesh[:EXTENSION]=nan|empty|huge|ragged|range, lost[:FUNCTION][=N]";

// Called before any instance exists, so no plan can be meant for them.
const std::set<std::string_view> kBeforeInstance = {"xrGetInstanceProcAddr", "xrEnumerateApiLayerProperties",
                                                    "xrEnumerateInstanceExtensionProperties", "xrCreateInstance"};

// Functions that take no session and no child of one (and every xrDestroy*): a lost session leaves them working.
const std::set<std::string_view> kSessionless = {
    "xrGetInstanceProcAddr", "xrEnumerateApiLayerProperties", "xrEnumerateInstanceExtensionProperties",
    "xrCreateInstance", "xrGetInstanceProperties", "xrPollEvent", "xrResultToString", "xrStructureTypeToString",
    "xrGetSystem", "xrGetSystemProperties", "xrEnumerateEnvironmentBlendModes", "xrEnumerateViewConfigurations",
    "xrGetViewConfigurationProperties", "xrEnumerateViewConfigurationViews", "xrStringToPath", "xrPathToString",
    "xrConvertTimespecTimeToTimeKHR", "xrConvertTimeToTimespecTimeKHR", "xrPollFutureEXT", "xrCancelFutureEXT",
    "xrEnumerateSceneComputeFeaturesMSFT", "xrEnumerateSupportedSemanticLabelSetsANDROID",
    "xrEnumerateSpatialCapabilitiesEXT", "xrEnumerateSpatialCapabilityComponentTypesEXT",
    "xrEnumerateSpatialCapabilityFeaturesEXT", "xrFreeWorldMeshBufferML"};

bool sessionless(std::string_view function) { return function.starts_with("xrDestroy") || kSessionless.count(function) != 0; }

// Every function the runtime exports, and which of them belong to a scene extension.
struct Functions {
  std::set<std::string, std::less<>> all, scene;
};

const Functions& functions() {
  static const Functions f = [] {
    Functions out;
#define SIM_NAME(name) out.all.insert(#name);
    SIM_CORE_FUNCTIONS(SIM_NAME)
    SIM_UNSUPPORTED_CORE_FUNCTIONS(SIM_NAME)
#undef SIM_NAME
    for (const ServedExtension* e : served_extensions())
      for (const ServedFunction& fn : e->functions) {
        out.all.insert(fn.name);
        if (e->scene) out.scene.insert(fn.name);
      }
    return out;
  }();
  return f;
}

std::optional<XrResult> result_named(std::string_view name) {
#define SIM_RESULT(n, v) \
  if (name == #n) return n;
  XR_LIST_ENUM_XrResult(SIM_RESULT)
#undef SIM_RESULT
  return std::nullopt;
}

// A value as one short line of the message: control characters as '?', at most 64 characters.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 64;
  std::string out(text.substr(0, kMax));
  if (text.size() > kMax) out += "...";
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

[[noreturn]] void bad(std::string_view item, const std::string& why) {
  throw std::invalid_argument("ROOMSENSE_SIM_FAULTS: '" + shown(item) + "' " + why);
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

Fault parse_one(std::string_view item) {
  const std::size_t eq = item.find('=');
  const std::string_view head = item.substr(0, eq);
  const std::optional<std::string_view> value = eq == std::string_view::npos ? std::nullopt : std::optional(item.substr(eq + 1));
  const std::size_t colon = head.find(':');
  const std::string_view kind = head.substr(0, colon);
  const std::string_view target = colon == std::string_view::npos ? std::string_view() : head.substr(colon + 1);
  if (colon != std::string_view::npos && target.empty()) bad(item, "has an empty target");
  if (value && value->empty()) bad(item, "has an empty value");

  Fault f;
  f.target = std::string(target);
  const auto function_target = [&](bool required) {
    if (target.empty()) {
      if (required) bad(item, "needs a function: error:FUNCTION=XR_RESULT");
      return;
    }
    if (functions().all.count(target) == 0) bad(item, "names no function this runtime exports");
    if (kBeforeInstance.count(target) != 0) bad(item, "names a function called before the instance exists");
  };
  const auto extension_target = [&] {
    if (target.empty()) return;
    const auto& names = fault_extensions();
    if (std::find(names.begin(), names.end(), target) == names.end())
      bad(item, "names no scene extension this runtime serves (XR_MSFT_scene_understanding, ...)");
  };
  if (kind == "error") {
    f.kind = Fault::Kind::Error;
    function_target(true);
    if (!value) bad(item, "needs a result: error:FUNCTION=XR_RESULT");
    const auto r = result_named(*value);
    if (!r || *r == XR_SUCCESS) bad(item, "needs an XrResult name other than XR_SUCCESS after '='");
    f.result = *r;
  } else if (kind == "pending") {
    f.kind = Fault::Kind::Pending;
    extension_target();
    if (value) bad(item, "takes no value");
  } else if (kind == "mesh") {
    f.kind = Fault::Kind::Mesh;
    extension_target();
    if (!value) bad(item, "needs a value: nan, empty, huge, ragged or range");
    if (*value == "nan") f.mesh = MeshFault::Nan;
    else if (*value == "empty") f.mesh = MeshFault::Empty;
    else if (*value == "huge") f.mesh = MeshFault::Huge;
    else if (*value == "ragged") f.mesh = MeshFault::Ragged;
    else if (*value == "range") f.mesh = MeshFault::Range;
    else bad(item, "needs a value: nan, empty, huge, ragged or range");
  } else if (kind == "lost") {
    f.kind = Fault::Kind::Lost;
    function_target(false);
    if (!target.empty() && sessionless(target)) bad(item, "names a function that takes no session");
    if (value) {
      std::uint32_t n = 0;
      for (char c : *value) {
        if (c < '0' || c > '9' || n > 100000) bad(item, "needs a call number from 1 to 1000000 after '='");
        n = n * 10 + static_cast<std::uint32_t>(c - '0');
      }
      if (n < 1 || n > 1000000) bad(item, "needs a call number from 1 to 1000000 after '='");
      f.call = n;
    }
  } else {
    bad(item, std::string("is not a fault (") + kGrammar + ")");
  }
  return f;
}

// The installed plan, the calls counted for lost faults, and whether the session is lost.
struct Active {
  std::mutex mutex;
  std::shared_ptr<const Plan> plan;
  std::unordered_map<std::string, std::uint32_t> calls;
  bool lost = false;
};

Active& active() {
  return process_wide<Active>();
}

std::atomic<bool> g_installed{false};  // a plan with faults: the fast path of every call when false

std::shared_ptr<const Plan> current() {
  if (!g_installed.load(std::memory_order_acquire)) return nullptr;
  Active& a = active();
  std::lock_guard lock(a.mutex);
  return a.plan;
}

bool applies(const Fault& f, std::string_view extension) { return f.target.empty() || f.target == extension; }

void lose_every_session() {
  std::lock_guard lock(runtime().mutex);
  for (auto& [id, session] : runtime().sessions) runtime().push_state(*session, id, XR_SESSION_STATE_LOSS_PENDING);
}

}  // namespace

const std::vector<std::string_view>& fault_extensions() {
  static const std::vector<std::string_view> names = {
      XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME, "XR_META_spatial_entity_mesh", "XR_ANDROID_scene_meshing",
      "XR_ML_world_mesh_detection", "XR_EXT_spatial_plane_tracking"};
  return names;
}

Plan parse(std::string_view spec) {
  Plan plan;
  if (trimmed(spec).empty()) return plan;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = spec.find(',', start);
    const std::string_view item = trimmed(spec.substr(start, comma == std::string_view::npos ? spec.npos : comma - start));
    if (item.empty()) throw std::invalid_argument("ROOMSENSE_SIM_FAULTS: an empty fault in '" + shown(spec) + "'");
    plan.faults.push_back(parse_one(item));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return plan;
}

void install(std::shared_ptr<const Plan> plan) {
  Active& a = active();
  std::lock_guard lock(a.mutex);
  const bool any = plan && !plan->faults.empty();
  a.plan = any ? std::move(plan) : nullptr;
  a.calls.clear();
  a.lost = false;
  g_installed.store(any, std::memory_order_release);
}

XrResult on_call(const char* function) noexcept {
  if (!g_installed.load(std::memory_order_acquire)) return XR_SUCCESS;
  try {
    const std::string_view name(function);
    bool lose = false;
    {
      Active& a = active();
      std::lock_guard lock(a.mutex);
      if (!a.plan) return XR_SUCCESS;
      if (a.lost) return sessionless(name) ? XR_SUCCESS : XR_ERROR_SESSION_LOST;
      for (const Fault& f : a.plan->faults) {
        if (f.kind == Fault::Kind::Error && f.target == name) return f.result;
        if (f.kind == Fault::Kind::Lost && !sessionless(name) &&
            (f.target == name || (f.target.empty() && functions().scene.count(name) != 0)) &&
            ++a.calls[f.target] == f.call)
          lose = a.lost = true;
      }
    }
    if (!lose) return XR_SUCCESS;
    lose_every_session();
    return XR_ERROR_SESSION_LOST;
  } catch (...) {
    return XR_ERROR_RUNTIME_FAILURE;
  }
}

bool pending(std::string_view extension) {
  const auto plan = current();
  if (!plan) return false;
  for (const Fault& f : plan->faults)
    if (f.kind == Fault::Kind::Pending && applies(f, extension)) return true;
  return false;
}

MeshFault mesh_fault(std::string_view extension) {
  const auto plan = current();
  if (!plan) return MeshFault::None;
  for (const Fault& f : plan->faults)
    if (f.kind == Fault::Kind::Mesh && applies(f, extension)) return f.mesh;
  return MeshFault::None;
}

std::uint32_t vertex_count(std::string_view extension, std::size_t real, std::uint32_t capacity) {
  if (mesh_fault(extension) == MeshFault::Huge && (capacity == 0 || capacity < real)) return kHugeCount;
  return static_cast<std::uint32_t>(real);
}

}  // namespace roomsense::sim::faults
