// libFuzzer's entry for one target (fuzz/CMakeLists.txt builds one program per target,
// antumbra_fuzz_<name>, from this file, the target's own source and only the libraries that
// target reads with; ANTUMBRA_FUZZ_FUNCTION names its function).
#include <cstddef>
#include <cstdint>

#include "targets.hpp"

#ifndef ANTUMBRA_FUZZ_FUNCTION
#error "ANTUMBRA_FUZZ_FUNCTION names the target's function (fuzz/CMakeLists.txt)"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  antumbra::fuzz::ANTUMBRA_FUZZ_FUNCTION(antumbra::fuzz::Bytes(data, size));
  return 0;
}
