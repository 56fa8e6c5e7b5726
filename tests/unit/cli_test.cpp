// `roomsense analyze` as a user runs it: exit codes, one clear stderr line on bad input, the JSON.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

struct CliRun {
  int status = -1;
  std::string err;
};

// Per-process file names: ctest runs tests of this binary in parallel processes.
std::string temp_path(const std::string& name) { return testing::TempDir() + "/" + std::to_string(getpid()) + "_" + name; }

CliRun run_cli(const std::string& args) {
  const std::string err_path = temp_path("cli_stderr.txt");
  const std::string cmd = std::string(ROOMSENSE_CLI) + " " + args + " >/dev/null 2>" + err_path;
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err_path);
  r.err.assign(std::istreambuf_iterator<char>(in), {});
  return r;
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(Cli, AnalyzesTheBuiltInRoomIntoJsonAndBounds) {
  const std::string json = temp_path("default.json"), glb = temp_path("default.glb");
  const CliRun r = run_cli("analyze synthetic:default --json " + json + " --bounds " + glb);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(json);
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["status"], "ok");
  EXPECT_NEAR(doc["ceiling_y"].get<double>() - doc["floor_y"].get<double>(), 2.6, 0.05);
  std::ifstream bounds(glb, std::ios::binary);
  char magic[4] = {};
  bounds.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");
}

TEST(Cli, BadInputGetsOneClearLineAndAnErrorStatus) {
  const std::string nan_obj = write_file("nan.obj", "v nan 0 0\nv 0 nan 0\nv 0 0 nan\nf 1 2 3\n");
  const std::string empty_obj = write_file("empty.obj", "");
  const std::string garbage = write_file("garbage.ply", "this is not a ply file\n");
  const std::string flat = write_file("flat.obj", "v 0 0 0\nv 4 0 0\nv 4 0 4\nv 0 0 4\nf 1 3 2\nf 1 4 3\n");
  // A header that claims a billion vertices in a tiny file: refused before anything is allocated for them.
  const std::string huge = write_file("huge.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\n"
                                                  "property float y\nproperty float z\nend_header\n0 0 0\n");
  const std::string bad_index = write_file("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  for (const std::string& args : std::vector<std::string>{"analyze /no/such/file.obj", "analyze " + nan_obj, "analyze " + empty_obj,
                                  "analyze " + garbage, "analyze " + flat, "analyze " + huge, "analyze " + bad_index, "analyze synthetic:nope",
                                  "analyze synthetic:default --voxel 0", "analyze synthetic:default --voxel 1e9"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("roomsense analyze: "), std::string::npos) << r.err;
  }
}

TEST(Cli, BadUsageGetsStatus2) {
  for (const char* args : {"", "frobnicate", "analyze", "analyze a.obj --up w", "analyze a.obj --voxel x",
                           "analyze a.obj --threads -1", "analyze a.obj b.obj", "analyze a.obj --json"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  }
  EXPECT_EQ(run_cli("--help").status, 0);
  EXPECT_EQ(run_cli("analyze --help").status, 0);
}

}  // namespace
