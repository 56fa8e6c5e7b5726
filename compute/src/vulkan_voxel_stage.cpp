// VulkanVoxelStage: one command buffer, one submission per run():
//   clear -> vertex voxels -> triangle voxels -> byte grid + |V_y| -> I_Floor/I_Ceiling -> |V_xz| + any
// with a barrier between dependent passes. Buffers are sized from the grid and kept for later runs.
#include "roomsense/vulkan_voxel_stage.h"

#include "roomsense/cancel.h"

#include "device_choice.h"
#include "gpu_buffer.h"
#include "triangle_work.h"
#include "voxel_pipelines.h"
#include "vulkan_context.h"
#include "vulkan_error.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace roomsense {

using namespace compute;

const char* to_string(GpuKind kind) {
  switch (kind) {
    case GpuKind::Discrete: return "discrete GPU";
    case GpuKind::Integrated: return "integrated GPU";
    case GpuKind::Virtual: return "virtual GPU";
    case GpuKind::Cpu: return "CPU";
    default: return "other";
  }
}

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vertices are uploaded as packed float triples");

using Clock = std::chrono::steady_clock;
// How often a wait for the GPU looks at the stop token.
constexpr std::uint64_t kStopSliceNs = 10'000'000;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Where each result lives in the Out buffer (shaders/common.glsl), in 32-bit words.
struct OutLayout {
  std::uint64_t grid_words = 0, levels = 0, select = 0, columns = 0, any = 0, total_words = 0;

  explicit OutLayout(const GridSpec& s) {
    grid_words = (s.voxel_count() + 3) / 4;
    levels = grid_words;
    select = levels + std::uint64_t(s.ny);
    columns = select + 8;  // 5 used
    any = columns + s.column_count();
    total_words = any + (s.column_count() + 3) / 4;
  }
};

// The timestamps written between passes.
enum Stamp : std::uint32_t { kBegin, kUploaded, kVertices, kTriangles, kLevels, kSelect, kColumns, kReadback, kStampCount };

constexpr VkMemoryPropertyFlags kDeviceLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kHostCoherent = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kHostCached = kHostCoherent | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

std::chrono::milliseconds timeout_from_env(std::chrono::milliseconds fallback) {
  const char* v = std::getenv("ROOMSENSE_VULKAN_TIMEOUT_MS");
  if (v == nullptr || *v == '\0') return fallback;
  char* end = nullptr;
  const long long ms = std::strtoll(v, &end, 10);
  return (end != nullptr && *end == '\0' && ms >= 0) ? std::chrono::milliseconds(ms) : fallback;
}

}  // namespace

class VulkanVoxelStage::Impl {
 public:
  Impl(std::unique_ptr<VulkanContext> ctx, const VulkanStageOptions& options);
  ~Impl();
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  VoxelStageResult run(const VoxelizeRequest& request);

  std::unique_ptr<VulkanContext> ctx;  // first: destroyed last
  VulkanRunTimings timings;
  std::uint64_t fallbacks = 0;

 private:
  VoxelStageResult fall_back(const VoxelizeRequest& request, const std::string& why);
  std::string unsupported_reason(const VoxelizeRequest& request) const;
  void ensure_buffers(VkDeviceSize vertex_bytes, VkDeviceSize index_bytes, VkDeviceSize bits_bytes, VkDeviceSize out_bytes);
  void record(const VoxelizeRequest& request, const PushConstants& pc, VkDeviceSize vertex_bytes,
              VkDeviceSize index_bytes, VkDeviceSize bits_bytes, VkDeviceSize out_bytes);
  void read_timestamps();
  std::pair<std::uint32_t, std::uint32_t> groups(std::uint64_t items) const;

  VoxelPipelines pipelines_;
  DeviceChild<VkDescriptorPool> descriptor_pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with the pool
  DeviceChild<VkCommandPool> command_pool_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;  // freed with the pool
  DeviceChild<VkFence> fence_;
  DeviceChild<VkQueryPool> queries_;
  // Unified memory (integrated GPUs, lavapipe): device-local memory the host can map, so the shaders read
  // the uploaded data in place and the results are read where they were written, with no staging copies.
  bool unified_ = false;
  GpuBuffer vertices_, indices_, bits_, out_;
  GpuBuffer upload_, readback_;  // staging, discrete GPUs only
  TriangleWork work_;  // the triangle pass's extra items (triangle_work.h), reused
  std::chrono::milliseconds timeout_;
  bool unusable_ = false;  // after a timeout or device loss every run goes to the CPU
  bool submitted_ = false;  // a submission not yet waited for (its run was cancelled)
  void finish_submission();
  CpuVoxelStage cpu_;
};

VulkanVoxelStage::Impl::Impl(std::unique_ptr<VulkanContext> context, const VulkanStageOptions& options)
    : ctx(std::move(context)), pipelines_(*ctx), timeout_(timeout_from_env(options.fence_timeout)) {
  const DeviceFunctions& vk = ctx->vk();
  const VkDevice device = ctx->device();

  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 1;
  dpi.poolSizeCount = 1;
  dpi.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vk.vkCreateDescriptorPool(device, &dpi, nullptr, &pool), "vkCreateDescriptorPool");
  descriptor_pool_ = DeviceChild<VkDescriptorPool>(device, pool, vk.vkDestroyDescriptorPool);
  VkDescriptorSetAllocateInfo dsai{};
  dsai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 1;
  const VkDescriptorSetLayout dsl = pipelines_.set_layout.get();
  dsai.pSetLayouts = &dsl;
  check(vk.vkAllocateDescriptorSets(device, &dsai, &set_), "vkAllocateDescriptorSets");

  VkCommandPoolCreateInfo cpi{};
  cpi.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  cpi.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  cpi.queueFamilyIndex = ctx->queue_family();
  VkCommandPool command_pool = VK_NULL_HANDLE;
  check(vk.vkCreateCommandPool(device, &cpi, nullptr, &command_pool), "vkCreateCommandPool");
  command_pool_ = DeviceChild<VkCommandPool>(device, command_pool, vk.vkDestroyCommandPool);
  VkCommandBufferAllocateInfo cbai{};
  cbai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cbai.commandPool = command_pool;
  cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cbai.commandBufferCount = 1;
  check(vk.vkAllocateCommandBuffers(device, &cbai, &cmd_), "vkAllocateCommandBuffers");

  VkFenceCreateInfo fi{};
  fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence fence = VK_NULL_HANDLE;
  check(vk.vkCreateFence(device, &fi, nullptr, &fence), "vkCreateFence");
  fence_ = DeviceChild<VkFence>(device, fence, vk.vkDestroyFence);

  if (ctx->timestamp_valid_bits() > 0) {
    VkQueryPoolCreateInfo qpi{};
    qpi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qpi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qpi.queryCount = kStampCount;
    VkQueryPool qp = VK_NULL_HANDLE;
    check(vk.vkCreateQueryPool(device, &qpi, nullptr, &qp), "vkCreateQueryPool");
    queries_ = DeviceChild<VkQueryPool>(device, qp, vk.vkDestroyQueryPool);
  }

  if (ctx->info().kind != GpuKind::Discrete) {
    const auto& mem = ctx->memory();
    for (std::uint32_t i = 0; i < mem.memoryTypeCount; ++i)
      if ((mem.memoryTypes[i].propertyFlags & (kDeviceLocal | kHostCoherent)) == (kDeviceLocal | kHostCoherent)) unified_ = true;
  }
}

VulkanVoxelStage::Impl::~Impl() {
  // The buffers and pools below must not be destroyed while a (timed-out) submission still uses them.
  if (ctx && ctx->device() != VK_NULL_HANDLE) ctx->vk().vkDeviceWaitIdle(ctx->device());
}

std::pair<std::uint32_t, std::uint32_t> VulkanVoxelStage::Impl::groups(std::uint64_t items) const {
  // One item per invocation over a 2D grid of groups (item_index() in shaders/common.glsl); 65535 groups
  // per dimension is the guaranteed limit.
  const std::uint64_t needed = std::max<std::uint64_t>(1, (items + kLocalSize - 1) / kLocalSize);
  const std::uint64_t x = std::min<std::uint64_t>(needed, 65535);
  return {std::uint32_t(x), std::uint32_t((needed + x - 1) / x)};
}

std::string VulkanVoxelStage::Impl::unsupported_reason(const VoxelizeRequest& r) const {
  const GridSpec& s = r.spec;
  if (s.voxel_count() == 0) return "the grid is empty";
  // The shaders index voxels with 32-bit integers (with headroom for the 4-voxel words).
  if (s.voxel_count() >= (std::uint64_t{1} << 31)) return "the grid has more than 2^31 voxels";
  if (s.ny > kMaxLevels) return "the grid has more than " + std::to_string(kMaxLevels) + " levels";
  if (r.indices.size() >= std::numeric_limits<std::uint32_t>::max() || r.grid_vertices.size() >= (std::uint64_t{1} << 30))
    return "the mesh is too large for 32-bit indexing";
  const std::uint64_t max_range = ctx->properties().limits.maxStorageBufferRange;
  if (OutLayout(s).total_words * 4 > max_range || r.grid_vertices.size() * 12 > max_range || r.indices.size() * 4 > max_range)
    return "a buffer would exceed the device's maxStorageBufferRange";
  return {};
}

VoxelStageResult VulkanVoxelStage::Impl::fall_back(const VoxelizeRequest& request, const std::string& why) {
  ctx->log(why + "; computing on the CPU");
  ++fallbacks;
  timings = {};
  timings.fell_back = true;
  return cpu_.run(request);
}

void VulkanVoxelStage::Impl::ensure_buffers(VkDeviceSize vertex_bytes, VkDeviceSize index_bytes, VkDeviceSize bits_bytes,
                                            VkDeviceSize out_bytes) {
  constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  constexpr VkBufferUsageFlags kDst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  constexpr VkBufferUsageFlags kSrc = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  const auto grow = [&](GpuBuffer& b, VkDeviceSize bytes, VkBufferUsageFlags usage,
                        std::initializer_list<VkMemoryPropertyFlags> prefs) {
    if (!b || b.size() < bytes) {
      b = GpuBuffer();  // free first: peak memory stays at one copy
      b = GpuBuffer(*ctx, bytes, usage, prefs);
    }
  };
  if (unified_) {
    grow(vertices_, vertex_bytes, kStorage, {kDeviceLocal | kHostCoherent});
    grow(indices_, index_bytes, kStorage, {kDeviceLocal | kHostCoherent});
    grow(out_, out_bytes, kStorage | kDst, {kDeviceLocal | kHostCached, kDeviceLocal | kHostCoherent});
  } else {
    grow(vertices_, vertex_bytes, kStorage | kDst, {kDeviceLocal, 0});
    grow(indices_, index_bytes, kStorage | kDst, {kDeviceLocal, 0});
    grow(out_, out_bytes, kStorage | kDst | kSrc, {kDeviceLocal, 0});
    grow(upload_, vertex_bytes + index_bytes, kSrc, {kHostCoherent});
    grow(readback_, out_bytes, kDst, {kHostCached, kHostCoherent});
  }
  grow(bits_, bits_bytes, kStorage | kDst, {kDeviceLocal, 0});
}

void VulkanVoxelStage::Impl::record(const VoxelizeRequest& request, const PushConstants& pc, VkDeviceSize vertex_bytes,
                                    VkDeviceSize index_bytes, VkDeviceSize bits_bytes, VkDeviceSize out_bytes) {
  const DeviceFunctions& vk = ctx->vk();
  const OutLayout out(request.spec);

  const VkDescriptorBufferInfo infos[4] = {{vertices_.get(), 0, vertex_bytes},
                                           {indices_.get(), 0, index_bytes},
                                           {bits_.get(), 0, bits_bytes},
                                           {out_.get(), 0, out_bytes}};
  VkWriteDescriptorSet writes[4]{};
  for (std::uint32_t i = 0; i < 4; ++i) {
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set_;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vk.vkUpdateDescriptorSets(ctx->device(), 4, writes, 0, nullptr);

  check(vk.vkResetCommandPool(ctx->device(), command_pool_.get(), 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vk.vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");

  const auto stamp = [&](Stamp s) {
    if (queries_) vk.vkCmdWriteTimestamp(cmd_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries_.get(), s);
  };
  const auto barrier = [&](VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage, VkAccessFlags dst) {
    VkMemoryBarrier mb{};
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    mb.srcAccessMask = src;
    mb.dstAccessMask = dst;
    vk.vkCmdPipelineBarrier(cmd_, src_stage, dst_stage, 0, 1, &mb, 0, nullptr, 0, nullptr);
  };
  constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
  constexpr VkAccessFlags kShaderRW = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  const auto compute_to_compute = [&] { barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, kCompute, kShaderRW); };
  const auto dispatch = [&](Kernel k, std::uint64_t items) {
    vk.vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[k]);
    const auto [gx, gy] = groups(items);
    vk.vkCmdDispatch(cmd_, gx, gy, 1);
  };

  if (queries_) vk.vkCmdResetQueryPool(cmd_, queries_.get(), 0, kStampCount);
  stamp(kBegin);
  // Upload (staging copies on a discrete GPU) and clears: V and the atomically summed |V_y| start at 0.
  if (!unified_) {
    const VkBufferCopy vcopy{0, 0, vertex_bytes};
    const VkBufferCopy icopy{vertex_bytes, 0, index_bytes};
    vk.vkCmdCopyBuffer(cmd_, upload_.get(), vertices_.get(), 1, &vcopy);
    vk.vkCmdCopyBuffer(cmd_, upload_.get(), indices_.get(), 1, &icopy);
  }
  vk.vkCmdFillBuffer(cmd_, bits_.get(), 0, bits_bytes, 0);
  vk.vkCmdFillBuffer(cmd_, out_.get(), out.levels * 4, (out.columns - out.levels) * 4, 0);
  barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, kCompute, kShaderRW);
  stamp(kUploaded);

  vk.vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.layout.get(), 0, 1, &set_, 0, nullptr);
  vk.vkCmdPushConstants(cmd_, pipelines_.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
  if (request.mode == VoxelMode::Vertices) {  // Eq. 3.6/3.7; triangle mode marks triangles only
    dispatch(Kernel::Vertices, pc.vertex_count);
    compute_to_compute();
  }
  stamp(kVertices);
  if (pc.work_count > 0) {
    dispatch(Kernel::Triangles, pc.work_count);
    compute_to_compute();
  }
  stamp(kTriangles);
  dispatch(Kernel::ExpandGrid, out.grid_words);  // both read V and write disjoint regions: no barrier between
  dispatch(Kernel::CountLevels, std::uint64_t(pc.ny) * ((pc.column_count + 63) / 64));  // Eq. 3.8
  compute_to_compute();
  stamp(kLevels);
  dispatch(Kernel::SelectLevels, 1);  // Eq. 3.9/3.10
  compute_to_compute();
  stamp(kSelect);
  dispatch(Kernel::CountColumns, (pc.column_count + 3) / 4);  // Eq. 3.11/3.12
  stamp(kColumns);
  if (!unified_) {
    barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, kTransfer, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy copy{0, 0, out_bytes};
    vk.vkCmdCopyBuffer(cmd_, out_.get(), readback_.get(), 1, &copy);
    barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  } else {
    barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  }
  stamp(kReadback);
  check(vk.vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
}

void VulkanVoxelStage::Impl::read_timestamps() {
  timings.gpu_timestamps = false;
  if (!queries_) return;
  std::uint64_t t[kStampCount] = {};
  if (ctx->vk().vkGetQueryPoolResults(ctx->device(), queries_.get(), 0, kStampCount, sizeof(t), t, sizeof(std::uint64_t),
                                      VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
    return;
  const std::uint32_t bits = ctx->timestamp_valid_bits();
  const std::uint64_t mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  const double ns_per_tick = ctx->properties().limits.timestampPeriod;
  const auto span_ms = [&](Stamp a, Stamp b) { return double((t[b] - t[a]) & mask) * ns_per_tick * 1e-6; };
  timings.gpu_upload_ms = span_ms(kBegin, kUploaded);
  timings.gpu_vertices_ms = span_ms(kUploaded, kVertices);
  timings.gpu_triangles_ms = span_ms(kVertices, kTriangles);
  timings.gpu_levels_ms = span_ms(kTriangles, kLevels);
  timings.gpu_select_ms = span_ms(kLevels, kSelect);
  timings.gpu_columns_ms = span_ms(kSelect, kColumns);
  timings.gpu_readback_ms = span_ms(kColumns, kReadback);
  timings.gpu_timestamps = true;
}

void VulkanVoxelStage::Impl::finish_submission() {
  if (!submitted_) return;
  const auto timeout_ns = std::uint64_t(std::chrono::nanoseconds(timeout_).count());
  if (ctx->vk().vkWaitForFences(ctx->device(), 1, fence_.address(), VK_TRUE, timeout_ns) != VK_SUCCESS) {
    unusable_ = true;
    throw std::runtime_error("a cancelled submission did not finish within " + std::to_string(timeout_.count()) + " ms");
  }
  submitted_ = false;
}

VoxelStageResult VulkanVoxelStage::Impl::run(const VoxelizeRequest& request) {
  if (unusable_) return fall_back(request, "the device timed out or was lost earlier");
  if (const std::string why = unsupported_reason(request); !why.empty()) return fall_back(request, why);
  const GridSpec& s = request.spec;
  const OutLayout out(s);
  const std::uint64_t triangles = request.mode == VoxelMode::Triangles ? request.indices.size() / 3 : 0;
  VulkanRunTimings t;
  auto t0 = Clock::now();
  // The boxes are the GPU's work: past the budget the work list alone could take gigabytes. The CPU scans
  // only near each triangle's plane, so it may still fit the budget there.
  if (!build_triangle_work(request.grid_vertices, request.indices.first(triangles * 3), s.nx, s.ny, s.nz,
                           request.test_budget, work_))
    return fall_back(request, "the triangles' boxes need more than the work budget of " +
                                  std::to_string(request.test_budget) + " triangle-voxel tests");
  const std::uint64_t tests = work_.tests;
  t.host_work_list_ms = ms_since(t0);
  const std::uint64_t index_words = triangles * 3;
  const std::uint64_t work_words = work_.extra.size();
  if (index_words + work_words >= std::numeric_limits<std::uint32_t>::max() ||
      triangles + work_words / 2 >= std::numeric_limits<std::uint32_t>::max() ||
      (index_words + work_words) * 4 > ctx->properties().limits.maxStorageBufferRange)
    return fall_back(request, "the triangle work list is too large for one buffer");
  // Empty inputs still get a (small) buffer: a zero-sized VkBuffer is invalid.
  const VkDeviceSize vertex_bytes = std::max<VkDeviceSize>(16, request.grid_vertices.size() * sizeof(glm::vec3));
  const VkDeviceSize index_bytes = std::max<VkDeviceSize>(16, (index_words + work_words) * sizeof(std::uint32_t));
  const VkDeviceSize bits_bytes = ((s.voxel_count() + 31) / 32) * 4;
  const VkDeviceSize out_bytes = out.total_words * 4;

  PushConstants pc{};
  pc.nx = s.nx;
  pc.ny = s.ny;
  pc.nz = s.nz;
  pc.vertex_count = std::uint32_t(request.grid_vertices.size());
  pc.work_count = std::uint32_t(triangles + work_words / 2);  // one item per triangle, then the extra ones
  pc.work_offset = std::uint32_t(index_words);
  pc.voxel_count = std::uint32_t(s.voxel_count());
  pc.column_count = std::uint32_t(s.column_count());
  pc.min_separation = request.min_separation_levels;
  pc.grid_offset = 0;
  pc.levels_offset = std::uint32_t(out.levels);
  pc.select_offset = std::uint32_t(out.select);
  pc.columns_offset = std::uint32_t(out.columns);
  pc.any_offset = std::uint32_t(out.any);

  try {
    const DeviceFunctions& vk = ctx->vk();
    finish_submission();  // a cancelled run's work still owns the buffers
    ensure_buffers(vertex_bytes, index_bytes, bits_bytes, out_bytes);

    t0 = Clock::now();
    auto* vertex_dst = static_cast<std::byte*>(unified_ ? vertices_.mapped() : upload_.mapped());
    auto* index_dst = unified_ ? static_cast<std::byte*>(indices_.mapped()) : vertex_dst + vertex_bytes;
    if (vertex_dst == nullptr || index_dst == nullptr) throw std::runtime_error("upload memory is not mapped");
    if (!request.grid_vertices.empty())
      std::memcpy(vertex_dst, request.grid_vertices.data(), request.grid_vertices.size() * sizeof(glm::vec3));
    if (index_words > 0) std::memcpy(index_dst, request.indices.data(), index_words * sizeof(std::uint32_t));
    if (work_words > 0) std::memcpy(index_dst + index_words * 4, work_.extra.data(), work_words * sizeof(std::uint32_t));
    t.host_upload_ms = ms_since(t0);

    t0 = Clock::now();
    record(request, pc, vertex_bytes, index_bytes, bits_bytes, out_bytes);
    check(vk.vkResetFences(ctx->device(), 1, fence_.address()), "vkResetFences");
    VkSubmitInfo si{};
    si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd_;
    check(vk.vkQueueSubmit(ctx->queue(), 1, &si, fence_.get()), "vkQueueSubmit");  // the one submission
    submitted_ = true;
    // Waited for in short slices: a stop request returns at once, and the submission, which cannot be
    // recalled, is waited for by the next run or the destructor (the budget bounds how long it runs).
    const auto deadline = Clock::now() + timeout_;
    VkResult waited = VK_TIMEOUT;
    while (waited == VK_TIMEOUT && Clock::now() < deadline) {
      stop_point(request.stop);
      waited = vk.vkWaitForFences(ctx->device(), 1, fence_.address(), VK_TRUE, kStopSliceNs);
    }
    if (waited == VK_TIMEOUT) {
      unusable_ = true;
      return fall_back(request, "the GPU did not finish within " + std::to_string(timeout_.count()) + " ms");
    }
    check(waited, "vkWaitForFences");
    submitted_ = false;
    t.submit_wait_ms = ms_since(t0);

    t0 = Clock::now();
    const auto* src = static_cast<const std::byte*>(unified_ ? out_.mapped() : readback_.mapped());
    if (src == nullptr) throw std::runtime_error("readback memory is not mapped");
    const auto words = [&](std::uint64_t offset) { return src + offset * 4; };
    VoxelStageResult r;
    r.voxel_tests = tests;
    r.grid = VoxelGrid(s);
    std::memcpy(r.grid.cells.data(), words(0), s.voxel_count());
    r.level_counts.resize(std::size_t(s.ny));
    std::memcpy(r.level_counts.data(), words(out.levels), std::size_t(s.ny) * 4);
    std::uint32_t sel[5];
    std::memcpy(sel, words(out.select), sizeof(sel));
    if (sel[0] != 0) r.levels = FloorCeiling{int(sel[1]), int(sel[2]), int(sel[3]), int(sel[4])};
    r.column_counts.resize(s.column_count());
    std::memcpy(r.column_counts.data(), words(out.columns), s.column_count() * 4);
    r.column_any.resize(s.column_count());
    std::memcpy(r.column_any.data(), words(out.any), s.column_count());  // bytes, packed in order
    t.host_readback_ms = ms_since(t0);
    timings = t;
    read_timestamps();
    return r;
  } catch (const Error&) {
    throw;  // cancelled: no fallback
  } catch (const VulkanError& e) {
    if (e.result() == VK_ERROR_DEVICE_LOST) unusable_ = true;
    return fall_back(request, e.what());
  } catch (const std::exception& e) {
    return fall_back(request, e.what());
  }
}

VulkanVoxelStage::VulkanVoxelStage(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VulkanVoxelStage::~VulkanVoxelStage() = default;

std::unique_ptr<VulkanVoxelStage> VulkanVoxelStage::create(const VulkanStageOptions& options, std::string* why_not) {
  ContextOptions co;
  co.validation = options.validation;
  co.require_validation = options.require_validation;
  co.log = options.log;
  std::unique_ptr<VulkanContext> ctx = VulkanContext::create(co, why_not);
  if (!ctx) return nullptr;
  try {
    return std::unique_ptr<VulkanVoxelStage>(new VulkanVoxelStage(std::make_unique<Impl>(std::move(ctx), options)));
  } catch (const std::exception& e) {
    if (why_not != nullptr) *why_not = e.what();
    return nullptr;
  }
}

VoxelStageResult VulkanVoxelStage::run(const VoxelizeRequest& request) { return impl_->run(request); }
const VulkanDeviceInfo& VulkanVoxelStage::device() const { return impl_->ctx->info(); }
bool VulkanVoxelStage::validation_enabled() const { return impl_->ctx->validation_enabled(); }
std::uint64_t VulkanVoxelStage::validation_messages() const { return impl_->ctx->validation_messages(); }
const VulkanRunTimings& VulkanVoxelStage::last_timings() const { return impl_->timings; }
std::uint64_t VulkanVoxelStage::fallbacks() const { return impl_->fallbacks; }

std::optional<VulkanDeviceInfo> probe_vulkan_device(std::string* why_not) {
  ContextOptions co;
  co.create_device = false;
  std::unique_ptr<VulkanContext> ctx = VulkanContext::create(co, why_not);
  if (!ctx) return std::nullopt;
  return ctx->info();
}

}  // namespace roomsense
