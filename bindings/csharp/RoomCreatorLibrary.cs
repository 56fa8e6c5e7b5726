// C# binding of libRoomCreatorLibrary (capi/): for Unity (drop this file and the library into Assets/) and
// any .NET or Mono program. Two APIs, as in the C headers:
// - RoomCreatorLibrary: the thesis's six functions (§3.8.1), declared exactly as its Unity scripts do
//   (float[] in, `ref int` sizes, IntPtr out), plus helpers that copy the results into managed arrays.
// - Analyzer and the rs_* declarations in Native: the handle-based API of roomsense/roomsense.h.
// Struct layouts mirror the C structs field by field (LayoutKind.Sequential, 4-byte enums); tests/csharp
// checks every size and offset against the C compiler's and the results against the C API's.
using System;
using System.Runtime.InteropServices;

namespace RoomCreator
{
    // ---- The thesis API (RoomCreatorLibrary.h) ----
    public static class RoomCreatorLibrary
    {
        public const string Library = "RoomCreatorLibrary";
        public const int FloatsPerArea = 11;

        [DllImport(Library, EntryPoint = "StartRoomUnderstanding")]
        extern static public int StartRoomUnderstanding(float[] vertexPositions, int arraySize);
        [DllImport(Library, EntryPoint = "RetrieveRoomUnderstanding")]
        extern static public IntPtr RetrieveRoomUnderstanding(ref int errorCode, ref int arraySize);
        [DllImport(Library, EntryPoint = "CleanUpRoomUnderstanding")]
        extern static public int CleanUpRoomUnderstanding();
        // Beyond the thesis: each area's storey and room, 2 floats per area (room -1: none).
        [DllImport(Library, EntryPoint = "RetrieveRoomUnderstandingPlaces")]
        extern static public IntPtr RetrieveRoomUnderstandingPlaces(ref int errorCode, ref int arraySize);

        [DllImport(Library, EntryPoint = "StartRoomBounds")]
        extern static public int StartRoomBounds(float[] vertexPositions, int arraySize);
        [DllImport(Library, EntryPoint = "RetrieveRoomBounds")]
        extern static public IntPtr RetrieveRoomBounds(ref int errorCode, ref int vertexSize, ref int triangleSize);
        [DllImport(Library, EntryPoint = "CleanUpRoomBounds")]
        extern static public int CleanUpRoomBounds();

        // The thesis's declarations trust arraySize: one larger than the array makes the library read past it.
        // These take the array's own length (a null array gives 1, no input).
        public static int StartRoomUnderstanding(float[] vertexPositions)
        {
            return StartRoomUnderstanding(vertexPositions, vertexPositions == null ? 0 : vertexPositions.Length);
        }
        public static int StartRoomBounds(float[] vertexPositions)
        {
            return StartRoomBounds(vertexPositions, vertexPositions == null ? 0 : vertexPositions.Length);
        }

        // Polls RetrieveRoomUnderstanding once. Returns -1 while running, 0 with `areas` (11 floats per area,
        // copied: call CleanUpRoomUnderstanding afterwards), 1 when the job ended without a result.
        public static int TryRetrieveAreas(out float[] areas)
        {
            int code = -1, size = 0;
            IntPtr data = RetrieveRoomUnderstanding(ref code, ref size);
            areas = code == 0 ? Copy(data, size) : null;
            return code;
        }

        // Polls RetrieveRoomUnderstandingPlaces once, as TryRetrieveAreas: on 0, each area's storey and room.
        public static int TryRetrievePlaces(out int[] storeys, out int[] rooms)
        {
            int code = -1, size = 0;
            IntPtr data = RetrieveRoomUnderstandingPlaces(ref code, ref size);
            storeys = null;
            rooms = null;
            if (code != 0) return code;
            float[] places = Copy(data, size);
            storeys = new int[size / 2];
            rooms = new int[size / 2];
            for (int i = 0; i < size / 2; ++i)
            {
                storeys[i] = (int)places[2 * i];
                rooms[i] = (int)places[2 * i + 1];
            }
            return code;
        }

        // Polls RetrieveRoomBounds once: on 0, the bounds' vertices (x, y, z each) and triangle indices.
        public static int TryRetrieveBounds(out float[] vertices, out int[] triangles)
        {
            int code = -1, vertexSize = 0, triangleSize = 0;
            IntPtr data = RetrieveRoomBounds(ref code, ref vertexSize, ref triangleSize);
            vertices = null;
            triangles = null;
            if (code != 0) return code;
            float[] all = Copy(data, vertexSize + triangleSize);
            vertices = new float[vertexSize];
            Array.Copy(all, vertices, vertexSize);
            triangles = new int[triangleSize];
            for (int i = 0; i < triangleSize; ++i) triangles[i] = (int)all[vertexSize + i];
            return code;
        }

        static float[] Copy(IntPtr data, int count)
        {
            var result = new float[count];
            if (count > 0) Marshal.Copy(data, result, 0, count);
            return result;
        }
    }

    // ---- The handle-based API (roomsense.h): types ----
    public enum Result : int
    {
        Success = 0, ErrorInvalidArgument = -1, ErrorHandleInvalid = -2, ErrorSizeInsufficient = -3,
        ErrorBusy = -4, ErrorNotReady = -5, ErrorNoResult = -6, ErrorEmptyInput = -7, ErrorBadIndices = -8,
        ErrorNoValidVertices = -9, ErrorGridTooLarge = -10, ErrorNoRoom = -11, ErrorOutOfMemory = -12,
        ErrorInternal = -13, ErrorTooMuchWork = -14,
    }
    public enum UpAxis : int { Y = 0, Z = 1 }
    public enum Units : int { Metres = 0, Centimetres = 1, Millimetres = 2 }
    public enum State : int { Idle = 0, Running = 1, Ready = 2, Failed = 3 }
    public enum AreaType : int { None = 0, Wall = 1, Floor = 2, Ceiling = 3, Furniture = 4 }
    public enum AreaSize : int { Large = 1, Medium = 2, Small = 3 }
    public enum Reach : int { Close = 1, Distance = 2, None = 3 }
    public enum ReachFilter : int { Any = 0, Close = 1, Distance = 2 }
    public enum PlacementShortfall : int { None = 0, NoSurface = 1, NoSpace = 2, NoHeadroom = 3, NoReach = 4, TooFew = 5 }
    [Flags] public enum ComputeFlags : uint { Areas = 1, Bounds = 2 }
    [Flags] public enum Surfaces : uint { Wall = 1, Floor = 2, Ceiling = 4, Furniture = 8, Any = 15 }

    [StructLayout(LayoutKind.Sequential)] public struct Vec3 { public float X, Y, Z; public Vec3(float x, float y, float z) { X = x; Y = y; Z = z; } }
    [StructLayout(LayoutKind.Sequential)] public struct Quat { public float X, Y, Z, W; }

    [StructLayout(LayoutKind.Sequential)]
    public struct AnalyzerOptions
    {
        public uint StructSize;
        public float VoxelSize;
        public uint ThreadCount;
        public ComputeFlags ComputeFlags;
        public UpAxis UpAxis;
        public Units Units;
        public int LeftHanded;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Timings { public double Prepare, Voxelize, Features, Areas, Reduce, Classify, Bounds, Total; }

    [StructLayout(LayoutKind.Sequential)]
    public struct Layout
    {
        public float FloorY, CeilingY;
        public uint StoreyCount, AreaCount, BoundsVertexCount, BoundsIndexCount;
        public uint InputVertexCount, InputTriangleCount, SkippedVertexCount, OutlierVertexCount;
        public float VoxelSize;
        public Vec3 GridOrigin;
        public uint GridDimX, GridDimY, GridDimZ;
        public Timings Timings;
    }

    [StructLayout(LayoutKind.Sequential)] public struct Storey { public float FloorY, CeilingY; }

    // API 1.2: a room of a storey, and where an area lies (Room: an index into Rooms(), or NoRoom).
    [StructLayout(LayoutKind.Sequential)]
    public struct Room
    {
        public uint Storey;
        public float FloorArea;          // m² of free floor
        public Vec3 Center;             // the centroid of its free floor, at its floor's height
        public float FloorY, CeilingY;
    }
    [StructLayout(LayoutKind.Sequential)]
    public struct AreaPlace
    {
        public const int NoRoom = -1;
        public uint Storey;
        public int Room;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Area
    {
        public AreaType Type;
        public AreaSize Size;
        public Reach Reach;
        public uint Flags;               // thesis Eq. 3.58
        public Vec3 Center, Normal;
        public Quat Orientation;
        public Vec3 Corner0, Corner1, Corner2, Corner3;
        public float HalfWidth, HalfHeight, RotationDeg, VolumeHeight;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct PlacementQuery
    {
        public uint StructSize;
        public Vec3 Size;
        public Surfaces Surfaces;
        public float Clearance, ClearanceAbove, EdgeDistance;
        public ReachFilter Reach;
        public int HasUserPosition;
        public Vec3 UserPosition;
        public float UserReach;
        public int HasNearPoint;
        public Vec3 NearPoint;
        public Vec3 FaceDirection;
        public uint MaxCount;
        public int AllowOverlap;
        public uint Reserved;
        public ulong Seed;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Placement
    {
        public AreaType Surface;
        public Reach Reach;
        public uint Storey;
        public Vec3 Center, Normal;
        public Quat Orientation;
        public Vec3 Corner0, Corner1, Corner2, Corner3;
        public float Width, Depth, Margin;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct RayHit { public int Hit, Scanned; public AreaType Surface; public float Distance; public Vec3 Position, Normal; }
    [StructLayout(LayoutKind.Sequential)]
    public struct Location { public int Inside, Free; public uint Storey; }
    [StructLayout(LayoutKind.Sequential)]
    public struct SurfacePoint { public int Found; public AreaType Surface; public Vec3 Position, Normal; }

    // ---- The handle-based API: functions, as declared in roomsense.h ----
    public static class Native
    {
        const string L = RoomCreatorLibrary.Library;
        public const uint WaitInfinite = uint.MaxValue;
        [DllImport(L)] public static extern IntPtr rs_result_string(Result result);
        [DllImport(L)] public static extern uint rs_api_version();
        [DllImport(L)] public static extern void rs_analyzer_options_init(out AnalyzerOptions options);
        [DllImport(L)] public static extern Result rs_analyzer_create(ref AnalyzerOptions options, out IntPtr analyzer);
        [DllImport(L)] public static extern void rs_analyzer_destroy(IntPtr analyzer);
        [DllImport(L)] public static extern Result rs_analyzer_compute(IntPtr analyzer, float[] xyz, uint vertexCount, uint[] indices, uint indexCount);
        [DllImport(L)] public static extern Result rs_analyzer_set_chunk(IntPtr analyzer, ulong chunkId, float[] xyz, uint vertexCount, uint[] indices, uint indexCount);
        [DllImport(L)] public static extern Result rs_analyzer_remove_chunk(IntPtr analyzer, ulong chunkId);
        [DllImport(L)] public static extern Result rs_analyzer_compute_chunks(IntPtr analyzer);
        [DllImport(L)] public static extern Result rs_analyzer_state(IntPtr analyzer, out State state);
        [DllImport(L)] public static extern Result rs_analyzer_wait(IntPtr analyzer, uint timeoutMs, out State state);
        [DllImport(L)] public static extern Result rs_analyzer_get_layout(IntPtr analyzer, out Layout layout);
        [DllImport(L)] public static extern Result rs_analyzer_get_storeys(IntPtr analyzer, uint capacity, out uint count, [Out] Storey[] storeys);
        [DllImport(L)] public static extern Result rs_analyzer_get_areas(IntPtr analyzer, uint capacity, out uint count, [Out] Area[] areas);
        [DllImport(L)] public static extern Result rs_analyzer_get_bounds(IntPtr analyzer, uint vertexCapacity, out uint vertexCount, [Out] float[] xyz,
                                                                         uint indexCapacity, out uint indexCount, [Out] uint[] indices);
        [DllImport(L)] public static extern Result rs_analyzer_get_rooms(IntPtr analyzer, uint capacity, out uint count, [Out] Room[] rooms);
        [DllImport(L)] public static extern Result rs_analyzer_get_area_places(IntPtr analyzer, uint capacity, out uint count, [Out] AreaPlace[] places);
        [DllImport(L)] public static extern Result rs_analyzer_get_room_bounds(IntPtr analyzer, uint room, uint vertexCapacity, out uint vertexCount, [Out] float[] xyz,
                                                                              uint indexCapacity, out uint indexCount, [Out] uint[] indices);
        [DllImport(L)] public static extern Result rs_analyzer_get_message(IntPtr analyzer, uint capacity, out uint count, [Out] byte[] buffer);
        [DllImport(L)] public static extern void rs_placement_query_init(out PlacementQuery query);
        [DllImport(L)] public static extern Result rs_analyzer_find_placements(IntPtr analyzer, ref PlacementQuery query, uint capacity, out uint count,
                                                                              [Out] Placement[] placements, out PlacementShortfall shortfall);
        [DllImport(L)] public static extern Result rs_analyzer_raycast(IntPtr analyzer, ref Vec3 origin, ref Vec3 direction, float maxDistance, out RayHit hit);
        [DllImport(L)] public static extern Result rs_analyzer_locate(IntPtr analyzer, ref Vec3 point, out Location location);
        [DllImport(L)] public static extern Result rs_analyzer_random_point_on_surface(IntPtr analyzer, Surfaces surfaces, float edgeDistance, ulong seed, out SurfacePoint point);
        [DllImport(L)] public static extern Result rs_analyzer_random_point_in_room(IntPtr analyzer, float clearance, ulong seed, out SurfacePoint point);
    }

    public class RoomSenseException : Exception
    {
        public readonly Result Result;
        public RoomSenseException(Result result, string what)
            : base(what + ": " + Marshal.PtrToStringAnsi(Native.rs_result_string(result))) { Result = result; }
    }

    // One analyzer (rs_analyzer) with the two-call idiom done for you; Dispose frees it.
    public sealed class Analyzer : IDisposable
    {
        IntPtr handle;

        public Analyzer() : this(DefaultOptions()) {}
        public Analyzer(AnalyzerOptions options) { Check(Native.rs_analyzer_create(ref options, out handle), "rs_analyzer_create"); }

        public static AnalyzerOptions DefaultOptions()
        {
            Native.rs_analyzer_options_init(out AnalyzerOptions options);
            return options;
        }

        public IntPtr Handle { get { return handle; } }

        // Starts a compute on the library's worker; xyz holds 3 floats per vertex, indices 3 per triangle or null.
        // A null or ragged xyz is the caller's mistake, told in C#'s terms before anything reaches the library.
        public void Compute(float[] xyz, uint[] indices = null)
        {
            if (xyz == null) throw new ArgumentNullException("xyz");
            if (xyz.Length % 3 != 0) throw new ArgumentException("xyz must hold 3 floats per vertex, got " + xyz.Length, "xyz");
            Check(Native.rs_analyzer_compute(handle, xyz, (uint)(xyz.Length / 3), indices, indices == null ? 0u : (uint)indices.Length),
                  "rs_analyzer_compute");
        }

        // API 1.3: a room in chunks by id (roomsense.h). SetChunk adds or replaces one, RemoveChunk removes one,
        // ComputeChunks analyses all held, voxelizing only those changed since the last.
        public void SetChunk(ulong id, float[] xyz, uint[] indices = null)
        {
            if (xyz == null) throw new ArgumentNullException("xyz");
            if (xyz.Length % 3 != 0) throw new ArgumentException("xyz must hold 3 floats per vertex, got " + xyz.Length, "xyz");
            Check(Native.rs_analyzer_set_chunk(handle, id, xyz, (uint)(xyz.Length / 3), indices, indices == null ? 0u : (uint)indices.Length),
                  "rs_analyzer_set_chunk");
        }

        public void RemoveChunk(ulong id) { Check(Native.rs_analyzer_remove_chunk(handle, id), "rs_analyzer_remove_chunk"); }

        public void ComputeChunks() { Check(Native.rs_analyzer_compute_chunks(handle), "rs_analyzer_compute_chunks"); }

        public State State { get { Check(Native.rs_analyzer_state(handle, out State s), "rs_analyzer_state"); return s; } }

        public State Wait(uint timeoutMs = Native.WaitInfinite)
        {
            Check(Native.rs_analyzer_wait(handle, timeoutMs, out State s), "rs_analyzer_wait");
            return s;
        }

        public Layout Layout { get { Check(Native.rs_analyzer_get_layout(handle, out Layout l), "rs_analyzer_get_layout"); return l; } }

        public Storey[] Storeys()
        {
            Check(Native.rs_analyzer_get_storeys(handle, 0, out uint n, null), "rs_analyzer_get_storeys");
            var storeys = new Storey[n];
            Check(Native.rs_analyzer_get_storeys(handle, n, out n, storeys), "rs_analyzer_get_storeys");
            return storeys;
        }

        public Area[] Areas()
        {
            Check(Native.rs_analyzer_get_areas(handle, 0, out uint n, null), "rs_analyzer_get_areas");
            var areas = new Area[n];
            Check(Native.rs_analyzer_get_areas(handle, n, out n, areas), "rs_analyzer_get_areas");
            return areas;
        }

        public void Bounds(out float[] xyz, out uint[] indices)
        {
            Check(Native.rs_analyzer_get_bounds(handle, 0, out uint nv, null, 0, out uint ni, null), "rs_analyzer_get_bounds");
            xyz = new float[3 * nv];
            indices = new uint[ni];
            Check(Native.rs_analyzer_get_bounds(handle, nv, out nv, xyz, ni, out ni, indices), "rs_analyzer_get_bounds");
        }

        public Room[] Rooms()
        {
            Check(Native.rs_analyzer_get_rooms(handle, 0, out uint n, null), "rs_analyzer_get_rooms");
            var rooms = new Room[n];
            Check(Native.rs_analyzer_get_rooms(handle, n, out n, rooms), "rs_analyzer_get_rooms");
            return rooms;
        }

        // Element i says where Areas()[i] lies.
        public AreaPlace[] AreaPlaces()
        {
            Check(Native.rs_analyzer_get_area_places(handle, 0, out uint n, null), "rs_analyzer_get_area_places");
            var places = new AreaPlace[n];
            Check(Native.rs_analyzer_get_area_places(handle, n, out n, places), "rs_analyzer_get_area_places");
            return places;
        }

        public void RoomBounds(uint room, out float[] xyz, out uint[] indices)
        {
            Check(Native.rs_analyzer_get_room_bounds(handle, room, 0, out uint nv, null, 0, out uint ni, null), "rs_analyzer_get_room_bounds");
            xyz = new float[3 * nv];
            indices = new uint[ni];
            Check(Native.rs_analyzer_get_room_bounds(handle, room, nv, out nv, xyz, ni, out ni, indices), "rs_analyzer_get_room_bounds");
        }

        public string Message()
        {
            Check(Native.rs_analyzer_get_message(handle, 0, out uint n, null), "rs_analyzer_get_message");
            var bytes = new byte[n];
            Check(Native.rs_analyzer_get_message(handle, n, out n, bytes), "rs_analyzer_get_message");
            return System.Text.Encoding.UTF8.GetString(bytes, 0, (int)Math.Max(n, 1) - 1);
        }

        public static PlacementQuery DefaultQuery()
        {
            Native.rs_placement_query_init(out PlacementQuery q);
            return q;
        }

        public Placement[] FindPlacements(PlacementQuery query, out PlacementShortfall shortfall)
        {
            Check(Native.rs_analyzer_find_placements(handle, ref query, 0, out uint n, null, out shortfall), "rs_analyzer_find_placements");
            var found = new Placement[n];
            Check(Native.rs_analyzer_find_placements(handle, ref query, n, out n, found, out shortfall), "rs_analyzer_find_placements");
            return found;
        }

        public RayHit Raycast(Vec3 origin, Vec3 direction, float maxDistance = 0)
        {
            Check(Native.rs_analyzer_raycast(handle, ref origin, ref direction, maxDistance, out RayHit hit), "rs_analyzer_raycast");
            return hit;
        }

        public Location Locate(Vec3 point)
        {
            Check(Native.rs_analyzer_locate(handle, ref point, out Location where), "rs_analyzer_locate");
            return where;
        }

        public SurfacePoint RandomPointOnSurface(Surfaces surfaces, float edgeDistance, ulong seed)
        {
            Check(Native.rs_analyzer_random_point_on_surface(handle, surfaces, edgeDistance, seed, out SurfacePoint p), "rs_analyzer_random_point_on_surface");
            return p;
        }

        public SurfacePoint RandomPointInRoom(float clearance, ulong seed)
        {
            Check(Native.rs_analyzer_random_point_in_room(handle, clearance, seed, out SurfacePoint p), "rs_analyzer_random_point_in_room");
            return p;
        }

        public void Dispose()
        {
            if (handle != IntPtr.Zero) Native.rs_analyzer_destroy(handle);
            handle = IntPtr.Zero;
            GC.SuppressFinalize(this);
        }

        ~Analyzer() { if (handle != IntPtr.Zero) Native.rs_analyzer_destroy(handle); }

        static void Check(Result r, string what) { if (r != Result.Success) throw new RoomSenseException(r, what); }
    }
}
