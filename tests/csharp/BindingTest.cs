// Run by csharp_binding_test.cpp with the folder it wrote: checks the binding's struct layouts against the C
// compiler's (layouts.txt) and that the thesis API and the handle API give, through the binding, exactly the
// C API's results (*.bin). Prints "BindingTest: ok" and exits 0, or names the first difference and exits 1.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using RoomCreator;

static class BindingTest
{
    static string dir;
    static int failures;

    static void Check(bool ok, string what)
    {
        if (ok) return;
        Console.WriteLine("BindingTest: FAILED: " + what);
        ++failures;
    }

    static float[] Floats(string name) { var b = File.ReadAllBytes(Path.Combine(dir, name)); var f = new float[b.Length / 4]; Buffer.BlockCopy(b, 0, f, 0, b.Length); return f; }
    static uint[] Uints(string name) { var b = File.ReadAllBytes(Path.Combine(dir, name)); var u = new uint[b.Length / 4]; Buffer.BlockCopy(b, 0, u, 0, b.Length); return u; }

    // The bytes C would hold for these structs (the binding's layout, checked against C's below).
    static byte[] Bytes<T>(T[] items) where T : struct
    {
        int size = Marshal.SizeOf(typeof(T));
        var bytes = new byte[size * items.Length];
        IntPtr buffer = Marshal.AllocHGlobal(size);
        try
        {
            for (int i = 0; i < items.Length; ++i)
            {
                Marshal.StructureToPtr(items[i], buffer, false);
                Marshal.Copy(buffer, bytes, i * size, size);
            }
        }
        finally { Marshal.FreeHGlobal(buffer); }
        return bytes;
    }

    static bool SameBits(float[] a, float[] b) { return a.Length == b.Length && Enumerable.Range(0, a.Length).All(i => BitConverter.ToInt32(BitConverter.GetBytes(a[i]), 0) == BitConverter.ToInt32(BitConverter.GetBytes(b[i]), 0)); }

    // Every field's offset in declaration order, nested structs as one field, as layouts.txt lists them.
    static void CheckLayout(string line)
    {
        var parts = line.Split(' ');
        Type t = typeof(Area).Assembly.GetType("RoomCreator." + parts[0]);
        if (t == null) { Check(false, "no C# type for " + parts[0]); return; }
        var fields = t.GetFields(BindingFlags.Instance | BindingFlags.Public).OrderBy(f => f.MetadataToken).ToArray();
        Check(Marshal.SizeOf(t) == int.Parse(parts[1]), parts[0] + ": size " + Marshal.SizeOf(t) + ", C says " + parts[1]);
        Check(fields.Length == parts.Length - 2, parts[0] + ": " + fields.Length + " fields, C lists " + (parts.Length - 2));
        for (int i = 0; i < Math.Min(fields.Length, parts.Length - 2); ++i)
        {
            int offset = (int)Marshal.OffsetOf(t, fields[i].Name);
            Check(offset == int.Parse(parts[i + 2]), parts[0] + "." + fields[i].Name + " at " + offset + ", C says " + parts[i + 2]);
        }
    }

    static int Main(string[] args)
    {
        dir = args[0];
        foreach (string line in File.ReadAllLines(Path.Combine(dir, "layouts.txt"))) CheckLayout(line);
        float[] xyz = Floats("vertices.bin");
        uint[] indices = Uints("indices.bin");

        // The thesis API, declared as the thesis's Unity scripts declare it.
        Check(RoomCreatorLibrary.StartRoomUnderstanding(xyz, xyz.Length) == 0, "StartRoomUnderstanding");
        float[] areas;
        int code;
        while ((code = RoomCreatorLibrary.TryRetrieveAreas(out areas)) == -1) System.Threading.Thread.Sleep(5);
        Check(code == 0 && SameBits(areas, Floats("thesis_areas.bin")), "RetrieveRoomUnderstanding differs from C's");
        Check(RoomCreatorLibrary.TryRetrievePlaces(out int[] placeStoreys, out int[] placeRooms) == 0 &&
              placeStoreys.Length == areas.Length / RoomCreatorLibrary.FloatsPerArea && placeRooms.All(r => r >= -1),
              "RetrieveRoomUnderstandingPlaces: a storey and a room per area");
        Check(RoomCreatorLibrary.StartRoomUnderstanding(xyz, xyz.Length) == 4, "a second Start before CleanUp is busy (4)");
        Check(RoomCreatorLibrary.CleanUpRoomUnderstanding() == 0, "CleanUpRoomUnderstanding");
        Check(RoomCreatorLibrary.StartRoomBounds(xyz, xyz.Length) == 0, "StartRoomBounds");
        float[] boundsXyz;
        int[] triangles;
        while ((code = RoomCreatorLibrary.TryRetrieveBounds(out boundsXyz, out triangles)) == -1) System.Threading.Thread.Sleep(5);
        float[] cBounds = Floats("thesis_bounds.bin");
        var flat = new List<float> { boundsXyz.Length, triangles.Length };
        flat.AddRange(boundsXyz);
        flat.AddRange(triangles.Select(i => (float)i));
        Check(code == 0 && SameBits(flat.ToArray(), cBounds), "RetrieveRoomBounds differs from C's");
        RoomCreatorLibrary.CleanUpRoomBounds();
        Check(RoomCreatorLibrary.StartRoomUnderstanding(null, 0) == 1 && RoomCreatorLibrary.StartRoomUnderstanding(new float[4], 4) == 2,
              "the thesis API's input errors (1, 2)");
        Check(RoomCreatorLibrary.StartRoomUnderstanding(null) == 1 && RoomCreatorLibrary.StartRoomBounds(new float[5]) == 2,
              "the length-taking overloads' input errors (1, 2)");

        // API 1.3: the room as one chunk is the room given whole.
        using (var chunked = new Analyzer())
        {
            chunked.SetChunk(7, xyz, indices);
            chunked.ComputeChunks();
            Check(chunked.Wait() == State.Ready, "the chunked analysis is ready: " + chunked.Message());
            Check(Bytes(chunked.Areas()).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_areas.bin"))),
                  "the room as one chunk differs from C's rs_analyzer_compute");
            try { chunked.RemoveChunk(8); Check(false, "removing a chunk never set throws"); }
            catch (RoomSenseException e) { Check(e.Result == Result.ErrorInvalidArgument, "removing an unknown chunk: " + e.Message); }
        }

        // The handle API.
        uint version = Native.rs_api_version();
        int storeyCount, placementCount, hitCount = 0;
        using (var analyzer = new Analyzer())
        {
            try { analyzer.Layout.ToString(); Check(false, "a getter before any compute throws"); }
            catch (RoomSenseException e) { Check(e.Result == Result.ErrorNoResult, "before a compute: " + e.Message); }
            analyzer.Compute(xyz, indices);
            Check(analyzer.Wait() == State.Ready, "the analysis is ready: " + analyzer.Message());
            Check(analyzer.Message().StartsWith("ok"), "the message says ok: " + analyzer.Message());
            Check(Bytes(analyzer.Areas()).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_areas.bin"))), "rs_analyzer_get_areas differs from C's");
            analyzer.Bounds(out float[] bxyz, out uint[] bidx);
            Check(SameBits(bxyz, Floats("handle_bounds_xyz.bin")) && bidx.SequenceEqual(Uints("handle_bounds_indices.bin")), "rs_analyzer_get_bounds differs from C's");
            Storey[] storeys = analyzer.Storeys();
            storeyCount = storeys.Length;
            Check(Bytes(storeys).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_storeys.bin"))), "rs_analyzer_get_storeys differs from C's");
            Check(Bytes(analyzer.Rooms()).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_rooms.bin"))), "rs_analyzer_get_rooms differs from C's");
            AreaPlace[] places = analyzer.AreaPlaces();
            Check(places.Length == analyzer.Areas().Length && Bytes(places).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_area_places.bin"))),
                  "rs_analyzer_get_area_places differs from C's");
            analyzer.RoomBounds(0, out float[] rxyz, out uint[] ridx);
            Check(ridx.SequenceEqual(Uints("handle_room0_indices.bin")) && rxyz.Length > 0, "rs_analyzer_get_room_bounds differs from C's");
            try { analyzer.RoomBounds((uint)analyzer.Rooms().Length, out rxyz, out ridx); Check(false, "a room past the last throws"); }
            catch (RoomSenseException e) { Check(e.Result == Result.ErrorInvalidArgument, "a room past the last: " + e.Message); }
            Layout layout = analyzer.Layout;
            Check(layout.AreaCount == analyzer.Areas().Length && layout.InputVertexCount == xyz.Length / 3, "the layout's counts");
            PlacementQuery q = Analyzer.DefaultQuery();
            q.Surfaces = Surfaces.Furniture | Surfaces.Floor;
            q.MaxCount = 8;
            q.Seed = 42;
            Placement[] placements = analyzer.FindPlacements(q, out PlacementShortfall shortfall);
            placementCount = placements.Length;
            Check(Bytes(placements).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_placements.bin"))), "rs_analyzer_find_placements differs from C's");
            float[] m = Floats("middle.bin");
            var middle = new Vec3(m[0], m[1], m[2]);
            var hits = new List<RayHit>();
            for (int i = 0; i < 16; ++i)
            {
                float angle = 0.3927f * i;
                hits.Add(analyzer.Raycast(middle, new Vec3((float)Math.Cos(angle), -0.3f, (float)Math.Sin(angle))));
            }
            hitCount = hits.Count(h => h.Hit != 0);
            Check(Bytes(hits.ToArray()).SequenceEqual(File.ReadAllBytes(Path.Combine(dir, "handle_rays.bin"))), "rs_analyzer_raycast differs from C's");
            try { analyzer.Compute(null); Check(false, "Compute(null) throws"); }
            catch (ArgumentNullException) {}
            try { analyzer.Compute(new float[4]); Check(false, "Compute of 4 floats throws"); }
            catch (ArgumentException) {}
            try { analyzer.Compute(xyz, new uint[] { 0, 1 }); Check(false, "2 indices throw"); }
            catch (RoomSenseException e) { Check(e.Result == Result.ErrorBadIndices, "2 indices: " + e.Message); }
            q.MaxCount = 0;
            try { analyzer.FindPlacements(q, out shortfall); Check(false, "max_count 0 throws"); }
            catch (RoomSenseException e) { Check(e.Result == Result.ErrorInvalidArgument, "max_count 0: " + e.Message); }
        }
        var disposed = new Analyzer();
        disposed.Dispose();
        disposed.Dispose();  // twice is harmless
        try { disposed.Compute(xyz); Check(false, "a disposed analyzer throws"); }
        catch (RoomSenseException e) { Check(e.Result == Result.ErrorHandleInvalid, "disposed: " + e.Message); }
        if (failures > 0) return 1;
        Console.WriteLine("BindingTest: ok: layouts of " + File.ReadAllLines(Path.Combine(dir, "layouts.txt")).Length +
                          " structs as C's; thesis API " + areas.Length / 11 + " areas and their places, bounds " +
                          boundsXyz.Length / 3 + " vertices; handle API (" + (version >> 22) + "." + ((version >> 12) & 0x3FF) + ") areas, bounds, " +
                          storeyCount + " storeys, rooms, area places, room bounds, " + placementCount + " placements, " + hitCount + "/16 rays, equal to the C API's");
        return 0;
    }
}
