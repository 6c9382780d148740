#!/usr/bin/env bash
# The windowed editor in a real window: Xvfb + lavapipe, validation (synchronization
# validation included) on. Opens, presents 30 frames, reads the last presented swapchain
# image back as a screenshot (UI included, a light selected: its range sphere drawn),
# closes. The screenshot must have the window's
# size and not be blank, and the log must hold no validation error.
# Skips (exit 77) only when there is no xvfb-run to give it a display.
set -u
antumbra=$1
png_stats=$2
source_root=$3
command -v xvfb-run >/dev/null 2>&1 || { echo "SKIP: xvfb-run is not installed"; exit 77; }
source "$(dirname "$0")/editor_test_setup.sh" "$source_root/data/scenes/atrium.json"

log="$tmp/log.txt"
start=$(date +%s.%N)
xvfb-run -a -s "-screen 0 640x480x24" "$antumbra" edit --validation --frames 30 --size 320x180 \
  --select l05 --scene "$tmp/scene.json" --graph "$tmp/graph.json" --screenshot "$tmp/shot.png" >"$log" 2>&1
rc=$?
end=$(date +%s.%N)
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; exit 1; }
[ $rc -eq 0 ] || fail "edit exited with $rc"
grep -q "Validation Error" "$log" && fail "validation errors in the log"
grep -q "validation: 0 error(s)" "$log" || fail "no clean validation summary"
grep -q "editor: 30 frame(s) presented" "$log" || fail "did not present 30 frames"
[ -s "$tmp/shot.png" ] || fail "no screenshot written"
stats=$("$png_stats" "$tmp/shot.png") || fail "cannot read the screenshot"
echo "screenshot: $stats"
case "$stats" in
  320x180\ *) ;;
  *) fail "screenshot is not 320x180: $stats" ;;
esac
colours=${stats##*colours=}
[ "$colours" -ge 16 ] || fail "screenshot looks blank ($colours colours)"
ls "$tmp"/*.recovery >/dev/null 2>&1 && fail "a recovery file was left behind"
# A light that is not in the scene is a usage error, not a crash.
xvfb-run -a -s "-screen 0 640x480x24" "$antumbra" edit --frames 2 --size 64x36 --select nosuch \
  --scene "$tmp/scene.json" --graph "$tmp/graph.json" >"$log" 2>&1
[ $? -eq 2 ] || fail "--select of a missing light should exit 2"
grep -q "no light named 'nosuch'" "$log" || fail "no message for the missing light"
echo "PASS: editor window smoke test in $(awk "BEGIN { printf \"%.1f\", $end - $start }") s"
