#!/usr/bin/env bash
# Device memory running out when a reloaded graph allocates (docs/robustness.md, "Out of
# device memory"), injected through the test hook ANTUMBRA_TEST_FAIL_HEAPS_ABOVE (a graph's
# transient heap over that many bytes fails with VK_ERROR_OUT_OF_DEVICE_MEMORY): under
# render --watch and in the headless editor the reload fails with FG100 naming the graph's
# file and what the plan needs, the previous graph keeps rendering, and a graph that fits
# is taken afterwards.
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
pid=""
trap '[ -n "$pid" ] && kill "$pid" 2>/dev/null; rm -rf "$tmp"' EXIT
export ANTUMBRA_CACHE_DIR="$tmp/cache" ANTUMBRA_TEST_FAIL_HEAPS_ABOVE=1000000
schema="$source_root/data/schema/"
# At 64x36 the default deferred graph's heap is ~0.1 MB; at 8 times the viewport, ~5 MB.
sed "s|\"../schema/|\"$schema|" "$source_root/data/graphs/deferred.json" > "$tmp/good.json"
sed 's/"size": "viewport"/"size": {"scale": 8}/g' "$tmp/good.json" > "$tmp/big.json"
sed 's/"aces"/"reinhard"/' "$tmp/good.json" > "$tmp/other.json"
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }

# render --watch
cp "$tmp/good.json" "$tmp/graph.json"
"$antumbra" render --graph "$tmp/graph.json" --size 64x36 --out "$tmp/out.png" --watch \
  --watch-seconds 60 >"$log" 2>&1 &
pid=$!
wait_for() {  # PATTERN COUNT: until PATTERN occurs COUNT times in the log (30 s at most)
  for _ in $(seq 1 300); do
    [ "$(grep -c -- "$1" "$log")" -ge "$2" ] && return 0
    kill -0 "$pid" 2>/dev/null || fail "antumbra exited while waiting for '$1'"
    sleep 0.1
  done
  fail "timed out waiting for '$1' x$2"
}
edit() { sleep 1.1; cp "$1" "$2.tmp"; mv "$2.tmp" "$2"; }  # a new second: file times differ
wait_for "watching" 1
edit "$tmp/big.json" "$tmp/graph.json"
wait_for "reload failed" 1
grep -Eq "graph.json: error\[FG100\]: .*out-of-memory injected above 1000000 bytes.*the plan needs" \
  "$log" || fail "no FG100 naming the graph, the failure and what the plan needs"
edit "$tmp/other.json" "$tmp/graph.json"
wait_for "reloaded" 1
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
pid=""

# edit --headless: the same reload through the editor's session
cp "$tmp/good.json" "$tmp/graph.json"
cp "$source_root/tests/data/editor/lamps.json" "$tmp/scene.json"
cat >"$tmp/script.json" <<JSON
{"steps": [
  {"do": "write-file", "path": "\$graph", "from": "$tmp/big.json"},
  {"do": "reload"},
  {"expect": "reload-failed", "code": "FG100"},
  {"do": "frames", "count": 2},
  {"do": "write-file", "path": "\$graph", "from": "$tmp/other.json"},
  {"do": "reload"},
  {"expect": "reload-ok"}
]}
JSON
"$antumbra" edit --headless --size 64x36 --graph "$tmp/graph.json" --scene "$tmp/scene.json" \
  --script "$tmp/script.json" --out "$tmp/edit.png" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "edit exited with $rc"
grep -q "0 step(s) failed" "$log" || fail "a step failed"
grep -q "error\[FG100\]" "$log" || fail "the editor printed no FG100"
[ -s "$tmp/edit.png" ] || fail "no image after the failed reload"
echo "out of memory on reload: FG100, the previous graph kept, the next one taken"
