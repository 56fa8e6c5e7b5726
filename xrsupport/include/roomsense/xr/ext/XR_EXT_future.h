/* roomsense: declarations for XR_EXT_future (futures returned by *Async calls,
 * polled with xrPollFutureEXT). Used only when the system <openxr/openxr.h>
 * is older than the extension; a header that has it wins. */
#ifndef ROOMSENSE_XR_EXT_XR_EXT_FUTURE_H
#define ROOMSENSE_XR_EXT_XR_EXT_FUTURE_H

#include <openxr/openxr.h>

#include "base_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef XR_EXT_future
#define XR_EXT_future 1
#define XR_EXT_future_SPEC_VERSION 1
#define XR_EXT_FUTURE_EXTENSION_NAME "XR_EXT_future"
#define XR_NULL_FUTURE_EXT 0

XR_DEFINE_OPAQUE_64(XrFutureEXT)

/* Values this extension adds to core enums. */
#define XR_ERROR_FUTURE_PENDING_EXT ((XrResult)-1000469001)
#define XR_ERROR_FUTURE_INVALID_EXT ((XrResult)-1000469002)

#define XR_TYPE_FUTURE_CANCEL_INFO_EXT ((XrStructureType)1000469000)
#define XR_TYPE_FUTURE_POLL_INFO_EXT ((XrStructureType)1000469001)
#define XR_TYPE_FUTURE_COMPLETION_EXT ((XrStructureType)1000469002)
#define XR_TYPE_FUTURE_POLL_RESULT_EXT ((XrStructureType)1000469003)

typedef enum XrFutureStateEXT {
    XR_FUTURE_STATE_PENDING_EXT = 1,
    XR_FUTURE_STATE_READY_EXT = 2,
    XR_FUTURE_STATE_MAX_ENUM_EXT = 0x7FFFFFFF
} XrFutureStateEXT;

typedef struct XrFutureCancelInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrFutureEXT future;
} XrFutureCancelInfoEXT;

typedef struct XrFuturePollInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrFutureEXT future;
} XrFuturePollInfoEXT;

/* Common head of every *Completion* struct filled by a *Complete* call. */
typedef struct XR_MAY_ALIAS XrFutureCompletionBaseHeaderEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
} XrFutureCompletionBaseHeaderEXT;

/* Completion for operations that return nothing but a result. */
typedef struct XrFutureCompletionEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
} XrFutureCompletionEXT;

typedef struct XrFuturePollResultEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrFutureStateEXT state;
} XrFuturePollResultEXT;

typedef XrResult(XRAPI_PTR* PFN_xrPollFutureEXT)(XrInstance instance, const XrFuturePollInfoEXT* pollInfo,
                                                 XrFuturePollResultEXT* pollResult);
typedef XrResult(XRAPI_PTR* PFN_xrCancelFutureEXT)(XrInstance instance, const XrFutureCancelInfoEXT* cancelInfo);

#endif /* XR_EXT_future */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_EXT_FUTURE_H */
