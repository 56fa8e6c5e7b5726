// VulkanVoxelStage: one command buffer per submission, one submission per run() in vertex mode:
//   clear -> vertex voxels -> byte grid + |V_y| -> I_Floor/I_Ceiling -> |V_xz| + any
// and two in triangle mode: first clear -> every triangle's first chunk, sizing the rest -> read back the
// big boxes; then their further chunks -> byte grid + |V_y| -> ... as above. A barrier separates dependent
// passes. Buffers are sized from the grid and the mesh and kept for later runs.
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

// The timestamps written between passes. The first submission writes kBegin to kFirstChunks (in vertex mode
// the only one writes them, the first chunks' span empty), the second kResumed on.
enum Stamp : std::uint32_t {
  kBegin, kUploaded, kFirstChunks, kResumed, kUploadedExtras, kVertices, kTriangles, kLevels, kSelect, kColumns,
  kReadback, kStampCount
};

// The bytes of one run's buffers.
struct Sizes {
  VkDeviceSize vertices = 0, indices = 0;
  VkDeviceSize grid_bits = 0, bits = 0;  // V's bits, and with the triangle pass's sizing after them
  VkDeviceSize info = 0;                 // that sizing: test count (2 words), big boxes, their triangles
  VkDeviceSize out = 0, extras = 0;      // results, and the extra items after them
};

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
  void grow(GpuBuffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage,
            std::initializer_list<VkMemoryPropertyFlags> preferences);
  void ensure_buffers(const Sizes& z);
  void begin_recording(const Sizes& z);
  void record_upload(const Sizes& z, VkDeviceSize clear);
  void record_first(const PushConstants& pc, const Sizes& z);
  void record_main(const VoxelizeRequest& request, const PushConstants& pc, const Sizes& z);
  bool submit_and_wait(const VoxelizeRequest& request);  // false: the GPU did not finish in time
  void stamp(Stamp s);
  void barrier(VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage, VkAccessFlags dst);
  void dispatch(Kernel k, std::uint64_t items);
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
  GpuBuffer info_readback_;      // the triangle pass's sizing, read between the submissions
  std::vector<std::uint32_t> big_, extra_;  // big boxes' triangles and their further chunks (triangle_work.h)
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

void VulkanVoxelStage::Impl::grow(GpuBuffer& b, VkDeviceSize bytes, VkBufferUsageFlags usage,
                                  std::initializer_list<VkMemoryPropertyFlags> prefs) {
  if (!b || b.size() < bytes) {
    b = GpuBuffer();  // free first: peak memory stays at one copy
    b = GpuBuffer(*ctx, bytes, usage, prefs);
  }
}

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kDst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkBufferUsageFlags kSrc = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

void VulkanVoxelStage::Impl::ensure_buffers(const Sizes& z) {
  const VkDeviceSize out_bytes = z.out + z.extras;
  if (unified_) {
    grow(vertices_, z.vertices, kStorage, {kDeviceLocal | kHostCoherent});
    grow(indices_, z.indices, kStorage, {kDeviceLocal | kHostCoherent});
    grow(out_, out_bytes, kStorage | kDst, {kDeviceLocal | kHostCached, kDeviceLocal | kHostCoherent});
  } else {
    grow(vertices_, z.vertices, kStorage | kDst, {kDeviceLocal, 0});
    grow(indices_, z.indices, kStorage | kDst, {kDeviceLocal, 0});
    grow(out_, out_bytes, kStorage | kDst | kSrc, {kDeviceLocal, 0});
    grow(upload_, std::max(z.vertices + z.indices, z.extras), kSrc, {kHostCoherent});
    grow(readback_, z.out, kDst, {kHostCached, kHostCoherent});
  }
  grow(bits_, z.bits, kStorage | kDst | kSrc, {kDeviceLocal, 0});
  if (z.info > 0) grow(info_readback_, z.info, kDst, {kHostCached, kHostCoherent});
}

void VulkanVoxelStage::Impl::stamp(Stamp s) {
  if (queries_) ctx->vk().vkCmdWriteTimestamp(cmd_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries_.get(), s);
}

void VulkanVoxelStage::Impl::barrier(VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage,
                                     VkAccessFlags dst) {
  VkMemoryBarrier mb{};
  mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  mb.srcAccessMask = src;
  mb.dstAccessMask = dst;
  ctx->vk().vkCmdPipelineBarrier(cmd_, src_stage, dst_stage, 0, 1, &mb, 0, nullptr, 0, nullptr);
}

void VulkanVoxelStage::Impl::dispatch(Kernel k, std::uint64_t items) {
  const DeviceFunctions& vk = ctx->vk();
  vk.vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[k]);
  const auto [gx, gy] = groups(items);
  vk.vkCmdDispatch(cmd_, gx, gy, 1);
}

constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kShaderRW = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;

// Binds this run's buffers and opens the command buffer (the previous submission has finished).
void VulkanVoxelStage::Impl::begin_recording(const Sizes& z) {
  const DeviceFunctions& vk = ctx->vk();
  const VkDescriptorBufferInfo infos[4] = {{vertices_.get(), 0, z.vertices},
                                           {indices_.get(), 0, z.indices},
                                           {bits_.get(), 0, z.bits},
                                           {out_.get(), 0, z.out + z.extras}};
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
}

// Resets the timestamps, then uploads (staging copies on a discrete GPU) and clears the first `clear` bytes of
// the bit buffer. The caller adds the barrier before the shaders.
void VulkanVoxelStage::Impl::record_upload(const Sizes& z, VkDeviceSize clear) {
  const DeviceFunctions& vk = ctx->vk();
  if (queries_) vk.vkCmdResetQueryPool(cmd_, queries_.get(), 0, kStampCount);
  stamp(kBegin);
  if (!unified_) {
    const VkBufferCopy vcopy{0, 0, z.vertices};
    const VkBufferCopy icopy{z.vertices, 0, z.indices};
    vk.vkCmdCopyBuffer(cmd_, upload_.get(), vertices_.get(), 1, &vcopy);
    vk.vkCmdCopyBuffer(cmd_, upload_.get(), indices_.get(), 1, &icopy);
  }
  vk.vkCmdFillBuffer(cmd_, bits_.get(), 0, clear, 0);
}

// Upload and the clears of V and the sizing, then every triangle's first chunk, and the sizing copied to where
// the host reads it.
void VulkanVoxelStage::Impl::record_first(const PushConstants& pc, const Sizes& z) {
  const DeviceFunctions& vk = ctx->vk();
  begin_recording(z);
  record_upload(z, z.grid_bits + 3 * 4);  // V, the test count, the big boxes' count
  barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, kCompute, kShaderRW);
  stamp(kUploaded);
  vk.vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.layout.get(), 0, 1, &set_, 0, nullptr);
  vk.vkCmdPushConstants(cmd_, pipelines_.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
  dispatch(Kernel::Triangles, pc.triangle_count);
  stamp(kFirstChunks);
  barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, kTransfer, VK_ACCESS_TRANSFER_READ_BIT);
  const VkBufferCopy copy{z.grid_bits, 0, z.info};
  vk.vkCmdCopyBuffer(cmd_, bits_.get(), info_readback_.get(), 1, &copy);
  barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  check(vk.vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
}

void VulkanVoxelStage::Impl::record_main(const VoxelizeRequest& request, const PushConstants& pc, const Sizes& z) {
  const DeviceFunctions& vk = ctx->vk();
  const OutLayout out(request.spec);
  begin_recording(z);
  if (pc.triangle_count == 0) {  // the only submission: it uploads and clears V, the first chunks' span empty
    record_upload(z, z.grid_bits);
    stamp(kUploaded);
    stamp(kFirstChunks);
  }
  stamp(kResumed);
  if (!unified_ && z.extras > 0) {
    const VkBufferCopy ecopy{0, z.out, z.extras};
    vk.vkCmdCopyBuffer(cmd_, upload_.get(), out_.get(), 1, &ecopy);
  }
  vk.vkCmdFillBuffer(cmd_, out_.get(), out.levels * 4, (out.columns - out.levels) * 4, 0);  // |V_y| is summed
  barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, kCompute, kShaderRW);
  stamp(kUploadedExtras);

  vk.vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.layout.get(), 0, 1, &set_, 0, nullptr);
  vk.vkCmdPushConstants(cmd_, pipelines_.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
  const auto compute_to_compute = [&] { barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, kCompute, kShaderRW); };
  if (request.mode == VoxelMode::Vertices) {  // Eq. 3.6/3.7; triangle mode marks triangles only
    dispatch(Kernel::Vertices, pc.vertex_count);
    compute_to_compute();
  }
  stamp(kVertices);
  if (pc.work_count > pc.item_base) {  // the big boxes' further chunks
    dispatch(Kernel::Triangles, pc.work_count - pc.item_base);
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
    const VkBufferCopy copy{0, 0, z.out};
    vk.vkCmdCopyBuffer(cmd_, out_.get(), readback_.get(), 1, &copy);
    barrier(kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  } else {
    barrier(kCompute, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  }
  stamp(kReadback);
  check(vk.vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
}

bool VulkanVoxelStage::Impl::submit_and_wait(const VoxelizeRequest& request) {
  const DeviceFunctions& vk = ctx->vk();
  check(vk.vkResetFences(ctx->device(), 1, fence_.address()), "vkResetFences");
  VkSubmitInfo si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd_;
  check(vk.vkQueueSubmit(ctx->queue(), 1, &si, fence_.get()), "vkQueueSubmit");
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
    return false;
  }
  check(waited, "vkWaitForFences");
  submitted_ = false;
  return true;
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
  timings.gpu_upload_ms = span_ms(kBegin, kUploaded) + span_ms(kResumed, kUploadedExtras);
  timings.gpu_vertices_ms = span_ms(kUploadedExtras, kVertices);
  timings.gpu_triangles_ms = span_ms(kUploaded, kFirstChunks) + span_ms(kVertices, kTriangles);
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
  const std::uint64_t index_words = triangles * 3;
  const std::uint64_t grid_bit_words = (s.voxel_count() + 31) / 32;
  const std::uint64_t max_range = ctx->properties().limits.maxStorageBufferRange;
  Sizes z;
  // Empty inputs still get a (small) buffer: a zero-sized VkBuffer is invalid.
  z.vertices = std::max<VkDeviceSize>(16, request.grid_vertices.size() * sizeof(glm::vec3));
  z.indices = std::max<VkDeviceSize>(16, index_words * sizeof(std::uint32_t));
  z.grid_bits = grid_bit_words * 4;
  z.info = triangles > 0 ? (3 + triangles) * 4 : 0;
  z.bits = z.grid_bits + std::max<VkDeviceSize>(z.info, 16);
  z.out = out.total_words * 4;
  if (z.bits > max_range) return fall_back(request, "the grid and the triangle sizing exceed the device's maxStorageBufferRange");

  PushConstants pc{};
  pc.nx = s.nx;
  pc.ny = s.ny;
  pc.nz = s.nz;
  pc.vertex_count = std::uint32_t(request.grid_vertices.size());
  pc.work_count = std::uint32_t(triangles);
  pc.work_offset = std::uint32_t(out.total_words);
  pc.voxel_count = std::uint32_t(s.voxel_count());
  pc.column_count = std::uint32_t(s.column_count());
  pc.min_separation = request.min_separation_levels;
  pc.grid_offset = 0;
  pc.levels_offset = std::uint32_t(out.levels);
  pc.select_offset = std::uint32_t(out.select);
  pc.columns_offset = std::uint32_t(out.columns);
  pc.any_offset = std::uint32_t(out.any);
  pc.item_base = 0;
  pc.triangle_count = std::uint32_t(triangles);
  pc.info_offset = std::uint32_t(grid_bit_words);

  VulkanRunTimings t;
  const auto timed_out = [&] {
    return fall_back(request, "the GPU did not finish within " + std::to_string(timeout_.count()) + " ms");
  };
  try {
    finish_submission();  // a cancelled run's work still owns the buffers
    extra_.clear();
    ensure_buffers(z);

    auto t0 = Clock::now();
    auto* vertex_dst = static_cast<std::byte*>(unified_ ? vertices_.mapped() : upload_.mapped());
    auto* index_dst = unified_ ? static_cast<std::byte*>(indices_.mapped()) : vertex_dst + z.vertices;
    if (vertex_dst == nullptr || index_dst == nullptr) throw std::runtime_error("upload memory is not mapped");
    if (!request.grid_vertices.empty())
      std::memcpy(vertex_dst, request.grid_vertices.data(), request.grid_vertices.size() * sizeof(glm::vec3));
    if (index_words > 0) std::memcpy(index_dst, request.indices.data(), index_words * sizeof(std::uint32_t));
    t.host_upload_ms = ms_since(t0);

    std::uint64_t tests = 0;
    if (triangles > 0) {
      t0 = Clock::now();
      record_first(pc, z);
      if (!submit_and_wait(request)) return timed_out();
      t.submit_wait_ms = ms_since(t0);

      // The boxes are the GPU's work: past the budget the extra items alone could take gigabytes. The CPU
      // scans only near each triangle's plane, so it may still fit the budget there. The first chunks, done
      // already, cost at most kChunkVoxels tests per triangle.
      t0 = Clock::now();
      const auto* info = static_cast<const std::uint32_t*>(info_readback_.mapped());
      if (info == nullptr) throw std::runtime_error("readback memory is not mapped");
      tests = std::uint64_t(info[0]) | (std::uint64_t(info[1]) << 32);
      if (tests > request.test_budget)
        return fall_back(request, "the triangles' boxes need " + std::to_string(tests) +
                                      " triangle-voxel tests, more than the work budget of " +
                                      std::to_string(request.test_budget));
      big_.clear();
      for (std::uint64_t i = 0; i < std::min<std::uint64_t>(info[2], triangles); ++i)
        if (info[3 + i] < triangles) big_.push_back(info[3 + i]);
      list_extra_chunks(request.grid_vertices, request.indices.first(index_words), s.nx, s.ny, s.nz, big_, extra_);
      z.extras = extra_.size() * sizeof(std::uint32_t);
      if (out.total_words + extra_.size() >= std::numeric_limits<std::uint32_t>::max() ||
          triangles + extra_.size() / 2 >= std::numeric_limits<std::uint32_t>::max() || z.out + z.extras > max_range)
        return fall_back(request, "the triangle work list is too large for one buffer");
      if (z.extras > 0) {
        ensure_buffers(z);  // out_ (and the staging buffer) may grow; the first submission used neither
        auto* extras_dst = unified_ ? static_cast<std::byte*>(out_.mapped()) + z.out : static_cast<std::byte*>(upload_.mapped());
        if (extras_dst == nullptr) throw std::runtime_error("upload memory is not mapped");
        std::memcpy(extras_dst, extra_.data(), z.extras);
      }
      t.host_work_list_ms = ms_since(t0);
    }
    pc.item_base = std::uint32_t(triangles);
    pc.work_count = std::uint32_t(triangles + extra_.size() / 2);

    t0 = Clock::now();
    record_main(request, pc, z);
    if (!submit_and_wait(request)) return timed_out();
    t.submit_wait_ms += ms_since(t0);

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
