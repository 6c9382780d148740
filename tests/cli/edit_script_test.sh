#!/usr/bin/env bash
# antumbra edit --headless --script: the scripted editing run of issue 4 on lavapipe with
# validation: a light moved into conflict warns (model and frame), undo clears it, the
# computed fix applies (on the default atrium at a cap of 3, a fix of several lights as one
# step), save writes the file, a broken graph and a shader error keep the
# last good frame with located diagnostics, fixing them swaps the new state in, and the
# cap edited through the graph's reflection warns again. Also a failing expectation
# must fail the run (a test that cannot fail is no test).
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/root"
cp -r "$source_root/data" "$source_root/passes" "$tmp/root/"
export ANTUMBRA_ROOT="$tmp/root" ANTUMBRA_CACHE_DIR="$tmp/cache"
cp "$source_root/tests/data/editor/lamps.json" "$tmp/scene.json"
sed 's/"maxLayers": 4/"maxLayers": 3/' "$source_root/data/graphs/layered-ssss.json" \
  | sed 's|"../schema/|"'"$source_root"'/data/schema/|' > "$tmp/graph.json"
grep -q '"maxLayers": 3' "$tmp/graph.json" || { echo "FAIL: could not set the cap"; exit 1; }
cp "$tmp/graph.json" "$tmp/graph-good.json"
cp "$tmp/root/passes/tonemap/tonemap.frag" "$tmp/tonemap-good.frag"
sed 's/void main() {/void main() { this is not glsl/' "$tmp/tonemap-good.frag" > "$tmp/tonemap-bad.frag"
cp "$source_root/tests/data/editor/script/edit.json" "$tmp/edit.json"

log="$tmp/log.txt"
"$antumbra" edit --headless --validation --size 96x54 --graph "$tmp/graph.json" \
  --scene "$tmp/scene.json" --script "$tmp/edit.json" --out "$tmp/last.png" >"$log" 2>&1
rc=$?
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }
[ $rc -eq 0 ] || fail "edit exited with $rc"
grep -q "0 step(s) failed" "$log" || fail "a step failed"
grep -q "graph.json:2:[0-9]*: error\[FG001\]" "$log" || fail "no located FG001 for the broken graph"
grep -q "tonemap.frag:[0-9]*\(:[0-9]*\)\?: error\[SH001\]" "$log" || fail "no SH001 with file:line"
grep -q "reload refused; the last good frame keeps running" "$log" || fail "no kept frame"
grep -q "fix: " "$log" || fail "no fix was described"
grep -q "editor frame (96x54)" "$log" || fail "no frame time"
grep -q "Validation Error" "$log" && fail "validation errors"
[ -s "$tmp/last.png" ] || fail "no image written"

# An expectation that does not hold fails the run, located in the script.
cp "$tmp/graph-good.json" "$tmp/graph.json"
printf '{"steps": [\n  {"expect": "warning"}\n]}\n' > "$tmp/wrong.json"
"$antumbra" edit --headless --size 96x54 --graph "$tmp/graph.json" --scene "$source_root/tests/data/editor/lamps.json" \
  --script "$tmp/wrong.json" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "a failing expectation gave exit $rc, not 1"
grep -q "wrong.json:2:[0-9]*: error\[ED100\]" "$log" || fail "the failure is not located"
# The default scene from its own camera: drags land under the cursor (within 5 cm), and
# a drag to a point off the light's plane fails, located, instead of claiming success.
cp "$source_root/tests/data/editor/script/atrium_drag.json" "$source_root/tests/data/editor/script/off_plane_drag.json" "$tmp/"
"$antumbra" edit --headless --validation --size 160x90 --script "$tmp/atrium_drag.json" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "the atrium drags exited with $rc"
grep -q "0 step(s) failed" "$log" || fail "an atrium drag did not land under the cursor"
grep -q "dragging on the horizontal plane y = 2.30 m" "$log" || fail "the drag does not say its plane"
grep -q "Validation Error" "$log" && fail "validation errors"
"$antumbra" edit --headless --size 160x90 --script "$tmp/off_plane_drag.json" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "a drag to a point off the plane gave exit $rc, not 1"
grep -q "off_plane_drag.json:5:[0-9]*: error\[ED100\]: .*m from the target" "$log" \
  || fail "the missed target is not a located ED100"
grep -q "unsaved changes to .*atrium.json were not saved" "$log" || fail "no unsaved-changes warning"

# The default atrium at a cap of 3: no one-light fix exists; the fix changes several
# lights, printed a line each, applied and undone as one step.
cp "$source_root/tests/data/editor/script/atrium_fix.json" "$tmp/"
"$antumbra" edit --headless --size 160x90 --script "$tmp/atrium_fix.json" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "the atrium fix exited with $rc"
grep -q "0 step(s) failed" "$log" || fail "a step of the atrium fix failed"
grep -q "fix: change [0-9]* lights (one undo step)" "$log" || fail "no several-light fix printed"
grep -q "^    reduce range of '\|^    move '" "$log" || fail "the fix's changes are not listed"

# A script runs headless only (the windowed editor has its own test, editor_window_test.sh).
"$antumbra" edit --script "$tmp/edit.json" >"$log" 2>&1
[ $? -eq 2 ] || fail "edit --script without --headless should be a usage error"
echo "edit script: all steps held; a wrong expectation fails located"
