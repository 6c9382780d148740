// Frames in flight and determinism of the default frame.

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "antumbra/gpu/frame_loop.hpp"
#include "gpu_test_support.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

std::vector<char> read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

}  // namespace

// RenderSession's FrameLoop keeps the default number of frames in flight; the test
// below is about two frames overlapping on the GPU.
static_assert(gpu::FrameLoop::kDefaultFramesInFlight == 2);

class FramesTest : public RenderTest {};

// 5 frames with 2 in flight share every graph resource: synchronization validation
// reports any cross-frame hazard (frame N+1 writing what frame N still reads). The
// last frame must equal a single-frame render: nothing leaks between frames.
TEST_F(FramesTest, FiveFramesInFlightMatchOneFrame) {
  OPEN_SESSION(single, kSmall);
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*single, default_graph()));
  single->set_scene(default_scene());
  single->render(1, nullptr);
  expect_no_validation_errors(*single);
  const auto one = read_output(*single);

  OPEN_SESSION(multi, kSmall);
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*multi, default_graph()));
  multi->set_scene(default_scene());
  multi->render(5, nullptr);
  expect_no_validation_errors(*multi);
  const auto five = read_output(*multi);

  ASSERT_FALSE(is_blank(one));
  EXPECT_EQ(max_abs_difference(one, five), 0.0f) << "frame 5 differs from frame 1";
  EXPECT_TRUE(one.texels == five.texels);

  // Rendering more frames after a read-back (the output left in TRANSFER_SRC by the
  // copy) must stay hazard-free as well.
  multi->render(3, nullptr);
  expect_no_validation_errors(*multi);
  EXPECT_TRUE(read_output(*multi).texels == one.texels);
}

// Two sessions rendering the same frame produce the same bytes, both in the read-back
// texels and in the PNG files write_image() produces.
TEST_F(FramesTest, RenderingIsDeterministic) {
  gpu::testing::TempDir temp;
  std::vector<gpu::HostImage> images;
  for (int run = 0; run < 2; ++run) {
    OPEN_SESSION(session, kSmall);
    ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, default_graph()));
    session->set_scene(default_scene());
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    images.push_back(read_output(*session));
    session->write_image("ldr", (temp.path() / ("run" + std::to_string(run) + ".png")).string());
    session->write_image("ldr", (temp.path() / ("run" + std::to_string(run) + ".pfm")).string());
  }
  ASSERT_FALSE(is_blank(images[0]));
  EXPECT_TRUE(images[0].texels == images[1].texels)
      << "max difference " << max_abs_difference(images[0], images[1]);
  for (const char* extension : {".png", ".pfm"}) {
    const auto first = read_bytes(temp.path() / (std::string("run0") + extension));
    const auto second = read_bytes(temp.path() / (std::string("run1") + extension));
    EXPECT_FALSE(first.empty()) << extension;
    EXPECT_TRUE(first == second) << extension << " files differ";
  }
}
