// The pfm target: PFM as `compare` and `quality` read it.
#include <cstddef>
#include <string>

#include "image_metrics.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {

void pfm(Bytes data) {
  std::string error;
  const auto image = app::decode_pfm(data, "fuzz.pfm", error);
  if (image &&
      image->texels.size() != std::size_t{image->width} * image->height * image->channels) {
    __builtin_trap();  // a decoded image must hold exactly its texels
  }
}

}  // namespace antumbra::fuzz
