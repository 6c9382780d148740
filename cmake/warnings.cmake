# One place for warnings and sanitizers, applied per target so that third-party
# headers found through find_package stay outside -Werror-style noise.
function(antumbra_target_defaults target)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
      -Wconversion -Wno-sign-conversion -Wno-missing-field-initializers>)
  # CI builds (.ci/run) turn every warning into an error. GCC 12's -Wrestrict fires on
  # std::string concatenation inlined at -O2 (GCC bug 105329, a false positive in libstdc++
  # itself), so it stays a warning there.
  if(ANTUMBRA_WERROR)
    target_compile_options(${target} PRIVATE -Werror $<$<CXX_COMPILER_ID:GNU>:-Wno-error=restrict>)
  endif()
  # A unity build (cmake/unity.cmake) pastes each source into a generated file, so GCC takes a
  # test's fixture in an anonymous namespace for one defined in a header and warns that the
  # TEST_F class deriving from it has internal linkage: true of every such fixture, and
  # meaningless when the "header" is one translation unit's source.
  if(ANTUMBRA_UNITY_BUILD)
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-subobject-linkage>)
  endif()
  if(ANTUMBRA_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(ANTUMBRA_FUZZ)
    # libFuzzer's coverage in every library a target reaches; the programs add the fuzzer's
    # main (fuzz/CMakeLists.txt).
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined
      -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(ANTUMBRA_TSAN)
    target_compile_options(${target} PRIVATE -fsanitize=thread -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=thread)
  endif()
endfunction()

if(ANTUMBRA_SANITIZE AND ANTUMBRA_TSAN)
  message(FATAL_ERROR "ANTUMBRA_SANITIZE (ASan) and ANTUMBRA_TSAN cannot share a build")
endif()
if(ANTUMBRA_TSAN)
  add_link_options(-fsanitize=thread)
endif()

if(ANTUMBRA_SANITIZE)
  # Link-time sanitizer runtime must reach every executable, including tests.
  add_link_options(-fsanitize=address,undefined)
endif()
