// Every core and XR_EXTX_room_understanding function the layer touches, one line each, so the hooks read as
// lists (xrGetInstanceProcAddr in entry.cpp is generated from them). The mesh sources (sources/) list their
// own extensions' functions. What is not listed here goes straight to the next layer or the
// runtime: xrGetInstanceProcAddr hands out the next function itself, so the frame loop (xrWaitFrame,
// xrBeginFrame, xrEndFrame), xrLocateSpace and everything else pay nothing for the layer.
#pragma once
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <type_traits>

// Core functions the layer calls on the next layer (or the runtime).
#define ROOMSENSE_NEXT_CORE_FUNCTIONS(_)                                                                    \
  _(xrDestroyInstance) _(xrCreateSession) _(xrDestroySession) _(xrCreateReferenceSpace) _(xrDestroySpace) _(xrLocateSpace) \
  _(xrPollEvent) _(xrWaitFrame)

// Hooked on every instance.
#define ROOMSENSE_HOOKS_ALWAYS(_) _(xrGetInstanceProcAddr) _(xrDestroyInstance)

// Hooked when the layer captures (the extension is enabled, or ROOMSENSE_EXPORT_DIR is set): session state.
#define ROOMSENSE_HOOKS_SESSION(_) _(xrCreateSession) _(xrDestroySession)

// Hooked when the application enabled the extension: reference spaces, so that an analyzer's baseSpace can
// be checked (LOCAL or STAGE) and copied (the analyzer keeps its own space of the same kind and pose).
#define ROOMSENSE_HOOKS_SPACES(_) _(xrCreateReferenceSpace)

// Hooked when the layer enabled an extension with events the application did not ask for (the mesh sources'
// ExtensionFunctions::events): those events are the layer's, and are taken out of the application's queue.
// Also when it serves the spatial-entity API: its discovery-recommended events join the queue.
#define ROOMSENSE_HOOKS_EVENTS(_) _(xrPollEvent)

// Hooked when the layer serves the spatial-entity API on a runtime without XR_KHR_convert_timespec_time: the
// frame time is then the only clock the layer's own analyses can locate the runtime's meshes with.
#define ROOMSENSE_HOOKS_FRAME(_) _(xrWaitFrame)

// XR_EXTX_room_understanding: all of them the layer's own.
#define ROOMSENSE_EXTX_FUNCTIONS(_)                                                                     \
  _(xrCreateRoomAnalyzerEXTX) _(xrDestroyRoomAnalyzerEXTX) _(xrSubmitRoomMeshEXTX) _(xrComputeRoomEXTX) \
  _(xrGetRoomComputeStateEXTX) _(xrGetRoomLayoutEXTX) _(xrGetRoomAreasEXTX) _(xrGetRoomBoundsMeshEXTX)    \
  _(xrFindRoomPlacementsEXTX) _(xrRaycastRoomEXTX) _(xrGetRoomRandomPointEXTX) _(xrLocateRoomPointEXTX)

namespace roomsense::layer {

// The layer's implementations, each with exactly its PFN's signature (namespaced: nothing is exported).
#define ROOMSENSE_DECLARE(name) extern std::remove_pointer_t<PFN_##name> name;
ROOMSENSE_HOOKS_ALWAYS(ROOMSENSE_DECLARE)
ROOMSENSE_HOOKS_SESSION(ROOMSENSE_DECLARE)
ROOMSENSE_HOOKS_SPACES(ROOMSENSE_DECLARE)
ROOMSENSE_HOOKS_EVENTS(ROOMSENSE_DECLARE)
ROOMSENSE_HOOKS_FRAME(ROOMSENSE_DECLARE)
ROOMSENSE_EXTX_FUNCTIONS(ROOMSENSE_DECLARE)
#undef ROOMSENSE_DECLARE

// What the layer calls next, per instance (filled from the next xrGetInstanceProcAddr at xrCreateInstance).
struct NextDispatch {
  PFN_xrGetInstanceProcAddr xrGetInstanceProcAddr = nullptr;
#define ROOMSENSE_MEMBER(name) PFN_##name name = nullptr;
  ROOMSENSE_NEXT_CORE_FUNCTIONS(ROOMSENSE_MEMBER)
#undef ROOMSENSE_MEMBER
};

}  // namespace roomsense::layer
