// The png target: encoded images (PNG and JPEG; any other bytes are refused) as glTF
// materials decode them, with the default limits.
#include "antumbra/scene/image_cache.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {

void png(Bytes data) {
  (void)scene::decode_image(data, "fuzz.png");
}

}  // namespace antumbra::fuzz
