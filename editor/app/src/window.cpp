#include "window.hpp"

#include <cstdint>
#include <limits>
#include <utility>

#include <stdexcept>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "antumbra/gpu/vk_check.hpp"

namespace antumbra::editor_app {
namespace {

// GLFW reports errors through a callback; keep the last one for the exception text.
std::string& last_glfw_error() {
  static std::string error;
  return error;
}

void on_glfw_error(int code, const char* description) {
  last_glfw_error() = std::to_string(code) + ": " + (description ? description : "");
}

void init_glfw() {
  glfwSetErrorCallback(&on_glfw_error);
  if (glfwInit() != GLFW_TRUE) {
    throw std::runtime_error("cannot start GLFW (is there a display? " + last_glfw_error() + ")");
  }
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw std::runtime_error("GLFW finds no Vulkan loader");
  }
}

}  // namespace

std::vector<std::string> Window::required_instance_extensions() const {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) throw std::runtime_error("GLFW cannot present with Vulkan here");
  return {names, names + count};
}

Window::Window(int width, int height, const std::string& title) {
  init_glfw();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw std::runtime_error("cannot open a window: " + last_glfw_error());
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &Window::on_key);
  glfwSetMouseButtonCallback(window_, &Window::on_mouse_button);
  glfwSetCursorPosCallback(window_, &Window::on_cursor);
  glfwSetWindowContentScaleCallback(window_, &Window::on_content_scale);
  glfwGetCursorPos(window_, &cursor_x_, &cursor_y_);
}

void Window::on_cursor(GLFWwindow* window, double x, double y) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self == nullptr) return;
  self->cursor_x_ = x;
  self->cursor_y_ = y;
}

void Window::on_mouse_button(GLFWwindow* window, int button, int action, int /*mods*/) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self == nullptr || button < 0 || button >= QueuedMouse::kButtons) return;
  // The cursor as the event stream had it when the button changed: glfwGetCursorPos asks
  // the X server for where the pointer is now, after every motion still queued.
  self->mouse_events_.push_back(
      {button, action == GLFW_PRESS, self->cursor_x_, self->cursor_y_, self->sequence_++});
}

std::optional<QueuedMouse> Window::next_mouse_event() {
  delivered_now_.reset();
  if (mouse_events_.empty()) {
    // Caught up: the live state is what was last delivered.
    for (int b = 0; b < QueuedMouse::kButtons; ++b) {
      shown_mouse_.down[b] = glfwGetMouseButton(window_, b) == GLFW_PRESS;
    }
    return std::nullopt;
  }
  const MouseButtonEvent event = mouse_events_.front();
  mouse_events_.pop_front();
  delivered_now_ = event.sequence;
  shown_mouse_.down[event.button] = event.pressed;
  shown_mouse_.x = event.x;
  shown_mouse_.y = event.y;
  return shown_mouse_;
}

void Window::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self != nullptr) self->presses_.push_back({key, mods, self->sequence_++});
}

std::vector<KeyPress> Window::take_key_presses() {
  // Keys and the mouse in the order they came: a key pressed after a queued click waits
  // until the frame after that click is replayed (Ctrl+S after a fast drag saves the
  // drag's end, not its start).
  std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
  if (delivered_now_) {
    limit = *delivered_now_;
  } else if (!mouse_events_.empty()) {
    limit = mouse_events_.front().sequence;
  }
  std::vector<KeyPress> ready;
  std::vector<KeyPress> later;
  for (const KeyPress& press : presses_) (press.sequence < limit ? ready : later).push_back(press);
  presses_.swap(later);
  return ready;
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

VkExtent2D Window::framebuffer_size() const {
  int width = 0;
  int height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)};
}

VkExtent2D Window::window_size() const {
  int width = 0;
  int height = 0;
  glfwGetWindowSize(window_, &width, &height);
  return {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)};
}

float Window::content_scale() const {
  float x = 1.0f;
  float y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return x > 0.0f ? x : 1.0f;
}

void Window::on_content_scale(GLFWwindow* window, float /*x*/, float /*y*/) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self != nullptr) self->scale_changed_ = true;
}

bool Window::take_content_scale_change() {
  return std::exchange(scale_changed_, false);
}

bool Window::minimised() const {
  const VkExtent2D size = framebuffer_size();
  return size.width == 0 || size.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0;
}

bool Window::should_close() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}
void Window::set_should_close(bool close) {
  glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE);
}
void Window::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}
void Window::poll_events() {
  glfwPollEvents();
}
void Window::wait_events() {
  glfwWaitEventsTimeout(0.1);
}

Surface::Surface(VkInstance instance, const Window& window) : instance_(instance) {
  gpu::check(glfwCreateWindowSurface(instance, window.handle(), nullptr, &surface_),
             "glfwCreateWindowSurface");
}

Surface::~Surface() {
  vkDestroySurfaceKHR(instance_, surface_, nullptr);
}

}  // namespace antumbra::editor_app
