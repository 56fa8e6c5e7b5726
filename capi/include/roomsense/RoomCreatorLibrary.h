/* RoomCreatorLibrary.h: the thesis-compatible C API of roomsense (thesis §3.8), for engines that pass a
 * flattened vertex array: Unity through DllImport("RoomCreatorLibrary"), Unreal, or plain C.
 *
 * Six functions in two independent pairs of jobs, room understanding (placement areas) and room bounds (a
 * closed, simplified room mesh), and one addition, RetrieveRoomUnderstandingPlaces. Each job runs on a worker thread of the library; the caller polls:
 *
 *     int code = StartRoomUnderstanding(xyz, 3 * vertex_count);       // 0: started
 *     float* areas; int size;
 *     do { areas = RetrieveRoomUnderstanding(&code, &size); } while (code == -1);  // poll, e.g. per frame
 *     if (code == 0)
 *       for (int i = 0; i < size; i += 11) { ... areas[i] ... areas[i + 10] ... }
 *     CleanUpRoomUnderstanding();                                      // frees `areas`
 *
 * Differences from the thesis's header, all ABI-compatible with its Unity binding (thesis §3.8.1):
 * - Pointers where the thesis takes C++ references, so that C and C# can call the functions. A C++
 *   reference is passed as a pointer anyway.
 * - `int*` for the output sizes where the thesis's C++ header says `size_t&`. The thesis's published Unity
 *   binding declares them `ref int`: C# passes a pointer to a 4-byte int, and a library that writes a
 *   8-byte size_t through it overwrites 4 bytes of the caller's stack. We declare what the engine scripts
 *   actually pass. The sizes fit an int (see the limits below).
 * - The functions are extern "C" (unmangled, as DllImport and GetProcAddress need them); C++ callers also
 *   find them in namespace RoomCreator, as in the thesis.
 * No function throws or aborts on bad input; a null output pointer is skipped.
 *
 * Start*(VertexPositions, ArraySize): x1,y1,z1,x2,... (thesis Eq. 3.1), ArraySize floats; a point cloud.
 *   The array is copied before the call returns; the caller may free or reuse it at once.
 *   Returns 0: started. 1: VertexPositions is NULL or ArraySize < 1. 2: ArraySize is not a multiple of 3.
 *   4: this job is busy. A job is busy from a successful Start until its CleanUp, finished or not, so that
 *   the array returned by Retrieve stays valid until CleanUp and a new Start never frees it behind the
 *   caller's back. Input checks come first: bad input returns 1 or 2 even while the job is busy.
 *   NaN and Inf vertices are skipped and far outliers rejected; neither is an error.
 *   An internal failure while starting (out of memory, no thread) is reported by Retrieve as code 1.
 *   The two jobs are independent and may run at the same time.
 *
 * Retrieve*(OutErrorCode, ...): never blocks. *OutErrorCode is
 *   -1: still running (sizes 0, returns NULL);
 *    0: ready; returns the array, which the library owns until the job's CleanUp. It is never NULL, even
 *       when it holds no elements (C#'s Marshal.Copy rejects IntPtr.Zero);
 *    1: finished without a result: no floor and ceiling at least 1.5 m apart, every vertex invalid, an
 *       internal error; also when no job was started since the last CleanUp. Returns NULL, sizes 0.
 *   Retrieve may be called any number of times; it returns the same array each time.
 *
 * CleanUp*(): frees the job's array and makes the job idle; returns 0. Called while the job runs, it
 *   stops the worker (within about 100 ms) and discards its result. Calling
 *   it with no job is harmless. Without it the array stays allocated and Start keeps returning 4.
 *   A process may exit without it, a job running or not. A program that unloads the library while it stays
 *   (dlclose, FreeLibrary) calls both CleanUps first: on Windows a job's thread left behind outlives the code.
 *
 * RetrieveRoomUnderstanding: *OutArraySize floats, 11 per area (a multiple of 11), in the thesis's order:
 *   [0..2]  centre x, y, z
 *   [3..5]  unit surface normal x, y, z, pointing into free space (walls: into the room)
 *   [6]     area height: centre to the upper edge, metres (half the height)
 *   [7]     area width: centre to the right edge, metres (half the width)
 *   [8]     rotation about the normal, degrees; 0 for walls, in [0, 90) for squares (see "Frame")
 *   [9]     volume height: clear space checked in front of the surface, along the normal, metres
 *   [10]    category flags of thesis Eq. 3.58 as a float; (int)f gives the bits, exactly one per group:
 *           size 1 large, 2 medium, 4 small; interaction 8 close, 16 distance, 32 none;
 *           type 64 wall, 128 floor, 256 furniture, 512 ceiling.
 *   Areas come as walls, floors, ceilings, furniture; large before medium before small.
 *
 * RetrieveRoomUnderstandingPlaces(OutErrorCode, OutArraySize): beyond the thesis, where each area lies: 2 floats
 *   per area, in the order of RetrieveRoomUnderstanding's array (OutArraySize is 2/11 of its size): the storey
 *   (0 the main storey, then the others) and the room (its index among the rooms of the whole scan, storey by
 *   storey, each storey's largest first; -1: none), as floats; (int)f gives the number. The same codes,
 *   lifetime and job as RetrieveRoomUnderstanding: valid until CleanUpRoomUnderstanding. A room is a storey's
 *   free space up to passages at most 1.2 m wide between walls (a doorway, a narrow corridor).
 *
 * RetrieveRoomBounds: one array of *OutVertexSize + *OutTriangleSize floats: first the vertices, x,y,z
 *   each (*OutVertexSize is a multiple of 3, no vertex twice), then the triangles, three vertex indices
 *   each, stored as floats (*OutTriangleSize is a multiple of 3; (int)f is the index). Sizes are element
 *   counts of each part, as in the thesis. The mesh is the surface of the room's solid bounds volume
 *   (thesis §3.6: walls, floor, ceiling and what stands in the room, a shell), closed: each edge is
 *   shared by exactly two triangles, and every face's front is towards free space (inside the room,
 *   towards the room). A mesh of 2^24 or more vertices, whose indices a float cannot hold exactly, is
 *   reported as code 1 (the bounds mesh of a room has a few hundred).
 *
 * Frame. The thesis plugin takes and returns Unity's frame (left-handed, +Y up, metres); so does this
 *   library. Coordinates pass through unchanged: the library computes in a right-handed frame, and reading
 *   Unity's numbers as right-handed coordinates mirrors the room. A mirror keeps distances and angles, so
 *   levels, centres, sizes and normals (into free space) come out right in Unity's frame as they are.
 *   Triangles: ours are counter-clockwise seen from the front in a right-handed frame; the same index
 *   order read in the left-handed frame is clockwise seen from the front, Unity's convention (thesis
 *   §3.8).
 *   Rotation: the number is the right-handed rotation about the normal in the computing frame, i.e.
 *   rotating the unit X axis by it about the normal with the usual quaternion formula gives the area's
 *   width axis, from its left edge to its right. Unity's Quaternion.AngleAxis(angle, axis) uses that
 *   same formula on the same numbers, so Quaternion.AngleAxis(f[8], normal) * Vector3.right is the width
 *   axis in Unity too. The visual sense flips with the frame (counter-clockwise about the
 *   normal in the computing frame, clockwise in Unity's, which is what a positive angle means in a
 *   left-handed frame), just as the winding does, so the number itself stays. For ceilings (normal -Y)
 *   that is the thesis's "negative rotation" of Eq. 3.57 about the world's up.
 *   Units: metres in, metres out. Convert other units before the call (Unreal: centimetres, Z up,
 *   thesis Eq. 3.2).
 *
 * Threads: the functions may be called from any thread. Each job has one worker at a time.
 */
#ifndef ROOMSENSE_ROOMCREATORLIBRARY_H_
#define ROOMSENSE_ROOMCREATORLIBRARY_H_

#if defined(_WIN32)
#  if defined(ROOMSENSE_CAPI_BUILDING)
#    define ROOMSENSE_CAPI_EXPORT __declspec(dllexport)
#  else
#    define ROOMSENSE_CAPI_EXPORT __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define ROOMSENSE_CAPI_EXPORT __attribute__((visibility("default")))
#else
#  define ROOMSENSE_CAPI_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

ROOMSENSE_CAPI_EXPORT int StartRoomUnderstanding(const float* VertexPositions, int ArraySize);
ROOMSENSE_CAPI_EXPORT float* RetrieveRoomUnderstanding(int* OutErrorCode, int* OutArraySize);
ROOMSENSE_CAPI_EXPORT int CleanUpRoomUnderstanding(void);
ROOMSENSE_CAPI_EXPORT float* RetrieveRoomUnderstandingPlaces(int* OutErrorCode, int* OutArraySize);

ROOMSENSE_CAPI_EXPORT int StartRoomBounds(const float* VertexPositions, int ArraySize);
ROOMSENSE_CAPI_EXPORT float* RetrieveRoomBounds(int* OutErrorCode, int* OutVertexSize, int* OutTriangleSize);
ROOMSENSE_CAPI_EXPORT int CleanUpRoomBounds(void);

#ifdef __cplusplus
}  /* extern "C" */

namespace RoomCreator {  // the thesis's namespace
using ::StartRoomUnderstanding;
using ::RetrieveRoomUnderstanding;
using ::CleanUpRoomUnderstanding;
using ::RetrieveRoomUnderstandingPlaces;
using ::StartRoomBounds;
using ::RetrieveRoomBounds;
using ::CleanUpRoomBounds;
}  // namespace RoomCreator
#endif

#endif /* ROOMSENSE_ROOMCREATORLIBRARY_H_ */
