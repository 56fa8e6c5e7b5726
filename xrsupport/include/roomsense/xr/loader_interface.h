// The loader negotiation structures of the OpenXR loader specification, interface version 1: loader <-> API
// layer ("API Layer Interface Negotiation", xrCreateApiLayerInstance) and loader <-> runtime. Debian's OpenXR
// 1.0.20 ships no loader-interface header, so they are declared here from the specification; newer SDKs ship
// <openxr/openxr_loader_negotiation.h> with the same layout, and that header wins when it exists.
#pragma once
#include <openxr/openxr.h>

#if __has_include(<openxr/openxr_loader_negotiation.h>)
#include <openxr/openxr_loader_negotiation.h>
#elif !defined(XR_API_LAYER_INFO_STRUCT_VERSION)
#include <cstddef>
#include <cstdint>

extern "C" {

typedef enum XrLoaderInterfaceStructs {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO,
  XR_LOADER_INTERFACE_STRUCTS_MAX_ENUM = 0x7FFFFFFF
} XrLoaderInterfaceStructs;

#define XR_CURRENT_LOADER_API_LAYER_VERSION 1

#define XR_LOADER_INFO_STRUCT_VERSION 1
typedef struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_LOADER_INFO
  uint32_t structVersion;               // XR_LOADER_INFO_STRUCT_VERSION
  size_t structSize;                    // sizeof(XrNegotiateLoaderInfo)
  uint32_t minInterfaceVersion;
  uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
} XrNegotiateLoaderInfo;

typedef struct XrApiLayerCreateInfo XrApiLayerCreateInfo;
typedef XrResult(XRAPI_PTR* PFN_xrCreateApiLayerInstance)(const XrInstanceCreateInfo* info,
                                                           const XrApiLayerCreateInfo* apiLayerInfo, XrInstance* instance);

#define XR_API_LAYER_INFO_STRUCT_VERSION 1
typedef struct XrNegotiateApiLayerRequest {
  XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST
  uint32_t structVersion;               // XR_API_LAYER_INFO_STRUCT_VERSION
  size_t structSize;                    // sizeof(XrNegotiateApiLayerRequest)
  uint32_t layerInterfaceVersion;       // written by the layer
  XrVersion layerApiVersion;            // written by the layer
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;         // written by the layer
  PFN_xrCreateApiLayerInstance createApiLayerInstance;  // written by the layer
} XrNegotiateApiLayerRequest;

// One per layer in the chain, in order from the application down. The entry addressed to layer L (layerName)
// holds the functions L calls next: those of the layer below it, or the loader's terminators.
#define XR_API_LAYER_NEXT_INFO_STRUCT_VERSION 1
typedef struct XrApiLayerNextInfo {
  XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO
  uint32_t structVersion;               // XR_API_LAYER_NEXT_INFO_STRUCT_VERSION
  size_t structSize;                    // sizeof(XrApiLayerNextInfo)
  char layerName[XR_MAX_API_LAYER_NAME_SIZE];
  PFN_xrGetInstanceProcAddr nextGetInstanceProcAddr;
  PFN_xrCreateApiLayerInstance nextCreateApiLayerInstance;
  struct XrApiLayerNextInfo* next;
} XrApiLayerNextInfo;

#define XR_API_LAYER_MAX_SETTINGS_PATH_SIZE 512
#define XR_API_LAYER_CREATE_INFO_STRUCT_VERSION 1
struct XrApiLayerCreateInfo {
  XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO
  uint32_t structVersion;               // XR_API_LAYER_CREATE_INFO_STRUCT_VERSION
  size_t structSize;                    // sizeof(XrApiLayerCreateInfo)
  void* loaderInstance;                 // unused by the loader
  char settings_file_location[XR_API_LAYER_MAX_SETTINGS_PATH_SIZE];
  XrApiLayerNextInfo* nextInfo;  // the entry addressed to the layer being called
};

typedef XrResult(XRAPI_PTR* PFN_xrNegotiateLoaderApiLayerInterface)(const XrNegotiateLoaderInfo* loaderInfo,
                                                                     const char* layerName,
                                                                     XrNegotiateApiLayerRequest* apiLayerRequest);

#define XR_RUNTIME_INFO_STRUCT_VERSION 1
typedef struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST
  uint32_t structVersion;               // XR_RUNTIME_INFO_STRUCT_VERSION
  size_t structSize;                    // sizeof(XrNegotiateRuntimeRequest)
  uint32_t runtimeInterfaceVersion;     // written by the runtime
  XrVersion runtimeApiVersion;          // written by the runtime
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;  // written by the runtime
} XrNegotiateRuntimeRequest;

#define XR_CURRENT_LOADER_RUNTIME_VERSION 1

}  // extern "C"
#endif
