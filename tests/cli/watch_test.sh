#!/usr/bin/env bash
# render --watch as a script would use it: a broken graph keeps the last good frame and
# prints located diagnostics; the fixed graph is swapped in and a new image written; a
# shader syntax error keeps the old pipeline (SH001 with file:line); fixing it reloads.
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; rm -rf "$tmp"' EXIT
mkdir -p "$tmp/root"
cp -r "$source_root/data" "$source_root/passes" "$tmp/root/"
export ANTUMBRA_ROOT="$tmp/root" ANTUMBRA_CACHE_DIR="$tmp/cache"
graph="$tmp/root/data/graphs/deferred.json"
shader="$tmp/root/passes/tonemap/tonemap.frag"
log="$tmp/log.txt"

"$antumbra" render --graph "$graph" --size 64x36 --out "$tmp/out.png" --watch --watch-seconds 60 \
  >"$log" 2>&1 &
pid=$!

fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }
# wait_for PATTERN COUNT: until PATTERN occurs COUNT times in the log (30 s at most).
wait_for() {
  for _ in $(seq 1 300); do
    [ "$(grep -c -- "$1" "$log")" -ge "$2" ] && return 0
    kill -0 "$pid" 2>/dev/null || fail "antumbra exited while waiting for '$1'"
    sleep 0.1
  done
  fail "timed out waiting for '$1' x$2"
}
# Edits land in a new second so coarse file-time resolution cannot hide them.
edit() { sleep 1.1; cp "$1" "$2.tmp"; mv "$2.tmp" "$2"; }

wait_for "watching" 1
cp "$graph" "$tmp/good.json"
printf '{ "version": 1,\n  "passes": [' > "$tmp/broken.json"
edit "$tmp/broken.json" "$graph"
wait_for "reload failed" 1
grep -q "deferred.json:2:[0-9]*: error\[FG001\]" "$log" || fail "no located syntax diagnostic"
sed 's/"aces"/"reinhard"/' "$tmp/good.json" > "$tmp/reinhard.json"
edit "$tmp/reinhard.json" "$graph"
wait_for "reloaded" 1
# The diff names the one changed pass and keeps every resource (same descriptions).
grep -q "passes +0 -0 ~1, culled 0 unculled 0 rebuilt 0, resources +0 -0 realloc 0 kept [1-9]" "$log" \
  || fail "no reload diff with one changed pass and kept resources"
grep -q "passes changed: tonemap" "$log" || fail "the diff does not name the changed pass"

cp "$shader" "$tmp/good.frag"
sed 's/void main() {/void main() { this is not glsl/' "$tmp/good.frag" > "$tmp/bad.frag"
edit "$tmp/bad.frag" "$shader"
wait_for "reload failed" 2
grep -q "tonemap.frag:[0-9]*: error\[SH001\]" "$log" || grep -q "tonemap.frag:[0-9]*:[0-9]*: error\[SH001\]" "$log" \
  || fail "no SH001 diagnostic with the shader's file and line"
grep -q "^  | void main() { this is not glsl" "$log" || fail "no source line under the SH001 diagnostic"
edit "$tmp/good.frag" "$shader"
wait_for "reloaded" 2
# A shader-only reload names the passes whose pipelines were rebuilt.
grep -q "rebuilt 1, resources" "$log" || fail "the shader reload does not count the rebuilt pass"
grep -q "passes rebuilt from edited shaders: tonemap" "$log" || fail "the rebuilt pass is not named"
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null

# The layer-cap warning is reported again after every reload while it holds: the cap
# lowered in the file under --watch says so, located at the cap.
graph="$tmp/root/data/graphs/layered-ssss.json"
log="$tmp/log2.txt"
"$antumbra" render --graph "$graph" --size 64x36 --out "$tmp/out2.png" --watch --watch-seconds 120 \
  >"$log" 2>&1 &
pid=$!
wait_for "watching" 1
grep -q "LY001" "$log" && fail "the default cap (4) warns on the atrium"
sed 's/"maxLayers": 4/"maxLayers": 2/' "$graph" > "$tmp/cap2.json"
grep -q '"maxLayers": 2' "$tmp/cap2.json" || fail "could not lower the cap"
edit "$tmp/cap2.json" "$graph"
wait_for "reloaded" 1
wait_for "layered-ssss.json:[0-9]*:[0-9]*: warning\[LY001\]" 1
sed 's/"tileSize": 16/"tileSize": 32/; s/"maxLayers": 2/"maxLayers": 3/' "$tmp/cap2.json" > "$tmp/cap3.json"
edit "$tmp/cap3.json" "$graph"
wait_for "reloaded" 2
wait_for "warning\[LY001\]" 2
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
echo "watch: 4 reloads, 2 refused changes kept the last good frame, cap warnings re-reported"
