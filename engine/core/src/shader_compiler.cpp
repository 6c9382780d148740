#include "antumbra/gpu/shader_compiler.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <regex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "shader_error_column.hpp"
#include "shader_source.hpp"

namespace antumbra::gpu {

namespace fs = std::filesystem;

std::optional<ShaderStage> stage_from_path(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".vert") return ShaderStage::vertex;
  if (ext == ".frag") return ShaderStage::fragment;
  if (ext == ".comp") return ShaderStage::compute;
  if (ext == ".geom") return ShaderStage::geometry;
  if (ext == ".tesc") return ShaderStage::tess_control;
  if (ext == ".tese") return ShaderStage::tess_evaluation;
  return std::nullopt;
}

VkShaderStageFlagBits to_vk(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex:
      return VK_SHADER_STAGE_VERTEX_BIT;
    case ShaderStage::fragment:
      return VK_SHADER_STAGE_FRAGMENT_BIT;
    case ShaderStage::compute:
      return VK_SHADER_STAGE_COMPUTE_BIT;
    case ShaderStage::geometry:
      return VK_SHADER_STAGE_GEOMETRY_BIT;
    case ShaderStage::tess_control:
      return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case ShaderStage::tess_evaluation:
      return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
  }
  return VK_SHADER_STAGE_ALL;
}

const char* to_string(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex:
      return "vertex";
    case ShaderStage::fragment:
      return "fragment";
    case ShaderStage::compute:
      return "compute";
    case ShaderStage::geometry:
      return "geometry";
    case ShaderStage::tess_control:
      return "tess_control";
    case ShaderStage::tess_evaluation:
      return "tess_evaluation";
  }
  return "unknown";
}

namespace {

EShLanguage to_glslang(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex:
      return EShLangVertex;
    case ShaderStage::fragment:
      return EShLangFragment;
    case ShaderStage::compute:
      return EShLangCompute;
    case ShaderStage::geometry:
      return EShLangGeometry;
    case ShaderStage::tess_control:
      return EShLangTessControl;
    case ShaderStage::tess_evaluation:
      return EShLangTessEvaluation;
  }
  return EShLangCompute;
}

// Resolves #include like scan_source() and records every file it opened.
class Includer final : public glslang::TShader::Includer {
 public:
  explicit Includer(const std::vector<fs::path>& include_dirs) : include_dirs_(include_dirs) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
    return open(header, fs::path(includer).parent_path());
  }
  IncludeResult* includeSystem(const char* header, const char*, size_t) override {
    return open(header, {});
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }
  [[nodiscard]] const std::vector<fs::path>& opened() const { return opened_; }
  // `path` reads `text` instead of the file's contents (the column probes' cut copies).
  void replace(const fs::path& path, std::string text) {
    replaced_path_ = path;
    replaced_text_ = std::move(text);
  }

 private:
  IncludeResult* open(const char* header, const fs::path& dir) {
    auto path = detail::resolve_include(header, dir, include_dirs_);
    if (!path) return nullptr;  // glslang reports the failed #include with its location
    auto text = *path == replaced_path_ ? replaced_text_ : detail::read_text(*path);
    if (!text) return nullptr;
    if (std::find(opened_.begin(), opened_.end(), *path) == opened_.end()) {
      opened_.push_back(*path);
    }
    auto* owned = new std::string(std::move(*text));
    return new IncludeResult(path->string(), owned->data(), owned->size(), owned);
  }

  const std::vector<fs::path>& include_dirs_;
  std::vector<fs::path> opened_;
  fs::path replaced_path_;
  std::optional<std::string> replaced_text_;
};

base::Diagnostic make_error(const char* code, std::string message, const std::string& file) {
  base::Diagnostic diagnostic;
  diagnostic.code = code;
  diagnostic.message = std::move(message);
  diagnostic.file = file;
  return diagnostic;
}

// Everything a parse of the shader takes but the text of its files, so that the column
// probes parse exactly as the compile did.
struct ParseSetup {
  EShLanguage language = EShLangCompute;
  std::string name;  // the top-level file, as glslang names it in its log
  std::string preamble;
  std::string entry_point;
  const std::vector<fs::path>* include_dirs = nullptr;
};

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

std::string make_preamble(const std::vector<ShaderDefine>& defines) {
  // Include support is always on, so shaders need no #extension line for it.
  std::string preamble = "#extension GL_GOOGLE_include_directive : enable\n";
  for (const auto& define : defines) {
    preamble += "#define " + define.name + (define.value.empty() ? "" : " " + define.value) + "\n";
  }
  return preamble;
}

bool parse(glslang::TShader& shader, const ParseSetup& setup, const std::string& source,
           Includer& includer) {
  const char* text = source.c_str();
  const int length = static_cast<int>(source.size());
  const char* names[] = {setup.name.c_str()};
  shader.setStringsWithLengthsAndNames(&text, &length, names, 1);
  shader.setPreamble(setup.preamble.c_str());
  // SPIR-V always calls the entry point "main"; another GLSL function may serve as it.
  shader.setEntryPoint("main");
  if (setup.entry_point != "main") shader.setSourceEntryPoint(setup.entry_point.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, setup.language, glslang::EShClientVulkan, 100);
  // Vulkan 1.2 / SPIR-V 1.5 for every device: a 1.2 device (RenderDoc 1.24 reports every
  // device as one) rejects SPIR-V 1.6, and no shader needs what 1.6 adds.
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
  return shader.parse(GetDefaultResources(), 460, false, kMessages, includer);
}

// Whether `error` is reported again when `file` (the top-level one or an include) reads
// `text`: the probe detail::locate_in_source uses to find a syntax error's token.
bool reproduces(const ParseSetup& setup, const std::string& source, const base::Diagnostic& error,
                const std::string& file, const std::string& text) {
  glslang::TShader shader(setup.language);
  Includer includer(*setup.include_dirs);
  const bool top = file == setup.name;
  if (!top) includer.replace(file, text);
  parse(shader, setup, top ? text : source, includer);
  const base::Diagnostics log = parse_glslang_log(shader.getInfoLog(), setup.name);
  return std::any_of(log.begin(), log.end(), [&](const base::Diagnostic& d) {
    return d.file == error.file && d.line == error.line && d.message == error.message;
  });
}

// Columns, source lines and carets for every located diagnostic: the top-level file's text is
// at hand, included files are read again.
void locate_errors(base::Diagnostics& diagnostics, const ParseSetup& setup,
                   const std::string& source) {
  base::Diagnostics out;
  for (base::Diagnostic d : diagnostics) {
    const auto text = d.line < 1             ? std::nullopt
                      : d.file == setup.name ? std::optional<std::string>(source)
                                             : detail::read_text(d.file);
    if (text) {
      const base::Diagnostic original = d;
      detail::locate_in_source(d, *text, [&](const std::string& file, const std::string& cut) {
        return reproduces(setup, source, original, file, cut);
      });
    }
    out.add(std::move(d));
  }
  diagnostics = std::move(out);
}
}  // namespace

base::Diagnostics parse_glslang_log(std::string_view log, const std::string& fallback_file) {
  static const std::regex kLocated(R"(^(ERROR|WARNING): (.+):(\d+): (.*)$)");
  static const std::regex kSummary(R"(^ERROR: \d+ compilation errors\.)");
  base::Diagnostics diagnostics;
  std::istringstream lines{std::string(log)};
  std::string line;
  std::smatch match;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || std::regex_search(line, kSummary)) continue;
    base::Diagnostic diagnostic;
    if (std::regex_match(line, match, kLocated)) {
      const bool error = match[1] == "ERROR";
      diagnostic.code = error ? codes::shader::kCompile : codes::shader::kCompileWarning;
      diagnostic.severity = error ? base::Severity::error : base::Severity::warning;
      diagnostic.file = match[2].str();
      // glslang says "0:12" when a string has no name: that is our top-level file.
      if (diagnostic.file == "0" || diagnostic.file.empty()) diagnostic.file = fallback_file;
      diagnostic.line = std::stoi(match[3].str());
      diagnostic.message = match[4].str();
    } else if (line.rfind("ERROR: ", 0) == 0) {
      diagnostic = make_error(codes::shader::kCompile, line.substr(7), fallback_file);
    } else if (line.rfind("WARNING: ", 0) == 0) {
      diagnostic = make_error(codes::shader::kCompileWarning, line.substr(9), fallback_file);
      diagnostic.severity = base::Severity::warning;
    } else {
      continue;  // glslang's informational lines
    }
    diagnostics.add(std::move(diagnostic));
  }
  return diagnostics;
}

fs::path ShaderCompiler::default_cache_dir() {
  if (const char* dir = std::getenv("ANTUMBRA_CACHE_DIR"); dir && *dir) {
    return fs::path(dir) / "spirv";
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    return fs::path(xdg) / "antumbra" / "spirv";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return fs::path(home) / ".cache" / "antumbra" / "spirv";
  }
  return fs::temp_directory_path() / "antumbra" / "spirv";
}

ShaderCompiler::ShaderCompiler(ShaderCompilerOptions options) : options_(std::move(options)) {
  if (options_.cache_dir.empty()) options_.cache_dir = default_cache_dir();
  glslang::InitializeProcess();  // reference-counted by glslang
}

ShaderCompiler::~ShaderCompiler() {
  glslang::FinalizeProcess();
}

base::Result<ShaderBinary> ShaderCompiler::compile(const ShaderRequest& request) {
  std::error_code error;
  const fs::path path = fs::weakly_canonical(fs::absolute(request.path), error).lexically_normal();
  const std::optional<ShaderStage> stage =
      request.stage ? request.stage : stage_from_path(request.path);
  base::Diagnostics diagnostics;
  if (!stage) {
    diagnostics.add(make_error(codes::shader::kUnknownStage,
                               "cannot tell the shader stage from the extension '" +
                                   request.path.extension().string() +
                                   "' (use .vert .frag .comp .geom .tesc .tese)",
                               path.string()));
    return diagnostics;
  }
  auto source = detail::read_text(path);
  if (!source) {
    diagnostics.add(
        make_error(codes::shader::kUnreadable, "cannot read shader source", path.string()));
    return diagnostics;
  }
  const detail::SourceScan scan = detail::scan_source(path, *source, options_.include_dirs, *stage,
                                                      request.defines, request.entry_point);
  if (options_.use_cache) {
    if (auto words = detail::load_cached(options_.cache_dir, scan.key)) {
      ++cache_hit_count_;
      ShaderBinary binary{std::move(*words), *stage, "main", scan.files, scan.key, true};
      return binary;
    }
  }
  auto result = compile_glsl(*source, path, *stage, request.defines, request.entry_point);
  if (result.ok()) {
    result.value().key = scan.key;
    if (options_.use_cache)
      detail::store_cached(options_.cache_dir, scan.key, result.value().spirv);
  }
  return result;
}

base::Result<ShaderBinary> ShaderCompiler::compile_source(std::string_view source,
                                                          const fs::path& virtual_path,
                                                          ShaderStage stage,
                                                          const std::vector<ShaderDefine>& defines,
                                                          const std::string& entry_point) {
  return compile_glsl(std::string(source), virtual_path, stage, defines, entry_point);
}

base::Result<ShaderBinary> ShaderCompiler::compile_glsl(const std::string& source,
                                                        const fs::path& path, ShaderStage stage,
                                                        const std::vector<ShaderDefine>& defines,
                                                        const std::string& entry_point) {
  ++compiled_count_;
  const EShLanguage language = to_glslang(stage);
  glslang::TShader shader(language);
  const std::string name = path.string();
  const ParseSetup setup{language, name, make_preamble(defines), entry_point,
                         &options_.include_dirs};
  Includer includer(options_.include_dirs);
  base::Diagnostics diagnostics;
  if (!parse(shader, setup, source, includer)) {
    diagnostics = parse_glslang_log(shader.getInfoLog(), name);
    locate_errors(diagnostics, setup, source);
    if (!diagnostics.has_errors()) {
      diagnostics.add(
          make_error(codes::shader::kCompile, "glslang failed without a message", name));
    }
    return diagnostics;
  }
  diagnostics = parse_glslang_log(shader.getInfoLog(), name);
  locate_errors(diagnostics, setup, source);

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(kMessages)) {
    base::Diagnostics link = parse_glslang_log(program.getInfoLog(), name);
    for (const auto& d : link) {
      base::Diagnostic copy = d;
      if (copy.severity == base::Severity::error) copy.code = codes::shader::kLink;
      diagnostics.add(copy);
    }
    if (!diagnostics.has_errors()) {
      diagnostics.add(make_error(codes::shader::kLink, "glslang link failed", name));
    }
    return diagnostics;
  }

  ShaderBinary binary;
  binary.stage = stage;
  binary.entry_point = "main";
  glslang::SpvOptions spv_options;
  spv_options.generateDebugInfo = options_.debug_info;
  spv_options.disableOptimizer = true;  // glslang is built without SPIRV-Tools here
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(language), binary.spirv, &logger, &spv_options);
  const std::string spv_log = logger.getAllMessages();
  if (binary.spirv.empty()) {
    diagnostics.add(make_error(codes::shader::kLink, "SPIR-V generation failed: " + spv_log, name));
    return diagnostics;
  }
  binary.dependencies.push_back(path);
  for (const auto& dep : includer.opened()) binary.dependencies.push_back(dep);
  return base::Result<ShaderBinary>(std::move(binary), std::move(diagnostics));
}

}  // namespace antumbra::gpu
