// The seam between the layer and the runtime's scene extensions. One MeshSource per extension (group), one
// file pair each under sources/, and one line in source_list.cpp: that is all a new extension takes.
// A source says which runtime extensions it needs (the layer enables them below itself), which of the
// application's calls it watches (passive capture), and runs an active query of its own on an analyzer's
// worker thread. What it delivers is chunks with a stable id, a change marker and the runtime's labels.
#pragma once
#include "served_chunks.h"

#include <openxr/openxr.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <vector>

namespace roomsense::layer {

// What an active query is asked: everything the runtime has now, located in `base` at `time`.
struct QueryContext {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace base = XR_NULL_HANDLE;
  XrTime time = 0;
};

// A source's per-instance state: the next layer's functions it calls, loaded at xrCreateInstance.
class MeshSource {
 public:
  virtual ~MeshSource() = default;
  // Active capture (source_support.cpp): the source's run_query, then what every source shares. Throws
  // std::runtime_error with one readable line when the runtime does not deliver (an error, a future or compute
  // that never completes, nothing usable); returns what it has when `stop` is requested. The runtime's broken
  // triangles (non-finite vertices, indices out of range, a ragged index count) and empty chunks are dropped
  // with one log line. Once a call of the session came back XR_ERROR_SESSION_LOST, it returns nothing without
  // calling the runtime (the loss was logged once already).
  // A chunk served at the source's last query whose change marker and placement are the same is the same chunk
  // (served_chunks.h): it is not read, checked or keyed again.
  struct Answer {
    std::vector<ServedChunk> chunks;
    std::size_t read = 0;  // of them, those read from the runtime (the others were served before as they are)
  };
  Answer query(const QueryContext& context, std::stop_token stop);
  // The session is going away: forget the chunks served to it and the records of its handles (passive capture).
  // Called without locks.
  void end_session(XrSession session) {
    served_.forget(session);
    forget_session(session);
  }

  const char* name = "a mesh source";  // its SourceInfo's, set when it is created

 protected:
  // The source's own query, as query() describes it, before the shared checks.
  virtual std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) = 0;
  // end_session's: forget the records of the session's handles (passive capture).
  virtual void forget_session(XrSession session) { (void)session; }
  // For run_query: the chunk to list for `id` when the last query served it with this change marker and placement
  // (its same_as set), so that the source skips reading it; nullopt when it must be read.
  std::optional<SourceChunk> served_before(const QueryContext& context, const std::string& id, std::uint64_t change,
                                           const XrPosef& placed) const;

 private:
  ServedChunks served_;
};

struct HookEntry {
  const char* name;
  PFN_xrVoidFunction function;
};

// A runtime extension a source needs, with every function of it: those are not the application's to call when
// only the layer enabled the extension.
struct ExtensionFunctions {
  const char* extension;
  std::vector<const char*> functions;
  // Its event structures: when only the layer enabled the extension, xrPollEvent keeps them from the
  // application (they answer the layer's own requests and are types the application never asked for).
  std::vector<XrStructureType> events = {};
};

struct SourceInfo {
  const char* name;   // its main extension, as logged and written in analysis.json
  const char* gives;  // what it delivers, one phrase for the log
  std::vector<ExtensionFunctions> extensions;  // all needed from the runtime; the layer enables them below itself
  std::vector<HookEntry> hooks;  // the application's calls watched (passive capture) when it enabled all of them
  // Loads the functions the source calls; throws std::runtime_error when the next layer lacks one.
  std::unique_ptr<MeshSource> (*create)(PFN_xrGetInstanceProcAddr next, XrInstance instance) = nullptr;
};

// Every source, best first: full meshes before planes (a plane outline is coarser than a mesh).
const std::vector<const SourceInfo*>& mesh_sources();

// Loads one function from the next layer; throws std::runtime_error naming it when it is missing.
template <typename PFN>
void load_next(PFN_xrGetInstanceProcAddr next, XrInstance instance, const char* name, PFN& out) {
  PFN_xrVoidFunction f = nullptr;
  if (XR_FAILED(next(instance, name, &f)) || f == nullptr)
    throw std::runtime_error(std::string("the next layer or the runtime has no ") + name);
  out = reinterpret_cast<PFN>(f);
}

}  // namespace roomsense::layer
