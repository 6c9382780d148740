#pragma once
// Everything one headless render needs, built in order and torn down in reverse:
// device, shader compiler, pass registry, executor, scene on the GPU, frame loop.
// Shared by every command that renders (render, bench, quality, techniques) and the
// editor, windowed or headless.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fgvk/executor.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/frame_loop.hpp"
#include "antumbra/gpu/pipeline_cache.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/data_paths.hpp"
#include "antumbra/runtime/trace_writer.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/gpu_scene.hpp"

namespace antumbra::runtime {

struct SessionOptions {
  std::string device = "auto";
  bool validation = false;
  VkExtent2D viewport{1280, 720};
  // The windowed editor: surface extensions (GLFW's) and VK_KHR_swapchain on the device.
  std::vector<std::string> instance_extensions;
  bool present = false;
  // Under a graphics debugger (RenderDoc), capture the last frame of every render() call:
  // frames rendered headless have no present at which the debugger would capture.
  bool capture_last_frame = false;
  // A host's own pass types (docs/adding-a-pass.md, "A pass type from outside the tree"):
  // the folders of their GLSL, searched after the built-in passes/ folder and in this order,
  // for a pass's shader files and for #include; and the call that registers them, after the
  // built-in types. A type named like one already registered throws
  // fgvk::DuplicatePassType, out of the session's constructor.
  std::vector<std::filesystem::path> shader_dirs;
  std::function<void(fgvk::PassRegistry&)> register_passes;
  // The host's device (docs/integration.md, "The host's device"): when set, the session
  // borrows it instead of creating an instance and device (device, validation,
  // instance_extensions and present are then unused), and throws gpu::HostDeviceError
  // naming what the device lacks.
  std::optional<gpu::HostDevice> host_device;
  // Frames the host (or render()) records before waiting for the oldest to finish: the
  // per-frame buffers and timestamp queries rotate over this many slots.
  std::uint32_t frames_in_flight = gpu::FrameLoop::kDefaultFramesInFlight;
  // The host's pipeline cache, used instead of the session's own when set.
  VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
  // Also time the steps inside passes (every label a pass opens: a shadow pass's cull,
  // raster and resolve): step_timings(). A timestamp pair per step costs a little.
  bool time_steps = false;
  // Timings keep the samples of the latest frames only, between this many and twice as
  // many per pass (and step), so that a session running for hours (render --watch, the
  // headless editor) holds bounded memory: pass_timings() is then the median of those
  // latest frames. reset_timings() starts over.
  std::size_t timing_window = 8192;
};

// What the host's submission of a frame record() filled must signal (docs/integration.md,
// "The frame"): `value` on the timeline semaphore `semaphore`, as a
// signal semaphore with VkTimelineSemaphoreSubmitInfo (or synchronization2's submit info).
struct HostSubmission {
  VkSemaphore semaphore = VK_NULL_HANDLE;
  std::uint64_t value = 0;
};

// The pass types a session with `options` runs: the built-in ones, then the host's
// (options.register_passes). Needs no device: its reflection() is what the schema, the
// pass reference, validate (fg::compile_graph) and the editor's parameter panels read.
[[nodiscard]] fgvk::PassRegistry pass_registry(const SessionOptions& options);

struct PassTiming {
  std::string name;
  std::string type;
  double gpu_ms = 0.0;              // median over the timed frames
  double cpu_ms = 0.0;              // recording time, median
  std::vector<double> gpu_samples;  // every timed frame, in order (bench's percentiles)
};

class RenderSession {
 public:
  RenderSession(const DataPaths& paths, const SessionOptions& options);
  ~RenderSession();

  // The one load path from a graph file to the running graph (docs/architecture.md, "One
  // load path"): fg::read_graph, the host's `edit` (an output of its choice, overrides),
  // then load_graph below. Every command and the editor load graph files through it or
  // through its two halves. Diagnostics carry file, line:column and JSON Pointer; on
  // errors the previous graph keeps running.
  base::Diagnostics load_graph(const fg::GraphSource& source, const fg::GraphEdit& edit = {});
  // Compiles and realises a graph already read (or built in code). On errors (graph or
  // shader diagnostics, FG100 when the device cannot hold it) returns them and keeps the
  // previous graph running.
  base::Diagnostics load_graph(const fg::GraphDesc& graph);
  void set_scene(scene::Scene scene);
  // The scene file's object motions start over: the next frame recorded puts every dynamic
  // object with a motion where its frame 0 does. Without it they follow the frames recorded
  // since the session began (so an editor's scene edits do not make them jump); bench calls
  // it per scenario, so a row measures the same frames whatever ran before it.
  void restart_motion();
  // Lights only (the editor's edits): geometry stays uploaded, so the static shadow
  // cache keeps every face a changed light does not reach.
  void set_lights(std::vector<scene::PointLight> lights);
  // The camera (the editor's navigation): per-frame data, takes effect next frame.
  void set_camera(const scene::Camera& camera);
  // The host's window changed size (docs/integration.md, "Resize"): reloads the live
  // graph at `viewport` (kept resources of a fixed size carry over; the viewport-sized
  // ones are made anew). Imported images of the old size are unbound (a note says so):
  // bind the new ones before the next record(). On errors the previous graph and
  // viewport stay. Before any graph is loaded it only sets the viewport.
  base::Diagnostics resize(VkExtent2D viewport);
  // A new viewport takes effect at the next load_graph().
  void set_viewport(VkExtent2D viewport) { options_.viewport = viewport; }
  [[nodiscard]] VkExtent2D viewport() const { return options_.viewport; }
  // Forget the timings gathered so far (after warm-up frames).
  void reset_timings();
  // How many frames' samples the timings hold now (at most twice
  // SessionOptions::timing_window).
  [[nodiscard]] std::size_t timing_samples() const;

  // Called with the frame's index in this render() call before the frame reads the
  // scene: per-frame changes (bench's moving lights, through set_lights) without leaving
  // the loop, so frames stay pipelined as in a real application.
  using BeforeFrame = std::function<void(int frame)>;
  // Renders `frames` frames; per-pass timings are gathered from every frame.
  void render(int frames, TraceWriter* trace = nullptr, const BeforeFrame& before_frame = {});
  [[nodiscard]] std::vector<PassTiming> pass_timings() const;
  // With SessionOptions::time_steps: per step (a label inside a pass, named as the pass
  // names it, e.g. "shadowMaps.rasterDepth"), its GPU time summed over the frame (a step
  // recorded once per chunk counts once per frame), in the order steps first ran; type is
  // the pass's name. Empty without time_steps.
  [[nodiscard]] std::vector<PassTiming> step_timings() const;
  // What the passes reported about the last rendered frame.
  [[nodiscard]] const fgvk::FrameReport& last_report() const { return report_; }
  // The same messages as diagnostics located in the live graph's file: at the parameter
  // a message names (a layer-cap warning at /passes/N/params/maxLayers), else its pass, so reports
  // print them like any other diagnostic and JSON reports carry one list.
  [[nodiscard]] base::Diagnostics frame_diagnostics() const;

  // The host's frame (docs/integration.md, "The frame"): records the graph's passes into
  // the host's command buffer, which is recording and which the host then submits, before
  // its next call into the session, signalling the returned value. Waits while the frame
  // `frames_in_flight` earlier is still running. Throws std::logic_error before a scene
  // and a graph are loaded or while an imported resource has no image bound; after an
  // exception the command buffer holds part of a frame and must not be submitted.
  HostSubmission record(VkCommandBuffer cmd);
  // Binds the host's image to a resource the graph declares "import": true, for every
  // frame until bound again (rebind per frame for a swapchain image) and for graphs loaded
  // later. A name the live graph does not import, or an image that does not fit the
  // resource (format, extent, layers, usage), is FG101 located at the resource and binds
  // nothing. Before any graph is loaded the image is kept and checked at load_graph.
  base::Diagnostics bind_image(const std::string& resource, const fgvk::ImportedImage& image);

  // Writes a graph image to PNG (or PFM when the path ends in .pfm).
  void write_image(const std::string& resource, const std::string& path);

  // The pass types this session runs (pass_registry(options)).
  [[nodiscard]] const fgvk::PassRegistry& pass_registry() const { return *registry_; }
  [[nodiscard]] gpu::Context& gpu() { return *gpu_; }
  [[nodiscard]] const fgvk::Executor& executor() const { return *executor_; }
  // Tests load hand-edited plans through it (tests/gpu/executor_sources_test.cpp).
  [[nodiscard]] fgvk::Executor& executor() { return *executor_; }

  // Moves a mesh of the scene that was built dynamic (scene::SceneBuilder::add_mesh's
  // `dynamic`, a scene file's "dynamic" object without a motion): takes effect next frame
  // through the dynamic meshes' re-upload, and only the shadow faces its old or new bounds
  // reach redraw (docs/integration.md, "The host's scene through calls"). Throws
  // std::invalid_argument naming the mesh when it is out of range, static or moved by a
  // scene file's motion, or the transform is not finite or singular (scene::set_mesh_transform).
  void set_mesh_transform(std::size_t mesh, const glm::mat4& transform);

 private:
  class Observer;
  [[noreturn]] void throw_device_lost_at_submission(const gpu::VulkanError& e) const;
  void record_frame(VkCommandBuffer cmd);
  // FG101 errors for each image bound to an import of `plan` that does not fit it; an
  // image that differs only in extent (a resize) is a note, and its name goes to `stale`,
  // to be unbound once the plan is live.
  [[nodiscard]] base::Diagnostics check_bound_imports(const fg::Plan& plan,
                                                      const base::JsonDocument& document,
                                                      std::vector<std::string>& stale) const;
  DataPaths paths_;
  SessionOptions options_;
  std::unique_ptr<gpu::Context> gpu_;
  std::unique_ptr<gpu::ShaderCompiler> shaders_;
  std::unique_ptr<gpu::PipelineCache> pipeline_cache_;
  std::unique_ptr<fgvk::PassRegistry> registry_;
  std::unique_ptr<fgvk::Executor> executor_;
  std::unique_ptr<gpu::FrameLoop> frames_;
  std::unique_ptr<gpu::GpuTimer> timer_;
  std::optional<scene::Scene> scene_;
  std::unique_ptr<passes::GpuScene> gpu_scene_;
  std::unique_ptr<Observer> observer_;
  fgvk::FrameReport report_;
  base::JsonDocument live_document_;         // the source of the graph that is running
  std::optional<fg::GraphDesc> live_graph_;  // the graph that is running, for resize()
  std::uint64_t motion_frame_ = 0;           // frames recorded since restart_motion
};

}  // namespace antumbra::runtime
