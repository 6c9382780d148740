#!/usr/bin/env bash
# A scene file names only what lies beside it or below (docs/robustness.md, "Paths"): a
# "gltf" path climbing out of its folder is error SC046, located, in validate, render, the
# headless editor and techniques (exit 1, nothing rendered); --allow-outside-paths makes it
# a warning and the model is read.
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ANTUMBRA_CACHE_DIR="$tmp/cache"
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }

mkdir -p "$tmp/models" "$tmp/scenes"
cp "$source_root"/data/scenes/models/lattice.* "$tmp/models/"
cat >"$tmp/scenes/screen.json" <<'JSON'
{
  "version": 1,
  "camera": {"position": [0, 1.5, 4], "target": [0, 1, 0]},
  "objects": [
    {"name": "floor", "primitive": "box", "size": [8, 0.2, 8], "position": [0, -0.1, 0]},
    {"name": "screen", "gltf": "../models/lattice.gltf", "position": [0, 0, 0]}
  ],
  "lights": [{"name": "lamp", "position": [0, 2, 2], "intensity": 10, "range": 6, "size": 0.2}]
}
JSON
scene="$tmp/scenes/screen.json"
located="screen.json:6:32: error\[SC046\]: '../models/lattice.gltf' is a path that climbs out through '..', outside the scene file's folder: refused.*--allow-outside-paths.*\(at /objects/1/gltf\)"

"$antumbra" validate "$scene" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "validate exited with $rc, not 1"
grep -Eq "$located" "$log" || fail "validate: no located SC046"
"$antumbra" validate --allow-outside-paths "$scene" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "validate --allow-outside-paths exited with $rc, not 0"
grep -q "warning\[SC046\]" "$log" || fail "validate --allow-outside-paths: no SC046 warning"

"$antumbra" render --scene "$scene" --size 64x36 --out "$tmp/refused.png" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "render exited with $rc, not 1"
grep -Eq "$located" "$log" || fail "render: no located SC046"
[ -e "$tmp/refused.png" ] && fail "render wrote an image of a refused scene"
"$antumbra" render --allow-outside-paths --scene "$scene" --size 64x36 --out "$tmp/read.png" \
  >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "render --allow-outside-paths exited with $rc, not 0"
grep -q "warning\[SC046\]" "$log" || fail "render --allow-outside-paths: no SC046 warning"
[ -s "$tmp/read.png" ] || fail "render --allow-outside-paths wrote no image"

"$antumbra" edit --headless --frames 1 --size 64x36 --scene "$scene" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "edit exited with $rc, not 1"
grep -Eq "$located" "$log" || fail "edit: no located SC046"
"$antumbra" edit --headless --frames 1 --size 64x36 --allow-outside-paths --scene "$scene" \
  >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "edit --allow-outside-paths exited with $rc, not 0"
"$antumbra" techniques --scene "$scene" --graph hard.json --size 32x18 --out "$tmp/t/refused.md" \
  >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "techniques exited with $rc, not 1"
grep -Eq "$located" "$log" || fail "techniques: no located SC046"
[ -e "$tmp/t/refused.md" ] && fail "techniques wrote a table of a refused scene"
"$antumbra" techniques --allow-outside-paths --scene "$scene" --graph hard.json --size 32x18 \
  --out "$tmp/t/read.md" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "techniques --allow-outside-paths exited with $rc, not 0"
grep -q "warning\[SC046\]" "$log" || fail "techniques --allow-outside-paths: no SC046 warning"
[ -s "$tmp/t/read.md" ] || fail "techniques --allow-outside-paths wrote no table"
echo "outside paths: refused and located by default, read with a warning when allowed"
