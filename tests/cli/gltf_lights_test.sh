#!/usr/bin/env bash
# A glTF with KHR_lights_punctual lights as the whole scene, on lavapipe with validation:
# it renders lit by its own lights (no default rig, no warnings); a scripted edit of one
# of them is saved as an override in <model>.scene.json beside it, the glTF stays
# byte-identical, and the next render reads the override.
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fixture="$source_root/tests/data/scenes/gltf/lit_shelf.gltf"
cp "$fixture" "$tmp/lit_shelf.gltf"
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }

"$antumbra" render --validation --scene "$tmp/lit_shelf.gltf" --size 64x36 \
  --out "$tmp/before.png" >"$log" 2>&1 || fail "render exited with $?"
grep -q "warning\[" "$log" && fail "warnings"
grep -q "Validation Error" "$log" && fail "validation errors"
[ -e "$tmp/lit_shelf.gltf.scene.json" ] && fail "viewing wrote a scene file"

cat >"$tmp/edit.json" <<'SCRIPT'
{ "steps": [
  { "expect": "light-at", "light": "model/Lamp", "position": [0, 2.5, 0] },
  { "do": "set-light", "light": "model/Lamp", "intensity": 0.5, "color": [0, 0, 1] },
  { "do": "save" },
  { "expect": "file-contains", "path": "$scene", "text": "\"name\": \"model/Lamp\"" },
  { "expect": "file-lacks", "path": "$scene", "text": "\"name\": \"key\"" }
] }
SCRIPT
"$antumbra" edit --headless --validation --size 64x36 --scene "$tmp/lit_shelf.gltf" \
  --script "$tmp/edit.json" >"$log" 2>&1 || fail "edit exited with $?"
grep -q "0 step(s) failed" "$log" || fail "a step failed"
cmp -s "$fixture" "$tmp/lit_shelf.gltf" || fail "the glTF was rewritten"
[ -s "$tmp/lit_shelf.gltf.scene.json" ] || fail "no scene file beside the model"
grep -q '"intensity": 0.5' "$tmp/lit_shelf.gltf.scene.json" || fail "override not saved"
grep -q '"range"' "$tmp/lit_shelf.gltf.scene.json" && fail "the override repeats the glTF's values"

"$antumbra" render --validation --scene "$tmp/lit_shelf.gltf" --size 64x36 \
  --out "$tmp/after.png" >"$log" 2>&1 || fail "second render exited with $?"
cmp -s "$tmp/before.png" "$tmp/after.png" && fail "the override did not change the image"
echo "PASS"
