// The OBJ and PLY readers (scanio/read_obj.cpp, read_ply.cpp) and load_mesh_file's dispatch: what they read,
// and the issue-18 reproducers that crashed or went unreported under assimp, now one Error(Io) line each.
#include "roomsense/error.h"
#include "roomsense/scanio.h"
#include "test_process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>


namespace roomsense {
namespace {

using Indices = std::vector<std::uint32_t>;

Scan obj(const std::string& text) {
  std::istringstream in(text);
  return scanio::read_obj(in, "test.obj");
}

Scan ply(const std::string& bytes) {
  std::istringstream in(bytes);
  return scanio::read_ply(in, "test.ply");
}

// The Error's message when `read` throws one with ErrorCode::Io; fails the test otherwise.
template <class Read>
std::string io_error(Read&& read) {
  try {
    read();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no Error was thrown";
  return {};
}

const std::string kTriangleHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";

// --- PLY: the reproducers of issue 18 ----------------------------------------------------------------------

TEST(PlyReader, NegativeIndexIsAnErrorNamingTheFaceAndIndex) {  // was a SIGSEGV in assimp
  EXPECT_EQ(io_error([] { ply(kTriangleHeader + "3 0 1 -1\n"); }),
            "cannot read 'test.ply': face 0 refers to vertex -1, but the file has 3 vertices");
}

TEST(PlyReader, HugeIndexIsAnErrorNamingTheFaceAndIndex) {  // was a SIGSEGV in assimp
  EXPECT_EQ(io_error([] { ply(kTriangleHeader + "3 0 1 100000000\n"); }),
            "cannot read 'test.ply': face 0 refers to vertex 100000000, but the file has 3 vertices");
}

TEST(PlyReader, IndexJustPastTheVerticesIsReported) {  // assimp read it silently
  EXPECT_EQ(io_error([] { ply(kTriangleHeader + "3 0 1 5\n"); }),
            "cannot read 'test.ply': face 0 refers to vertex 5, but the file has 3 vertices");
  const std::string two_faces = std::string(kTriangleHeader).replace(kTriangleHeader.find("face 1"), 6, "face 2");
  EXPECT_EQ(io_error([&] { ply(two_faces + "3 0 1 2\n3 2 1 3\n"); }),
            "cannot read 'test.ply': face 1 refers to vertex 3, but the file has 3 vertices");
}

TEST(PlyReader, FacesOfFewerThanThreeVerticesAreSkippedButChecked) {  // an empty face was an assimp abort
  const Scan empty_face = ply(kTriangleHeader + "0\n");
  EXPECT_EQ(empty_face.vertices.size(), 3u);
  EXPECT_TRUE(empty_face.indices.empty());
  const std::string faces3 = std::string(kTriangleHeader).replace(kTriangleHeader.find("face 1"), 6, "face 3");
  EXPECT_EQ(ply(faces3 + "2 0 1\n1 2\n3 0 1 2\n").indices, (Indices{0, 1, 2}));
  EXPECT_NE(io_error([&] { ply(faces3 + "2 0 7\n1 2\n3 0 1 2\n"); }).find("face 0 refers to vertex 7"), std::string::npos);
}

TEST(PlyReader, MissingVertexLinesAreAnError) {  // was an assimp abort
  const std::string five = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  // Too short for what the header declares: refused before anything is read.
  EXPECT_NE(io_error([&] { ply(five + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"); }).find("declares more data"), std::string::npos);
  // Long enough, but the face lines come where vertices were declared: caught at the first of them.
  const std::string long_faces = "3 0 1 2                                                  \n";
  const std::string message = io_error([&] { ply(five + "0 0 0\n1 0 0\n0 1 0\n" + long_faces + long_faces); });
  EXPECT_NE(message.find("vertex 3 (line 13) has more values than its element declares (are vertex lines missing?)"),
            std::string::npos) << message;
  // And a file that simply stops.
  EXPECT_NE(io_error([&] { ply(five + "0 0 0\n1 0 0\n0 1 0\n0 0 1 \n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n"); })
                .find("the file ends after 4 of its 5 vertex lines"),
            std::string::npos);
}

TEST(PlyReader, HeaderCountsMustFitTheFile) {
  const std::string message = io_error([] {
    ply("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n0000");
  });
  EXPECT_NE(message.find("declares more data (at least 12000000000 bytes)"), std::string::npos) << message;
}

TEST(PlyReader, RefusesWhatIsNotPly) {
  EXPECT_EQ(io_error([] { ply("this is not a ply file\n"); }),
            "cannot read 'test.ply': it is not a PLY file (it does not start with 'ply')");
  EXPECT_NE(io_error([] { ply("ply\nformat ascii 1.0\nelement vertex 1\n"); }).find("no end_header"), std::string::npos);
  EXPECT_NE(io_error([] { ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n"); })
                .find("lacks an x, y or z"),
            std::string::npos);
  EXPECT_NE(io_error([] { ply(kTriangleHeader + "3 0 1 x\n"); }).find("'x' is not an integer"), std::string::npos);
}

// --- PLY: what it reads ------------------------------------------------------------------------------------

// A '+' sign is read as OBJ reads it (scan_file.h's number_word): once, and never before another sign, where it
// had made "+-1" read as -1.
TEST(PlyReader, APlusSignIsReadOnceAndNeverBeforeAnotherSign) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const Scan scan = ply(header + "+1.5 0 0\n1 +0 0\n0 1 +.5e+1\n+3 0 +1 +2\n");
  EXPECT_EQ(scan.vertices, (std::vector<glm::vec3>{{1.5f, 0, 0}, {1, 0, 0}, {0, 1, 5}}));
  EXPECT_EQ(scan.indices, (Indices{0, 1, 2}));
  EXPECT_EQ(io_error([&] { ply(header + "0 0 0\n1 +-1 0\n0 1 0\n3 0 1 2\n"); }),
            "cannot read 'test.ply': vertex 1 (line 11): '+-1' is not a number");
  EXPECT_EQ(io_error([&] { ply(header + "0 0 0\n1 0 0\n0 1 ++2\n3 0 1 2\n"); }),
            "cannot read 'test.ply': vertex 2 (line 12): '++2' is not a number");
  EXPECT_EQ(io_error([&] { ply(header + "0 0 0\n1 0 0\n0 1 0\n3 0 +-1 2\n"); }),
            "cannot read 'test.ply': face 0 (line 13): '+-1' is not an integer");
  EXPECT_EQ(io_error([&] { ply(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 +\n"); }),
            "cannot read 'test.ply': face 0 (line 13): '+' is not an integer");
}

TEST(PlyReader, AsciiPolygonsOtherPropertiesAndElements) {
  const Scan scan = ply(
      "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 5\nproperty double x\nproperty uchar red\n"
      "property float y\nproperty float z\nelement face 2\nproperty uchar flags\nproperty list int uint vertex_index\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "0 255 0 0\n1 0 0 0\n1 0 1 0\n0 0 1 0\n\t0.5 7 2.5 -1e-3\r\n"
      "1 4 0 1 2 3\n9 3 0 3 4\n0 1\n");
  ASSERT_EQ(scan.vertices.size(), 5u);
  EXPECT_EQ(scan.vertices[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(scan.vertices[4], glm::vec3(0.5f, 2.5f, -1e-3f));
  EXPECT_EQ(scan.indices, (Indices{0, 1, 2, 0, 2, 3, 0, 3, 4}));  // the quad as a fan, then the triangle
}

TEST(PlyReader, PointCloudHasNoIndices) {
  const Scan scan = ply("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                        "end_header\n1 2 3\n4 5 6\n");
  EXPECT_EQ(scan.vertices, (std::vector<glm::vec3>{{1, 2, 3}, {4, 5, 6}}));
  EXPECT_TRUE(scan.indices.empty());
}

// Little helpers to write binary PLY bodies in either byte order.
template <class T>
void put(std::string& out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian == (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string binary_room(bool big_endian) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty double z\nproperty uchar alpha\n"
                    "element material 2\nproperty list uchar float weights\n"
                    "element face 3\nproperty list ushort int vertex_indices\nproperty short tag\nend_header\n";
  const float xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int v = 0; v < 4; ++v) {
    put<float>(out, xy[v][0], big_endian);
    put<float>(out, xy[v][1], big_endian);
    put<double>(out, 0.25 * v, big_endian);
    put<std::uint8_t>(out, 200, big_endian);
  }
  put<std::uint8_t>(out, 2, big_endian), put<float>(out, 1.0f, big_endian), put<float>(out, 2.0f, big_endian);
  put<std::uint8_t>(out, 0, big_endian);
  put<std::uint16_t>(out, 4, big_endian);  // a quad
  for (int i : {3, 2, 1, 0}) put<std::int32_t>(out, i, big_endian);
  put<std::int16_t>(out, -5, big_endian);
  put<std::uint16_t>(out, 2, big_endian);  // a line: skipped
  for (int i : {0, 1}) put<std::int32_t>(out, i, big_endian);
  put<std::int16_t>(out, 0, big_endian);
  put<std::uint16_t>(out, 3, big_endian);
  for (int i : {0, 2, 3}) put<std::int32_t>(out, i, big_endian);
  put<std::int16_t>(out, 0, big_endian);
  return out;
}

TEST(PlyReader, BinaryLittleAndBigEndianRoundTrip) {
  for (const bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian ? "big endian" : "little endian");
    const Scan scan = ply(binary_room(big_endian));
    EXPECT_EQ(scan.vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0.25f}, {1, 1, 0.5f}, {0, 1, 0.75f}}));
    EXPECT_EQ(scan.indices, (Indices{3, 2, 1, 3, 1, 0, 0, 2, 3}));
  }
}

// A stream that cannot seek, like a pipe: the reader cannot check the header against the size.
class PipeBuffer : public std::streambuf {
 public:
  explicit PipeBuffer(std::string bytes) : bytes_(std::move(bytes)) { setg(bytes_.data(), bytes_.data(), bytes_.data() + bytes_.size()); }

 private:
  std::string bytes_;
};

TEST(PlyReader, BinaryErrors) {
  std::string negative = binary_room(false);
  const std::size_t quad = negative.find("end_header\n") + 11 + 4 * 17 + 10 + 2;  // the quad's first index
  for (std::size_t k = 12; k < 16; ++k) negative[quad + k] = char(0xff);         // its fourth: -1
  EXPECT_EQ(io_error([&] { ply(negative); }), "cannot read 'test.ply': face 0 refers to vertex -1, but the file has 4 vertices");
  const std::string whole = binary_room(true);
  EXPECT_NE(io_error([&] { ply(whole.substr(0, whole.find("end_header\n") + 30)); }).find("declares more data"),
            std::string::npos);
  // The header's minimum (a list counts as its count alone) fits, but the last face is cut short.
  const std::string truncated = whole.substr(0, whole.size() - 3);
  EXPECT_EQ(io_error([&] { ply(truncated); }), "cannot read 'test.ply': the file ends in face 2 of 3");
  PipeBuffer pipe(truncated);
  std::istream in(&pipe);
  EXPECT_EQ(io_error([&] { scanio::read_ply(in, "pipe"); }), "cannot read 'pipe': the file ends in face 2 of 3");
}

// --- OBJ -------------------------------------------------------------------------------------------------

TEST(ObjReader, PolygonsNegativeIndicesAndEveryFaceForm) {
  const Scan scan = obj("# a comment\n"
                        "o room\nv 0 0 0\nv 1 0 0\nv 1 1 0  # trailing comment\nv 0 1 0 1.0\n"
                        "vt 0 0\nvt 1 0\nvn 0 0 1\n"
                        "f 1/1/1 2/2/1 3/2/1 4/1/1\n"   // quad, v/vt/vn
                        "f 1//1 2//1 3//1\n"            // v//vn
                        "f 1/1 3/2 4/1\n"               // v/vt
                        "v 2 0 0\nv 2 1 0\n"
                        "f -6 -2 -1\n"                  // relative: vertices 1, 5, 6
                        "f 1 2 3 4 5\n"                 // pentagon
                        "l 1 2\n");
  ASSERT_EQ(scan.vertices.size(), 6u);
  EXPECT_EQ(scan.vertices[2], glm::vec3(1, 1, 0));
  EXPECT_EQ(scan.indices, (Indices{0, 1, 2, 0, 2, 3,  0, 1, 2,  0, 2, 3,  0, 4, 5,  0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST(ObjReader, ShortFacesAreSkippedAndForwardReferencesAllowed) {
  EXPECT_EQ(obj("f 1 2 3\nf 1 2\nv 0 0 0\nv 1 0 0\nv 0 1 0\n").indices, (Indices{0, 1, 2}));
}

// As assimp did: stray points of a mesh are no surface. Without any triangle, every vertex stays.
TEST(ObjReader, VerticesNoTriangleUsesAreDroppedFromAMesh) {
  const Scan mesh = obj("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 7 7 7\nv 0 1 0\nf 2 3 5\nf 4 2\n");
  EXPECT_EQ(mesh.vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(mesh.indices, (Indices{0, 1, 2}));
  EXPECT_EQ(obj("v 9 9 9\nv 0 0 0\nf 1 2\n").vertices.size(), 2u);
}

TEST(ObjReader, BadIndicesNameTheFace) {
  EXPECT_EQ(io_error([] { obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 99\n"); }),
            "cannot read 'test.obj': face 2 refers to vertex 99, but the file has 3 vertices");
  EXPECT_EQ(io_error([] { obj("v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n"); }),
            "cannot read 'test.obj': face 1 refers to vertex -3, but only 2 vertices precede it");
  EXPECT_EQ(io_error([] { obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"); }),
            "cannot read 'test.obj': face 1 has a missing or zero vertex index");
  EXPECT_NE(io_error([] { obj("v 0 0 0\nv 1 0 0\nf 1 7\n"); }).find("face 1 refers to vertex 7"), std::string::npos);
  EXPECT_EQ(io_error([] { obj("# nothing but a comment\n"); }), "cannot read 'test.obj': it holds no vertices");
}

// tinyobjloader alone read these as 0 (a vertex at the origin, silently): a coordinate that is not finite keeps its
// value (the pipeline skips such vertices and counts them, as PLY's), and one that is no number is an error.
TEST(ObjReader, CoordinatesThatAreNotFiniteKeepTheirValue) {
  const Scan scan = obj("v nan 0.5 0\nv 1 -inf 0\nv 0 1 +Infinity\nv -.5 +1. 2E-1 1.0\nv NaN 2 -nan\n"
                        "f 1 2 3\nf 3 4 5\n");
  ASSERT_EQ(scan.vertices.size(), 5u);
  EXPECT_TRUE(std::isnan(scan.vertices[0].x));
  EXPECT_EQ(scan.vertices[0].y, 0.5f);  // the plain coordinates of such a line as before
  EXPECT_EQ(scan.vertices[1].y, -std::numeric_limits<float>::infinity());
  EXPECT_EQ(scan.vertices[2].z, std::numeric_limits<float>::infinity());
  EXPECT_EQ(scan.vertices[3], glm::vec3(-0.5f, 1.0f, 0.2f));
  EXPECT_TRUE(std::isnan(scan.vertices[4].x) && std::isnan(scan.vertices[4].z));
  EXPECT_EQ(scan.vertices[4].y, 2.0f);
}

TEST(ObjReader, ACoordinateThatIsNoNumberIsAnErrorNamingTheLine) {
  EXPECT_EQ(io_error([] { obj("v 0 0 0\n# comment\nv 1,5 0 0\nv 0 1 0\nf 1 2 3\n"); }),
            "cannot read 'test.obj': line 3: vertex coordinate '1,5' is not a number");
  EXPECT_EQ(io_error([] { obj("v 1.5e 0 0\n"); }), "cannot read 'test.obj': line 1: vertex coordinate '1.5e' is not a number");
  EXPECT_EQ(io_error([] { obj("v 0 0 0\r\nv +-1 0 0\r\n"); }),
            "cannot read 'test.obj': line 2: vertex coordinate '+-1' is not a number");
  EXPECT_EQ(io_error([] { obj("v 0 0 0\rv 1 2\r"); }), "cannot read 'test.obj': line 2: a vertex needs three coordinates");
  EXPECT_EQ(io_error([] { obj("v 1 2 # z\n"); }), "cannot read 'test.obj': line 1: a vertex needs three coordinates");
  // A word of the file is quoted as one printable line: control bytes as '?', at most 32 bytes.
  EXPECT_EQ(io_error([] { obj(std::string("v 0\0x\x1b 0 0\n", 11)); }),
            "cannot read 'test.obj': line 1: vertex coordinate '0?x?' is not a number");
  EXPECT_EQ(io_error([] { obj("v " + std::string(100, 'x') + " 0 0\n"); }),
            "cannot read 'test.obj': line 1: vertex coordinate '" + std::string(32, 'x') + "' is not a number");
}

TEST(ObjReader, AStreamThatFailsIsAnErrorNotAShortFile) {
  struct Failing : std::streambuf {
    int_type underflow() override { throw std::runtime_error("disk gone"); }
  } failing;
  std::istream in(&failing);
  EXPECT_EQ(io_error([&] { scanio::read_obj(in, "test.obj"); }), "cannot read 'test.obj': reading it failed");
}

// --- load_mesh_file ------------------------------------------------------------------------------------

std::string temp_file(const std::string& name, const std::string& bytes) {
  const std::string path = test::temp_path(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(LoadMeshFile, DispatchesByContentAndCaseInsensitiveExtension) {
  EXPECT_EQ(scanio::load_mesh_file(temp_file("upper.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).indices.size(), 3u);
  EXPECT_EQ(scanio::load_mesh_file(temp_file("plain.mesh", kTriangleHeader + "3 0 1 2\n")).indices.size(), 3u);
  EXPECT_EQ(scanio::load_mesh_file(temp_file("binary.PLY", binary_room(true))).vertices.size(), 4u);
  const std::string stl = temp_file("room.stl", "solid room\nendsolid room\n");
  EXPECT_EQ(io_error([&] { scanio::load_mesh_file(stl); }),
            "cannot read '" + stl + "': unknown mesh format '.stl' (roomsense reads .obj, .ply, .gltf and .glb)");
}

TEST(LoadMeshFile, SaysWhatAPathIsWhenItIsNoRegularFile) {
  EXPECT_EQ(io_error([] { scanio::load_mesh_file("/no/such/room.obj"); }), "cannot read '/no/such/room.obj': no such file");
  EXPECT_EQ(io_error([] { scanio::load_mesh_file(testing::TempDir()); }),
            "cannot read '" + testing::TempDir() + "': it is a directory");
  if (!test::kPosix) return;  // no FIFOs or character devices to name
  EXPECT_EQ(io_error([] { scanio::load_mesh_file("/dev/zero"); }),
            "cannot read '/dev/zero': it is not a regular file (a character device)");
  const std::string fifo = test::temp_path("fifo.ply");
  std::filesystem::remove(fifo);
  ASSERT_TRUE(test::make_fifo(fifo));
  EXPECT_EQ(io_error([&] { scanio::load_mesh_file(fifo); }), "cannot read '" + fifo + "': it is not a regular file (a FIFO)");
  std::filesystem::remove(fifo);
}

}  // namespace
}  // namespace roomsense
