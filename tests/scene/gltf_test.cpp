#include "antumbra/scene/gltf_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "antumbra/base/diagnostic_codes.hpp"
#include "mesh_checks.hpp"

namespace antumbra::scene {
namespace {

namespace fs = std::filesystem;

const std::string kFixtures = std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/gltf/";
const std::string kBadScenes = std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/bad/";
const std::string kAssimp = ANTUMBRA_GLTF_MODELS_DIR;

void expect_triangle(const base::Result<GltfImport>& result) {
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(result->meshes.size(), 1u);
  const Mesh& mesh = result->meshes[0];
  EXPECT_EQ(mesh.name, "triangle");
  EXPECT_EQ(mesh.triangle_count(), 1u);
  // Node "root" translates by (1,2,3); its child scales by 2.
  EXPECT_EQ(mesh.bounds.min, glm::vec3(1, 2, 3));
  EXPECT_EQ(mesh.bounds.max, glm::vec3(3, 4, 3));
  // No NORMAL in the file: computed from the counter-clockwise triangle.
  for (const Vertex& v : mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(testing::misoriented_triangles(mesh), 0);
  ASSERT_EQ(result->materials.size(), 2u);  // "orange" + the default
  EXPECT_EQ(mesh.material, 0);
  EXPECT_EQ(result->materials[0].name, "orange");
  EXPECT_EQ(result->materials[0].albedo, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(result->materials[0].roughness, 0.6f);
}

TEST(Gltf, LoadsTextTriangleWithNodeTransforms) {
  expect_triangle(load_gltf(kFixtures + "triangle.gltf"));
}

TEST(Gltf, LoadsBinaryTriangle) {
  expect_triangle(load_gltf(kFixtures + "triangle.glb"));
}

struct BadGltf {
  std::string file;
  const char* code;
  const char* pointer;
};

// GoogleTest looks the printer up by this name.
void PrintTo(const BadGltf& b, std::ostream* os) {  // NOLINT(readability-identifier-naming)
  *os << b.file;
}

class BadGltfFiles : public ::testing::TestWithParam<BadGltf> {};

TEST_P(BadGltfFiles, FailWithTheExpectedCode) {
  const BadGltf& expected = GetParam();
  if (expected.file.rfind(kAssimp, 0) == 0 && !fs::exists(expected.file)) {
    GTEST_SKIP() << "assimp-testmodels not installed: " << expected.file;
  }
  const auto result = load_gltf(expected.file);
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* d = result.diagnostics().find(expected.code);
  ASSERT_NE(d, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(d->severity, base::Severity::error);
  EXPECT_EQ(d->pointer, expected.pointer) << result.diagnostics().to_text();
  EXPECT_EQ(d->file, expected.file);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BadGltfFiles,
    ::testing::Values(
        BadGltf{kBadScenes + "bad_index.gltf", codes::scene::kGltfIndexOutOfRange, "/accessors/1"},
        BadGltf{kFixtures + "accessor_overflow.gltf", codes::scene::kGltfOutOfBounds,
                "/accessors/0"},
        BadGltf{kFixtures + "bad_stride.gltf", codes::scene::kGltfBadAccessor,
                "/bufferViews/0/byteStride"},
        BadGltf{kFixtures + "float_indices.gltf", codes::scene::kGltfBadAccessor, "/accessors/1"},
        BadGltf{kBadScenes + "cycle.gltf", codes::scene::kGltfNodeCycle, "/nodes/1/children/0"},
        BadGltf{kFixtures + "no_such_file.gltf", codes::scene::kGltfFileMissing, ""},
        // Found by the gltf fuzz target: an image's bufferView one byte past its buffer made
        // tinygltf read past the heap block; refused before tinygltf runs.
        BadGltf{std::string(ANTUMBRA_SOURCE_DIR) +
                    "/fuzz/regressions/gltf/glb-image-view-past-buffer.glb",
                codes::scene::kGltfOutOfBounds, "/bufferViews/3"},
        // "extras" nested 200,000 deep overflowed tinygltf's recursive conversion; refused
        // past 256 levels, before any parser runs.
        BadGltf{
            std::string(ANTUMBRA_SOURCE_DIR) + "/fuzz/regressions/gltf/extras-nested-300-deep.gltf",
            codes::scene::kGltfParse, ""}));

// Debian's assimp-testmodels: malformed files from the wild.
INSTANTIATE_TEST_SUITE_P(
    AssimpCorpus, BadGltfFiles,
    ::testing::Values(
        BadGltf{kAssimp + "/wrongTypes/badArray.gltf", codes::scene::kGltfParse,
                "/meshes/0/primitives"},
        BadGltf{kAssimp + "/SchemaFailures/sceneWrongType.gltf", codes::scene::kGltfParse,
                "/scene"},
        BadGltf{kAssimp + "/IndexOutOfRange/IndexOutOfRange.gltf",
                codes::scene::kGltfIndexOutOfRange, "/accessors/0"},
        BadGltf{kAssimp + "/IndexOutOfRange/AllIndicesOutOfRange.gltf",
                codes::scene::kGltfIndexOutOfRange, "/accessors/0"},
        BadGltf{kAssimp + "/MissingBin/BoxTextured.gltf", codes::scene::kGltfParse, ""},
        BadGltf{kAssimp + "/RecursiveNodes/RecursiveNodes.gltf", codes::scene::kGltfNodeCycle,
                "/nodes/1/children/0"},
        BadGltf{kAssimp + "/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
                codes::scene::kGltfNonFinite, "/accessors/2"},
        BadGltf{kAssimp + "/IncorrectVertexArrays/Cube.gltf", codes::scene::kGltfCountMismatch,
                "/meshes/1/primitives/0"},
        BadGltf{kAssimp + "/TestNoRootNode/NoScene.gltf", codes::scene::kGltfNoGeometry, "/scene"},
        BadGltf{kAssimp + "/TestNoRootNode/SceneWithoutNodes.gltf", codes::scene::kGltfNoGeometry,
                "/scenes/0"},
        BadGltf{kAssimp + "/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf",
                codes::scene::kGltfUnsupported, "/extensionsRequired"}));

// Wrongly typed properties the importer does not use: geometry loads, with a warning.
TEST(Gltf, WrongTypesOutsideGeometryAreWarnings) {
  for (const char* name : {"badNumber", "badObject", "badUint", "badString", "badExtension"}) {
    const std::string path = kAssimp + "/wrongTypes/" + name + ".gltf";
    if (!fs::exists(path)) GTEST_SKIP();
    const auto result = load_gltf(path);
    ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
    EXPECT_EQ(result.diagnostics().warning_count(), 1u) << name;
    EXPECT_NE(result.diagnostics().find(codes::scene::kGltfWarning), nullptr) << name;
  }
}

TEST(Gltf, LoadsValidCorpusModels) {
  struct Good {
    const char* file;
    std::size_t triangles;
  };
  for (const Good& g : {Good{"/BoxTextured-glTF/BoxTextured.gltf", 12},
                        Good{"/BoxTextured-glTF-Binary/BoxTextured.glb", 12},
                        Good{"/BoxTextured-glTF-Embedded/BoxTextured.gltf", 12},
                        Good{"/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12},
                        Good{"/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496}}) {
    const std::string path = kAssimp + g.file;
    if (!fs::exists(path)) GTEST_SKIP();
    const auto result = load_gltf(path);
    ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
    std::size_t triangles = 0;
    for (const Mesh& m : result->meshes) {
      triangles += m.triangle_count();
      EXPECT_TRUE(testing::normals_unit(m)) << g.file;
      EXPECT_FALSE(m.bounds.empty());
      for (const auto i : m.indices) ASSERT_LT(i, m.vertices.size());
      ASSERT_LT(static_cast<std::size_t>(m.material), result->materials.size());
    }
    EXPECT_EQ(triangles, g.triangles) << g.file;
  }
}

// Whatever the corpus holds, loading never crashes and failures carry SC codes.
TEST(Gltf, EveryCorpusFileLoadsOrFailsCleanly) {
  if (!fs::exists(kAssimp)) GTEST_SKIP();
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(kAssimp)) {
    const auto ext = e.path().extension();
    if (ext != ".gltf" && ext != ".glb") continue;
    ++files;
    const auto result = load_gltf(e.path().string());
    for (const base::Diagnostic& d : result.diagnostics()) {
      EXPECT_EQ(d.code.rfind("SC", 0), 0u) << d.code;
      EXPECT_FALSE(d.message.empty());
    }
    if (!result.ok()) {
      EXPECT_TRUE(result.diagnostics().has_errors()) << e.path();
    }
  }
  EXPECT_GT(files, 20);
}

}  // namespace
}  // namespace antumbra::scene
