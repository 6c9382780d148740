#include "antumbra/runtime/render_session.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan_memory.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/memory_heaps.hpp"
#include "antumbra/gpu/pipeline_cache.hpp"
#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_builder.hpp"
#include "register_builtin_passes.hpp"

namespace antumbra::runtime {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace

// Opens a GPU timestamp scope and measures CPU recording time around each pass; with
// steps, every label the pass opens becomes a nested scope (gpu::LabelScopes).
class RenderSession::Observer final : public fgvk::PassObserver {
 public:
  Observer(gpu::Context& gpu, gpu::GpuTimer& timer, bool steps, std::size_t window)
      : gpu_(gpu),
        timer_(timer),
        labels_(timer),
        steps_(steps),
        window_(std::max<std::size_t>(window, 1)) {}

  void begin_pass(VkCommandBuffer cmd, const fg::PlanPass& pass) override {
    scope_ = timer_.begin_scope(cmd, pass.name);
    if (steps_) gpu_.set_label_listener(&labels_);
    cpu_.restart();
  }
  void end_pass(VkCommandBuffer cmd, const fg::PlanPass& pass) override {
    keep(cpu_ms[pass.name], cpu_.elapsed_ms());
    if (steps_) gpu_.set_label_listener(nullptr);
    timer_.end_scope(cmd, scope_);
  }
  void gather_gpu() {
    if (timer_.completed_frames() == last_completed_) return;
    last_completed_ = timer_.completed_frames();
    std::map<std::string, double> frame_steps;
    std::string pass;
    for (const auto& scope : timer_.last_results()) {
      if (scope.depth == 0) {
        keep(gpu_ms[scope.name], scope.gpu_ms);
        pass = scope.name;
        continue;
      }
      if (!frame_steps.contains(scope.name) && !step_pass.contains(scope.name)) {
        step_order.push_back(scope.name);
        step_pass[scope.name] = pass;
      }
      frame_steps[scope.name] += scope.gpu_ms;
    }
    for (const auto& [name, ms] : frame_steps) keep(step_ms[name], ms);
  }
  std::map<std::string, std::vector<double>> cpu_ms;
  std::map<std::string, std::vector<double>> gpu_ms;
  std::map<std::string, std::vector<double>> step_ms;
  std::vector<std::string> step_order;           // first seen first
  std::map<std::string, std::string> step_pass;  // the pass a step ran in

 private:
  gpu::Context& gpu_;
  gpu::GpuTimer& timer_;
  gpu::LabelScopes labels_;
  // A sample, dropping the oldest beyond the window: past twice the window, all but the
  // latest `window_` go at once, so a frame costs amortised O(1).
  void keep(std::vector<double>& samples, double ms) const {
    samples.push_back(ms);
    if (samples.size() > 2 * window_) {
      samples.erase(samples.begin(), samples.end() - static_cast<std::ptrdiff_t>(window_));
    }
  }

  bool steps_ = false;
  std::size_t window_;
  gpu::CpuTimer cpu_;
  std::uint32_t scope_ = 0;
  std::uint64_t last_completed_ = 0;
};

fgvk::PassRegistry pass_registry(const SessionOptions& options) {
  fgvk::PassRegistry registry = passes::builtin_pass_registry();
  if (options.register_passes) options.register_passes(registry);
  return registry;
}

RenderSession::RenderSession(const DataPaths& paths, const SessionOptions& options)
    : paths_(paths), options_(options) {
  // First: a host's pass type that cannot be registered fails before the device starts.
  registry_ = std::make_unique<fgvk::PassRegistry>(runtime::pass_registry(options));
  if (options.host_device) {
    gpu_ = std::make_unique<gpu::Context>(*options.host_device);
  } else {
    gpu::ContextOptions context_options;
    context_options.validation = options.validation;
    context_options.device = options.device;
    context_options.instance_extensions = options.instance_extensions;
    context_options.headless = !options.present;
    gpu_ = std::make_unique<gpu::Context>(context_options);
  }
  // The built-in passes/ folder, then the host's: for shader files and for #include.
  std::vector<std::filesystem::path> shader_dirs{paths_.shaders()};
  shader_dirs.insert(shader_dirs.end(), options.shader_dirs.begin(), options.shader_dirs.end());
  gpu::ShaderCompilerOptions shader_options;
  shader_options.include_dirs = shader_dirs;
  shaders_ = std::make_unique<gpu::ShaderCompiler>(shader_options);
  VkPipelineCache cache = options.pipeline_cache;
  if (cache == VK_NULL_HANDLE) {
    pipeline_cache_ = std::make_unique<gpu::PipelineCache>(*gpu_);
    cache = pipeline_cache_->handle();
  }
  executor_ =
      std::make_unique<fgvk::Executor>(*gpu_, *shaders_, *registry_, std::move(shader_dirs), cache);
  frames_ = std::make_unique<gpu::FrameLoop>(*gpu_, options.frames_in_flight);
  // Steps take a scope each, several per chunk in a shadow pass of many lights.
  constexpr std::uint32_t kPassScopes = 128;
  constexpr std::uint32_t kStepScopes = 4096;
  timer_ = std::make_unique<gpu::GpuTimer>(*gpu_, frames_->frames_in_flight(),
                                           options.time_steps ? kStepScopes : kPassScopes);
  observer_ = std::make_unique<Observer>(*gpu_, *timer_, options.time_steps, options.timing_window);
}

RenderSession::~RenderSession() {
  if (gpu_) gpu_->wait_idle();
}

base::Diagnostics RenderSession::load_graph(const fg::GraphSource& source,
                                            const fg::GraphEdit& edit) {
  auto graph = fg::read_graph(source);
  if (!graph.ok()) return graph.diagnostics();
  if (edit) edit(graph.value());
  base::Diagnostics diagnostics = graph.diagnostics();
  diagnostics.append(load_graph(graph.value()));
  return diagnostics;
}

base::Diagnostics RenderSession::load_graph(const fg::GraphDesc& graph) {
  fg::CompileOptions compile_options;
  compile_options.viewport = {options_.viewport.width, options_.viewport.height};
  compile_options.footprint = executor_->footprint_fn();
  // "auto" parameters choose for this device (the shadow rasteriser).
  compile_options.device = fg::DeviceTraits{
      gpu_->device_name(), gpu_->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU,
      gpu_->properties().vendorID};
  const auto realise_failed = [&](const std::string& why) {
    base::Diagnostics out;
    out.add({codes::graph::kRealiseFailed, base::Severity::error, why, graph.document.file(), "", 0,
             0});
    return out;
  };
  std::optional<base::Result<fg::Plan>> plan;
  try {
    // The device's own footprints: an image beyond its limits fails here.
    plan.emplace(fg::compile(graph, registry_->reflection(), compile_options));
  } catch (const std::runtime_error& e) {
    return realise_failed(std::string("the device cannot size this plan's resources: ") + e.what());
  }
  base::Diagnostics diagnostics = plan->diagnostics();
  if (!plan->ok()) return diagnostics;
  // Refused before allocating: a driver asked for more than it has may fail late, or (a
  // CPU device) overcommit host memory. The message says what the plan needs.
  const std::uint64_t needed = fg::plan_memory_bytes(plan->value());
  const std::uint64_t available = gpu::local_heaps(gpu_->physical_device()).total;
  const std::string memory = fg::describe_plan_memory(plan->value());
  if (available > 0 && needed > available) {
    diagnostics.append(realise_failed("the plan needs " + memory +
                                      "; the device's local memory heaps hold " +
                                      fg::format_bytes(available) + " in all"));
    return diagnostics;
  }
  // The host's images already bound must fit the new graph's imports.
  std::vector<std::string> stale_imports;
  diagnostics.append(check_bound_imports(plan->value(), graph.document, stale_imports));
  if (diagnostics.has_errors()) return diagnostics;
  try {
    executor_->load(std::move(plan->value()));
    live_document_ = graph.document;
    live_graph_ = graph;
    for (const auto& name : stale_imports) executor_->unbind_import(name);
  } catch (const fgvk::PassError& e) {
    // A diagnostic about the graph rather than a shader's text (a shader in none of the
    // shader folders) comes with a pointer alone: located here, in the graph's file.
    for (const auto& d : e.diagnostics()) {
      const bool in_graph = d.file.empty() && d.line == 0 && !d.pointer.empty();
      diagnostics.add(in_graph ? graph.document.make(d.code, d.severity, d.message, d.pointer) : d);
    }
  } catch (const std::runtime_error& e) {
    // The device cannot realise this plan (memory types, out of memory, a pass type with
    // no runtime): the previous plan stays live and the reason is reported with what the
    // plan needs.
    diagnostics.append(realise_failed(std::string(e.what()) + " (the plan needs " + memory + ")"));
  }
  return diagnostics;
}

base::Diagnostics RenderSession::frame_diagnostics() const {
  base::Diagnostics out;
  const fg::Plan& plan = executor_->plan();
  for (const auto& m : report_.messages()) {
    const fg::PlanPass* pass = plan.find_pass(m.pass);
    std::string pointer;
    if (pass != nullptr && pass->source_index >= 0) {
      pointer = "/passes/" + std::to_string(pass->source_index);
      const std::string param = pointer + "/params/" + m.param;
      if (!m.param.empty() && live_document_.root().is_object() &&
          live_document_.root().contains(nlohmann::json::json_pointer(param))) {
        pointer = param;
      }
    }
    out.add(
        live_document_.make(m.code, m.severity, "pass '" + m.pass + "': " + m.message, pointer));
  }
  return out;
}

void RenderSession::restart_motion() {
  motion_frame_ = 0;
}

void RenderSession::set_scene(scene::Scene scene) {
  if (frames_) frames_->wait_all();
  scene_ = std::move(scene);
  gpu_scene_ = std::make_unique<passes::GpuScene>(*gpu_, *scene_, frames_->frames_in_flight());
}

void RenderSession::set_lights(std::vector<scene::PointLight> lights) {
  if (!scene_) throw std::logic_error("set_lights() before set_scene()");
  // Light buffers are per frame slot and written when a frame starts: no wait needed.
  scene_->lights = std::move(lights);
}

void RenderSession::set_camera(const scene::Camera& camera) {
  if (!scene_) throw std::logic_error("set_camera() before set_scene()");
  scene_->camera = camera;  // written into the frame slot's buffer when a frame starts
}

void RenderSession::render(int frames, TraceWriter* trace, const BeforeFrame& before_frame) {
  if (!scene_ || !executor_->loaded()) throw std::logic_error("render() needs a scene and a graph");
  gpu::CpuTimer clock;
  for (int i = 0; i < frames; ++i) {
    const double frame_start = clock.elapsed_ms();
    if (before_frame) before_frame(i);
    VkCommandBuffer cmd = frames_->begin_frame();
    try {
      record_frame(cmd);
    } catch (...) {
      // A pass that fails midway (out of device memory) leaves the session usable: the
      // next frame begins afresh.
      frames_->abandon_frame();
      throw;
    }
    const bool capture = options_.capture_last_frame && i + 1 == frames;
    if (capture) gpu_->begin_debugger_capture();
    try {
      frames_->end_frame();
    } catch (const gpu::VulkanError& e) {
      if (e.result() != VK_ERROR_DEVICE_LOST) throw;
      throw_device_lost_at_submission(e);
    }
    if (capture) gpu_->end_debugger_capture();
    if (trace != nullptr) {
      trace->add({"frame " + std::to_string(i), "cpu", frame_start * 1000.0,
                  (clock.elapsed_ms() - frame_start) * 1000.0, 1});
    }
  }
  frames_->wait_all();
  // Timestamps of the last frames are read when their slot comes round again; run
  // one empty pass over the slots so every rendered frame is counted.
  for (std::uint32_t i = 0; i < frames_->frames_in_flight(); ++i) {
    VkCommandBuffer cmd = frames_->begin_frame();
    observer_->gather_gpu();
    timer_->begin_frame(cmd, frames_->slot());
    try {
      frames_->end_frame();
    } catch (const gpu::VulkanError& e) {
      if (e.result() != VK_ERROR_DEVICE_LOST) throw;
      throw_device_lost_at_submission(e);
    }
  }
  frames_->wait_all();
  observer_->gather_gpu();
  executor_->collect(report_);
  if (trace != nullptr) {
    double t = 0.0;
    for (const auto& timing : pass_timings()) {
      trace->add({timing.name, "gpu", t * 1000.0, timing.gpu_ms * 1000.0, 2});
      t += timing.gpu_ms;
    }
  }
}

// A loss met when a frame was submitted: no pass was recording, and the device says so
// when it notices, so the message names the frame's last pass and what else may be at fault.
void RenderSession::throw_device_lost_at_submission(const gpu::VulkanError& e) const {
  const auto& passes = executor_->plan().passes;
  const std::string last = passes.empty() ? std::string() : passes.back().name;
  throw gpu::DeviceLostError("the GPU device was lost when frame " +
                                 std::to_string(frames_->frame_number()) +
                                 " was submitted (its last pass: '" + last +
                                 "'; any pass of it or of the frames before it still in flight "
                                 "may be at fault) (" +
                                 e.what() + ")",
                             last, e.location());
}

// One frame into `cmd`, own or the host's: the scene's per-frame data, then the plan.
void RenderSession::record_frame(VkCommandBuffer cmd) {
  gpu_->collect_garbage();
  observer_->gather_gpu();
  timer_->begin_frame(cmd, frames_->slot());
  // Dynamic objects with a motion are where the frames recorded since restart_motion (or
  // since the session began) put them: readbacks and other submissions do not count.
  if (!scene_->dynamic_objects.empty()) scene::animate_objects(*scene_, motion_frame_);
  ++motion_frame_;
  const auto frame =
      gpu_scene_->update(cmd, frames_->slot(), *scene_, options_.viewport, frames_->frame_number());
  executor_->record(cmd, frame, observer_.get(), &report_);
}

void RenderSession::reset_timings() {
  frames_->wait_all();
  observer_->gather_gpu();
  observer_->cpu_ms.clear();
  observer_->gpu_ms.clear();
  observer_->step_ms.clear();
}

std::size_t RenderSession::timing_samples() const {
  std::size_t most = 0;
  for (const auto& [name, samples] : observer_->gpu_ms) most = std::max(most, samples.size());
  return most;
}

std::vector<PassTiming> RenderSession::pass_timings() const {
  std::vector<PassTiming> timings;
  for (const auto& pass : executor_->plan().passes) {
    PassTiming t{pass.name, pass.type};
    if (auto it = observer_->gpu_ms.find(pass.name); it != observer_->gpu_ms.end()) {
      t.gpu_ms = median(it->second);
      t.gpu_samples = it->second;
    }
    if (auto it = observer_->cpu_ms.find(pass.name); it != observer_->cpu_ms.end()) {
      t.cpu_ms = median(it->second);
    }
    timings.push_back(t);
  }
  return timings;
}

std::vector<PassTiming> RenderSession::step_timings() const {
  std::vector<PassTiming> timings;
  for (const std::string& name : observer_->step_order) {
    const auto it = observer_->step_ms.find(name);
    if (it == observer_->step_ms.end()) continue;  // not run since reset_timings()
    PassTiming t{name, observer_->step_pass.at(name)};
    t.gpu_ms = median(it->second);
    t.gpu_samples = it->second;
    timings.push_back(std::move(t));
  }
  return timings;
}

void RenderSession::write_image(const std::string& resource, const std::string& path) {
  const fg::Plan& plan = executor_->plan();
  if (const int index = plan.find_resource(resource);
      index >= 0 && plan.resources[static_cast<std::size_t>(index)].imported) {
    // Antumbra holds no image of its own for it, and no right to the host's.
    throw std::runtime_error("resource \"" + resource +
                             "\" is imported: its image is the host's (bind_image), so the host "
                             "reads it back from that image (docs/integration.md, \"The host's "
                             "images\")");
  }
  const gpu::Image* image = executor_->gpu_image(resource);
  const fgvk::BoundImage* bound = executor_->image(resource);
  if (image == nullptr || bound == nullptr) {
    throw std::runtime_error("resource \"" + resource + "\" is not a realised image of the graph");
  }
  frames_->wait_all();
  const auto host = gpu::read_image(*gpu_, *image, bound->layout);
  const bool pfm = path.size() > 4 && path.substr(path.size() - 4) == ".pfm";
  const bool ok = pfm ? gpu::write_pfm(path, host) : gpu::write_png(path, host);
  if (!ok) throw std::runtime_error("cannot write " + path);
}

void RenderSession::set_mesh_transform(std::size_t mesh, const glm::mat4& transform) {
  if (!scene_) throw std::logic_error("set_mesh_transform() before set_scene()");
  // CPU data the frame's GpuScene::update compares with what it uploaded: no wait needed.
  scene::set_mesh_transform(*scene_, mesh, transform);
}

}  // namespace antumbra::runtime
