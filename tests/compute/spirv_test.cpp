// The determinism argument rests on every float add, subtract and multiply of the SAT test being exact
// IEEE operations: each must carry the NoContraction decoration (GLSL `precise`), so no driver fuses them
// into an FMA, and no shader may divide. This reads the embedded SPIR-V and checks both.
#include "spirv/count_columns.h"
#include "spirv/count_levels.h"
#include "spirv/expand_grid.h"
#include "spirv/select_levels.h"
#include "spirv/voxelize_triangles.h"
#include "spirv/voxelize_vertices.h"

#include <gtest/gtest.h>

#include <set>
#include <span>

namespace {

constexpr std::uint32_t kMagic = 0x07230203;
constexpr std::uint32_t kOpDecorate = 71, kDecorationNoContraction = 42;
constexpr std::uint32_t kOpFNegate = 127, kOpFAdd = 129, kOpFSub = 131, kOpFMul = 133, kOpFDiv = 136, kOpFRem = 141,
                        kOpFMod = 142;
constexpr std::uint32_t kOpExtInst = 12, kGlslFma = 50;

struct Stats {
  int arithmetic = 0, uncontracted = 0, divisions = 0, fma = 0;
};

Stats scan(std::span<const std::uint32_t> words) {
  Stats s;
  EXPECT_EQ(words[0], kMagic);
  std::set<std::uint32_t> no_contraction;
  std::vector<std::uint32_t> arithmetic_results;
  for (std::size_t i = 5; i < words.size();) {
    const std::uint32_t count = words[i] >> 16, op = words[i] & 0xFFFF;
    if (count == 0) break;
    if (op == kOpDecorate && words[i + 2] == kDecorationNoContraction) no_contraction.insert(words[i + 1]);
    if (op == kOpFAdd || op == kOpFSub || op == kOpFMul) arithmetic_results.push_back(words[i + 2]);
    if (op == kOpFDiv || op == kOpFRem || op == kOpFMod) ++s.divisions;
    if (op == kOpExtInst && words[i + 4] == kGlslFma) ++s.fma;
    (void)kOpFNegate;  // exact, needs no decoration
    i += count;
  }
  s.arithmetic = int(arithmetic_results.size());
  for (std::uint32_t id : arithmetic_results) s.uncontracted += no_contraction.count(id) ? 1 : 0;
  return s;
}

TEST(Spirv, TriangleTestIsPreciseAndDivisionFree) {
  const Stats s = scan(roomsense::compute::spirv::kVoxelizeTriangles);
  EXPECT_GT(s.arithmetic, 20);
  EXPECT_EQ(s.uncontracted, s.arithmetic) << "float arithmetic without NoContraction in voxelize_triangles.comp";
  EXPECT_EQ(s.divisions, 0);
  EXPECT_EQ(s.fma, 0);
}

TEST(Spirv, NoShaderDividesFloats) {
  for (std::span<const std::uint32_t> words :
       {std::span<const std::uint32_t>(roomsense::compute::spirv::kVoxelizeVertices),
        std::span<const std::uint32_t>(roomsense::compute::spirv::kExpandGrid),
        std::span<const std::uint32_t>(roomsense::compute::spirv::kCountLevels),
        std::span<const std::uint32_t>(roomsense::compute::spirv::kSelectLevels),
        std::span<const std::uint32_t>(roomsense::compute::spirv::kCountColumns)}) {
    const Stats s = scan(words);
    EXPECT_EQ(s.divisions, 0);
    EXPECT_EQ(s.uncontracted, s.arithmetic);
  }
}

}  // namespace
