#!/usr/bin/env bash
# A RenderDoc capture of one `render` frame (lavapipe). RenderDoc 1.24 reports every
# device as Vulkan 1.2, so this runs the extension path (VK_KHR_dynamic_rendering,
# VK_KHR_synchronization2, VK_KHR_maintenance4) and the capture markers of a headless
# frame. The capture is converted to RenderDoc's XML and must hold the frame's commands,
# every pass's debug label and the objects' debug names.
# Without renderdoccmd: fails where ANTUMBRA_REQUIRE_GPU is set (CI; scripts/install-deps.sh
# installs it), else skips (exit 77).
set -u
antumbra=$1
source_root=$2
if ! command -v renderdoccmd >/dev/null 2>&1; then
  case "${ANTUMBRA_REQUIRE_GPU:-0}" in
    "" | 0) echo "SKIP: renderdoccmd is not installed (apt install renderdoc)"; exit 77 ;;
    *) echo "FAIL: ANTUMBRA_REQUIRE_GPU is set, but renderdoccmd is not installed" \
         "(scripts/install-deps.sh installs renderdoc)"; exit 1 ;;
  esac
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ANTUMBRA_CACHE_DIR="$tmp/cache"
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }

start=$(date +%s.%N)
# From the source root, so the program finds data/ and the shaders; -w waits for the exit.
(cd "$source_root" && renderdoccmd capture -w -c "$tmp/antumbra" "$antumbra" render \
  --size 64x36 --out "$tmp/frame.png") >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "renderdoccmd capture exited with $rc"
grep -q "unsuitable" "$log" && fail "the device was refused under RenderDoc"
grep -q "wrote $tmp/frame.png" "$log" || fail "render did not write its frame"
grep -q "Vulkan 1.2 with VK_KHR_dynamic_rendering, VK_KHR_synchronization2" "$log" ||
  fail "not the Vulkan 1.2 extension path"
grep -q "graphics debugger: RenderDoc" "$log" || fail "RenderDoc was not seen as a capture tool"
captures=("$tmp"/antumbra*.rdc)
[ -s "${captures[0]}" ] || fail "no capture file (expected $tmp/antumbra*.rdc)"
[ ${#captures[@]} -eq 1 ] || fail "${#captures[@]} capture files, expected one frame"
size=$(stat -c %s "${captures[0]}")

renderdoccmd convert -f "${captures[0]}" -c xml -o "$tmp/capture.xml" >>"$log" 2>&1 ||
  fail "renderdoccmd convert failed"
xml="$tmp/capture.xml"
end=$(date +%s.%N)

# The frame's commands, through the KHR entry points (RenderDoc names chunks by core name).
for chunk in vkCmdBeginRendering vkCmdPipelineBarrier2 vkCmdDrawIndexed vkCmdDispatch \
  vkCmdBeginDebugUtilsLabelEXT; do
  grep -q "<chunk [^>]*name=\"$chunk\"" "$xml" || fail "the capture has no $chunk"
done
# One label per pass of data/graphs/layered-ssss.json (the default graph).
for pass in layers gbuffer shadowMaps penumbra blurH blurV lighting tonemap; do
  grep -q "\"pLabelName\" typename=\"string\"[^>]*>$pass<" "$xml" ||
    fail "no debug label for pass '$pass' in the capture"
done
# Object names: the scene's geometry, a pass pipeline, the transient graph images.
for name in scene.vertices scene.indices gbuffer.pipeline lighting.pipeline context.queue depth ldr; do
  grep -q "\"ObjectName\" typename=\"string\"[^>]*>$name<" "$xml" ||
    fail "no object named '$name' in the capture"
done
echo "PASS: RenderDoc capture of one frame, $size bytes, checked in" \
  "$(awk "BEGIN { printf \"%.1f\", $end - $start }") s"
