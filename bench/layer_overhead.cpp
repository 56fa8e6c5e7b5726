// The roomsense layer's overhead on calls it does not intercept: xrLocateSpace in a loop through the Khronos
// loader and the simulated runtime, without the layer (DISABLE_XR_APILAYER_ROOMSENSE set, so the loader leaves
// it out), with the layer in an application that does not enable the extension, and with the extension
// enabled (the layer then captures scene meshes, but xrLocateSpace still goes straight to the runtime).
// Prints the ratios of the medians at the end.
//
//   build/bench/roomsense_bench_layer --benchmark_repetitions=20 --benchmark_min_time=0.1
//     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//
// It finds the simulated runtime and the layer in its build tree (XR_RUNTIME_JSON, XDG_DATA_HOME) unless the
// environment already names them.
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include "headless_session.h"
#include "roomsense/xr/loader_interface.h"  // layer/src: the negotiation structures

#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

enum class Variant { WithoutLayer, LayerPassThrough, LayerWithExtension };

// Whether the layer is in this instance's chain. Debian's loader keeps a layer mapped after its instance is
// gone, so being mapped is not enough: the layer's own xrGetInstanceProcAddr (reached through its one
// exported symbol) knows only the instances created through it.
bool layer_in_chain(XrInstance instance) {
  void* lib = dlopen("libXrApiLayer_roomsense.so", RTLD_NOW | RTLD_NOLOAD);
  if (lib == nullptr) return false;
  auto negotiate = reinterpret_cast<PFN_xrNegotiateLoaderApiLayerInterface>(dlsym(lib, "xrNegotiateLoaderApiLayerInterface"));
  XrNegotiateLoaderInfo loader{XR_LOADER_INTERFACE_STRUCT_LOADER_INFO, XR_LOADER_INFO_STRUCT_VERSION, sizeof(XrNegotiateLoaderInfo),
                               1, 1, XR_MAKE_VERSION(1, 0, 0), XR_MAKE_VERSION(1, 0xffff, 0xffff)};
  XrNegotiateApiLayerRequest request{XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST, XR_API_LAYER_INFO_STRUCT_VERSION,
                                     sizeof(XrNegotiateApiLayerRequest), 0, 0, nullptr, nullptr};
  PFN_xrVoidFunction f = nullptr;
  const bool in_chain = negotiate != nullptr &&
                        negotiate(&loader, "XR_APILAYER_ROOMSENSE_room_understanding", &request) == XR_SUCCESS &&
                        request.getInstanceProcAddr(instance, "xrDestroyInstance", &f) == XR_SUCCESS;
  dlclose(lib);
  return in_chain;
}

void locate_space(benchmark::State& state, Variant variant) {
  if (variant == Variant::WithoutLayer) setenv("DISABLE_XR_APILAYER_ROOMSENSE", "1", 1);
  else unsetenv("DISABLE_XR_APILAYER_ROOMSENSE");
  std::vector<const char*> extensions;
  if (variant == Variant::LayerWithExtension) extensions.push_back(XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME);
  const roomsense::bench::HeadlessSession app(extensions);
  if (layer_in_chain(app.instance) != (variant != Variant::WithoutLayer)) {
    state.SkipWithError("the layer is not (or still) in the chain: check XDG_DATA_HOME and DISABLE_XR_APILAYER_ROOMSENSE");
    return;
  }
  const XrSpace view = app.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  const XrTime time = 1'000'000'000;
  for (auto _ : state) {
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION, nullptr, 0, {}};
    benchmark::DoNotOptimize(xrLocateSpace(view, app.local, time, &location));
    benchmark::DoNotOptimize(location);
  }
}

BENCHMARK_CAPTURE(locate_space, without_layer, Variant::WithoutLayer);
BENCHMARK_CAPTURE(locate_space, layer_pass_through, Variant::LayerPassThrough);
BENCHMARK_CAPTURE(locate_space, layer_with_extension, Variant::LayerWithExtension);

// Keeps each benchmark's time per iteration (the median when repeated) for the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_Defaults : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string name = r.run_name.function_name + (r.run_name.args.empty() ? "" : "/" + r.run_name.args);
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median") medians[name] = r.GetAdjustedRealTime();
      else if (r.run_type == Run::RT_Iteration && !r.error_occurred) plain[name].push_back(r.GetAdjustedRealTime());
    }
  }
  double time_of(const std::string& name) const {
    if (auto it = medians.find(name); it != medians.end()) return it->second;
    if (auto it = plain.find(name); it != plain.end() && !it->second.empty()) return it->second.back();
    return 0.0;
  }

 private:
  std::map<std::string, double> medians;
  std::map<std::string, std::vector<double>> plain;
};

void use_build_tree_unless_set() {
  if (std::getenv("XR_RUNTIME_JSON") == nullptr) setenv("XR_RUNTIME_JSON", ROOMSENSE_BENCH_RUNTIME_MANIFEST, 1);
  if (std::getenv("XDG_DATA_HOME") == nullptr) setenv("XDG_DATA_HOME", ROOMSENSE_BENCH_LAYER_SEARCH_DIR, 1);
}

}  // namespace

int main(int argc, char** argv) {
  use_build_tree_unless_set();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const double without = reporter.time_of("locate_space/without_layer");
  const double pass = reporter.time_of("locate_space/layer_pass_through");
  const double extx = reporter.time_of("locate_space/layer_with_extension");
  if (without > 0.0) {
    std::printf("\nxrLocateSpace per call: %.1f ns without the layer\n", without);
    if (pass > 0.0) std::printf("  with the layer, extension not enabled: %.1f ns, ratio %.3f\n", pass, pass / without);
    if (extx > 0.0) std::printf("  with the layer, extension enabled:     %.1f ns, ratio %.3f\n", extx, extx / without);
  }
  benchmark::Shutdown();
  return 0;
}
