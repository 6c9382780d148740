// The compiler runs on the CPU: these tests need no device.
#include <algorithm>
#include <fstream>

#include <gtest/gtest.h>

#include "antumbra/gpu/shader_compiler.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

class ShaderCompilerTest : public ::testing::Test {
 protected:
  ShaderCompilerTest() {
    write(root() / "lib" / "common.glsl",
          "#ifndef COMMON_GLSL\n#define COMMON_GLSL\n"
          "#include \"detail/scale.glsl\"\n"
          "vec4 tint(vec2 uv) { return vec4(uv * SCALE, 0.5, 1.0); }\n#endif\n");
    write(root() / "lib" / "detail" / "scale.glsl", "const float SCALE = 1.0;\n");
    write(root() / "shaders" / "fill.comp",
          "#version 460\n#include \"common.glsl\"\n"
          "layout(local_size_x = 8, local_size_y = 8) in;\n"
          "layout(set = 0, binding = 0, rgba8) uniform writeonly image2D out_image;\n"
          "void main() {\n  ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n"
          "  imageStore(out_image, p, tint(vec2(p) / 64.0) * FACTOR);\n}\n");
  }
  fs::path root() const { return dir_.path(); }
  ShaderCompilerOptions options() const {
    ShaderCompilerOptions o;
    o.include_dirs = {root() / "lib"};
    o.cache_dir = root() / "cache";
    return o;
  }
  ShaderRequest fill_request() const {
    return {root() / "shaders" / "fill.comp", std::nullopt, {{"FACTOR", "1.0"}}, "main"};
  }

  testing::TempDir dir_;
};

TEST(ShaderStage, FromExtension) {
  EXPECT_EQ(stage_from_path("a/b.vert"), ShaderStage::vertex);
  EXPECT_EQ(stage_from_path("b.frag"), ShaderStage::fragment);
  EXPECT_EQ(stage_from_path("b.comp"), ShaderStage::compute);
  EXPECT_EQ(stage_from_path("b.geom"), ShaderStage::geometry);
  EXPECT_FALSE(stage_from_path("b.glsl").has_value());
}

TEST_F(ShaderCompilerTest, CompilesWithIncludesAndDefines) {
  ShaderCompiler compiler(options());
  auto result = compiler.compile(fill_request());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const ShaderBinary& binary = result.value();
  ASSERT_GT(binary.spirv.size(), 5u);
  EXPECT_EQ(binary.spirv[0], 0x07230203u);
  EXPECT_EQ(binary.stage, ShaderStage::compute);
  ASSERT_EQ(binary.dependencies.size(), 3u);
  EXPECT_EQ(binary.dependencies[0].filename(), "fill.comp");
  EXPECT_EQ(binary.dependencies[1].filename(), "common.glsl");
  EXPECT_EQ(binary.dependencies[2].filename(), "scale.glsl");
  EXPECT_EQ(compiler.compiled_count(), 1u);
}

TEST_F(ShaderCompilerTest, MissingDefineIsAnError) {
  ShaderCompiler compiler(options());
  ShaderRequest request = fill_request();
  request.defines.clear();
  auto result = compiler.compile(request);
  EXPECT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(fs::path(error->file).filename(), "fill.comp");
  EXPECT_EQ(error->line, 7);
}

TEST_F(ShaderCompilerTest, ErrorInIncludeReportsTheIncludedFileAndLine) {
  write(root() / "lib" / "detail" / "scale.glsl", "const float SCALE = 1.0;\nfloat broken( {\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile(fill_request());
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(fs::path(error->file), fs::weakly_canonical(root() / "lib" / "detail" / "scale.glsl"))
      << result.diagnostics().to_text();
  EXPECT_EQ(error->line, 2) << result.diagnostics().to_text();
  EXPECT_EQ(error->severity, base::Severity::error);
}

TEST_F(ShaderCompilerTest, AMissingSemicolonIsReportedOnItsLineWithTheSourceAndACaret) {
  write(root() / "shaders" / "semi.frag",
        "#version 460\nlayout(location = 0) out vec4 colour;\nvoid main() {\n  float x = 1.0\n\n"
        "  colour = vec4(x);\n}\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile({root() / "shaders" / "semi.frag", {}, {}, "main"});
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(error->line, 4) << result.diagnostics().to_text();
  EXPECT_EQ(error->column, 16) << result.diagnostics().to_text();
  EXPECT_EQ(error->excerpt, "  float x = 1.0");
  EXPECT_NE(base::format_text(*error).find("\n  |   float x = 1.0\n  |                ^"),
            std::string::npos)
      << base::format_text(*error);
}

TEST_F(ShaderCompilerTest, AnErrorInsideALineGetsACaretUnderItsToken) {
  write(root() / "shaders" / "word.frag", "#version 460\nvoid main() {\n  this is not glsl;\n}\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile({root() / "shaders" / "word.frag", {}, {}, "main"});
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(error->line, 3) << result.diagnostics().to_text();
  EXPECT_EQ(error->excerpt, "  this is not glsl;");
  EXPECT_GT(error->column, 2) << result.diagnostics().to_text();
}

// glslang names no token for a syntax error ("'' : syntax error, unexpected FLOATCONSTANT") and
// no column: the compiler finds the token it stopped at, here the fifth of five constants, in
// a guarded header three files deep.
TEST_F(ShaderCompilerTest, ASyntaxErrorInAnIncludedHeaderHasItsFileLineAndColumn) {
  const std::string bad = "float weight() { return max(1.0, 2.0) + min(3.0, 4.0 5.0); }";
  ASSERT_EQ(bad.find("5.0"), 53u);
  write(root() / "lib" / "weights.glsl", "#ifndef WEIGHTS_GLSL\n#define WEIGHTS_GLSL\n" + bad +
                                             "\nfloat ok() { return 1.0; }\n"
                                             "#endif\n");
  write(root() / "shaders" / "weighted.frag",
        "#version 460\n#include \"common.glsl\"\n#include \"weights.glsl\"\n"
        "layout(location = 0) out vec4 colour;\nvoid main() { colour = vec4(weight()); }\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile({root() / "shaders" / "weighted.frag", {}, {}, "main"});
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(fs::path(error->file), fs::weakly_canonical(root() / "lib" / "weights.glsl"))
      << result.diagnostics().to_text();
  EXPECT_EQ(error->line, 3) << result.diagnostics().to_text();
  EXPECT_EQ(error->column, 54) << result.diagnostics().to_text();
  EXPECT_EQ(error->excerpt, bad);
  EXPECT_NE(base::format_text(*error).find("weights.glsl:3:54: error[SH001]: '' :  syntax error, "
                                           "unexpected FLOATCONSTANT"),
            std::string::npos)
      << base::format_text(*error);
}

// Issue 30's case: a syntax error far along a long line of the main file was reported at
// column 1 of its line.
TEST_F(ShaderCompilerTest, ASyntaxErrorFarAlongALineHasItsColumn) {
  const std::string bad =
      "  colour = vec4(texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb * vec3(0.5, 0.5, 0.5) "
      "* vec3(1.0, 1.0 1.0), 1.0);";
  ASSERT_EQ(bad.find("1.0 1.0") + 4, 101u);
  write(root() / "shaders" / "long.frag",
        "#version 460\nlayout(set = 0, binding = 0) uniform sampler2D hdr;\n"
        "layout(location = 0) out vec4 colour;\n\nvoid main() {\n" +
            bad + "\n}\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile({root() / "shaders" / "long.frag", {}, {}, "main"});
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* error = result.diagnostics().find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(fs::path(error->file).filename(), "long.frag");
  EXPECT_EQ(error->line, 6) << result.diagnostics().to_text();
  EXPECT_EQ(error->column, 102) << result.diagnostics().to_text();
  EXPECT_EQ(error->excerpt, bad);
}

// An error that names no token and is no syntax error gets no column: no caret at a guess.
TEST_F(ShaderCompilerTest, AnErrorWithoutATokenGetsNoColumn) {
  write(root() / "shaders" / "word.frag", "#version 460\nvoid main() {\n  this is not glsl;\n}\n");
  ShaderCompiler compiler(options());
  auto result = compiler.compile({root() / "shaders" / "word.frag", {}, {}, "main"});
  ASSERT_FALSE(result.ok());
  const auto& diagnostics = result.diagnostics();
  const auto terminated = std::find_if(diagnostics.begin(), diagnostics.end(), [](const auto& d) {
    return d.message.find("compilation terminated") != std::string::npos;
  });
  ASSERT_NE(terminated, diagnostics.end()) << diagnostics.to_text();
  EXPECT_EQ(terminated->line, 3);
  EXPECT_EQ(terminated->column, 0);
}

TEST_F(ShaderCompilerTest, MissingIncludeAndUnknownStage) {
  write(root() / "shaders" / "bad.frag",
        "#version 460\n#include \"nowhere.glsl\"\nvoid main() {}\n");
  ShaderCompiler compiler(options());
  auto missing = compiler.compile({root() / "shaders" / "bad.frag", {}, {}, "main"});
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.diagnostics()[0].line, 2) << missing.diagnostics().to_text();
  auto unknown = compiler.compile({root() / "shaders" / "x.glsl", {}, {}, "main"});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.diagnostics().find(codes::shader::kUnknownStage), nullptr);
  auto unreadable = compiler.compile({root() / "shaders" / "none.comp", {}, {}, "main"});
  EXPECT_NE(unreadable.diagnostics().find(codes::shader::kUnreadable), nullptr);
}

TEST_F(ShaderCompilerTest, SecondCompileHitsTheDiskCache) {
  {
    ShaderCompiler first(options());
    ASSERT_TRUE(first.compile(fill_request()).ok());
    EXPECT_EQ(first.compiled_count(), 1u);
    EXPECT_EQ(first.cache_hit_count(), 0u);
  }
  ShaderCompiler second(options());  // a new process would see the same files
  auto cached = second.compile(fill_request());
  ASSERT_TRUE(cached.ok());
  EXPECT_TRUE(cached.value().from_cache);
  EXPECT_EQ(second.compiled_count(), 0u);
  EXPECT_EQ(second.cache_hit_count(), 1u);
  EXPECT_EQ(cached.value().dependencies.size(), 3u);

  // Another define or a changed include is a different key.
  ShaderRequest other = fill_request();
  other.defines[0].value = "0.5";
  EXPECT_FALSE(second.compile(other).value().from_cache);
  write(root() / "lib" / "detail" / "scale.glsl", "const float SCALE = 2.0;\n");
  EXPECT_FALSE(second.compile(fill_request()).value().from_cache);
  EXPECT_EQ(second.compiled_count(), 2u);
}

TEST(ShaderCompilerDefaults, CacheDirFollowsEnvironment) {
  ::setenv("ANTUMBRA_CACHE_DIR", "/tmp/antumbra-env-test", 1);
  EXPECT_EQ(ShaderCompiler::default_cache_dir(), fs::path("/tmp/antumbra-env-test/spirv"));
  ::unsetenv("ANTUMBRA_CACHE_DIR");
}

TEST(GlslangLog, ParsesLocatedAndUnlocatedLines) {
  const auto diagnostics = parse_glslang_log(
      "ERROR: /a/b.frag:12: 'x' : undeclared identifier\n"
      "WARNING: /a/c.glsl:3: something odd\n"
      "ERROR: 0:4: 'y' : syntax error\n"
      "ERROR: 2 compilation errors.  No code generated.\n",
      "/a/b.frag");
  ASSERT_EQ(diagnostics.size(), 3u);
  EXPECT_EQ(diagnostics[0].file, "/a/b.frag");
  EXPECT_EQ(diagnostics[0].line, 12);
  EXPECT_EQ(diagnostics[0].code, "SH001");
  EXPECT_EQ(diagnostics[1].severity, base::Severity::warning);
  EXPECT_EQ(diagnostics[2].file, "/a/b.frag");
  EXPECT_EQ(diagnostics[2].line, 4);
}

}  // namespace
}  // namespace antumbra::gpu
