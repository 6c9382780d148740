#pragma once
// The editor's GLFW window (no client API: Vulkan draws into it) and its Vulkan surface.
// GLFW is initialised once per Window; the surface belongs to the instance, so it must
// be destroyed before the gpu::Context that owns the instance.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace antumbra::editor_app {

// A key going down, with the modifiers held (GLFW's key and mod codes).
struct KeyPress {
  int key = 0;
  int mods = 0;
  std::uint64_t sequence = 0;  // order among key and mouse button events
};

// A mouse button going down or up, where the cursor was then (window coordinates).
struct MouseButtonEvent {
  int button = 0;
  bool pressed = false;
  double x = 0.0;
  double y = 0.0;
  std::uint64_t sequence = 0;
};

// The mouse state a frame shows ImGui when queued button events are pending: one event a
// frame, so a click whose press and release (or two clicks) fall between two frames at a
// few frames per second on lavapipe is seen as a click, at the place it happened.
struct QueuedMouse {
  static constexpr int kButtons = 5;
  bool down[kButtons] = {};
  double x = 0.0;
  double y = 0.0;
};

class Window {
 public:
  // Throws std::runtime_error when GLFW cannot start (no display) or has no Vulkan.
  Window(int width, int height, const std::string& title);
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
  ~Window();

  // What vkCreateInstance must enable for this window's surface (GLFW decides).
  [[nodiscard]] std::vector<std::string> required_instance_extensions() const;

  [[nodiscard]] GLFWwindow* handle() const { return window_; }
  [[nodiscard]] VkExtent2D framebuffer_size() const;
  // In screen coordinates (ImGui's units); the framebuffer may have more pixels (macOS).
  [[nodiscard]] VkExtent2D window_size() const;
  // The DPI scale the desktop asks for (1 at 96 dpi), GLFW's content scale.
  [[nodiscard]] float content_scale() const;
  // True once after the window moved to a screen of another scale (or the setting
  // changed): the UI is then scaled again.
  [[nodiscard]] bool take_content_scale_change();
  // Iconified, or a 0x0 framebuffer (how some platforms report it): nothing to draw.
  [[nodiscard]] bool minimised() const;
  [[nodiscard]] bool should_close() const;
  void set_should_close(bool close);
  void set_title(const std::string& title);
  void poll_events();
  void wait_events();  // blocks: while minimised there is nothing to draw
  // Key presses since the last call. A tap that goes down and up between two frames
  // (easy at a few frames per second on lavapipe) is still here, where a per-frame
  // "is it down" test misses it. Registered before ImGui's backend, which chains to it.
  [[nodiscard]] std::vector<KeyPress> take_key_presses();
  // The next queued mouse button event applied to the buttons' state as last shown;
  // nullopt when none is pending (the live state is current).
  [[nodiscard]] std::optional<QueuedMouse> next_mouse_event();

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_content_scale(GLFWwindow* window, float x, float y);

  GLFWwindow* window_ = nullptr;
  std::vector<KeyPress> presses_;
  std::deque<MouseButtonEvent> mouse_events_;
  QueuedMouse shown_mouse_;     // the buttons as ImGui last saw them through the queue
  std::uint64_t sequence_ = 0;  // the next event's place in the order
  std::optional<std::uint64_t> delivered_now_;  // the mouse event replayed this frame
  double cursor_x_ = 0.0;                       // the cursor in event order (window coordinates)
  double cursor_y_ = 0.0;
  bool scale_changed_ = false;
};

// The window's VkSurfaceKHR, destroyed with the object (before the instance goes).
class Surface {
 public:
  Surface(VkInstance instance, const Window& window);
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;
  ~Surface();
  [[nodiscard]] VkSurfaceKHR handle() const { return surface_; }

 private:
  VkInstance instance_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

}  // namespace antumbra::editor_app
