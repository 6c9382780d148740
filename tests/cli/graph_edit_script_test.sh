#!/usr/bin/env bash
# antumbra edit --headless --script on the default graph's structure (issue 31), on lavapipe
# with validation: tests/data/editor/script/graph_edits.json adds, wires, renames,
# disconnects and removes passes, and refused connections leave the graph as it was. Then
# the saved file differs from the original by added lines only (and the commas before
# them), and a refused edit that no expectation names fails the run, located.
set -u
antumbra=$1
source_root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ANTUMBRA_CACHE_DIR="$tmp/cache"  # the tree's data and passes: nothing writes to them
cp "$source_root/data/graphs/layered-ssss.json" "$tmp/graph.json"
cp "$tmp/graph.json" "$tmp/graph-original.json"
cp "$source_root/tests/data/editor/script/graph_edits.json" "$tmp/"

log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }
"$antumbra" edit --headless --validation --size 96x54 --graph "$tmp/graph.json" \
  --script "$tmp/graph_edits.json" >"$log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "edit exited with $rc"
grep -q "0 step(s) failed" "$log" || fail "a step failed"
grep -q "refused: \[FG040\]" "$log" || fail "no FG040 refusal printed"
grep -q "refused: \[FG071\] this closes a cycle" "$log" || fail "no FG071 refusal printed"
grep -q "graph.json:[0-9]*:[0-9]*: error\[FG070\]" "$log" || fail "no located FG070 after the removal"
grep -q "the last good frame keeps running" "$log" || fail "no kept frame"
grep -q "Validation Error" "$log" && fail "validation errors"

# Saved with the file's own layout: only added lines, and at most two lines that gained a
# comma (the last pass's and the last resource's).
removed=$(diff "$tmp/graph-original.json" "$tmp/graph.json" | grep -c '^<')
added=$(diff "$tmp/graph-original.json" "$tmp/graph.json" | grep -c '^>')
[ "$removed" -le 2 ] || { diff "$tmp/graph-original.json" "$tmp/graph.json"; fail "$removed lines changed or removed"; }
[ "$added" -ge 5 ] || fail "the new pass was not saved"

# A refused edit that the next step does not expect fails the run, located in the script.
printf '{"steps": [\n  {"do": "connect", "from": ["gbuffer", "albedo"], "to": ["lighting", "layerTable"]}\n]}\n' \
  > "$tmp/unexpected.json"
cp "$tmp/graph-original.json" "$tmp/graph.json"
"$antumbra" edit --headless --size 96x54 --graph "$tmp/graph.json" --script "$tmp/unexpected.json" \
  >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "an unexpected refusal gave exit $rc, not 1"
grep -q "unexpected.json:2:[0-9]*: error\[ED100\]: .*edit refused: \[FG040\]" "$log" \
  || fail "the refusal is not a located ED100"
echo "graph edit script: all steps held; refusals leave the graph as it was"
