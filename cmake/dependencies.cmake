# Every dependency comes from a Debian package (scripts/install-deps.sh installs them).
find_package(Vulkan 1.3 REQUIRED)
find_package(glslang REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(spdlog REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
if(ANTUMBRA_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(ANTUMBRA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
# The windowed editor: GLFW, and Debian's Dear ImGui (libimgui-dev ships the core as a
# static library; its GLFW and Vulkan backends only as sources under the examples).
find_package(glfw3 3.3 REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
find_path(ANTUMBRA_IMGUI_BACKENDS_DIR imgui_impl_vulkan.cpp
  PATHS /usr/share/doc/libimgui-dev/examples/backends
  DOC "Folder with Dear ImGui's imgui_impl_glfw.cpp and imgui_impl_vulkan.cpp")
if(NOT ANTUMBRA_IMGUI_BACKENDS_DIR)
  message(FATAL_ERROR "Dear ImGui backend sources not found (Debian: apt install libimgui-dev)")
endif()
