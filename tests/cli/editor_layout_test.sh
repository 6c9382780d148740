#!/usr/bin/env bash
# The editor laid out around its viewport (Xvfb + lavapipe): from the layout report the
# editor writes on exit (--layout-report), no panel, splitter or status bar covers the
# viewport and the graph's image has the viewport's size; at UI scale 2 too. The layout
# file goes to the per-user config folder (here a temporary HOME), never the working
# folder; a splitter dragged with real X events (xdotool) survives a restart; a corrupt
# layout file is the defaults with a message, not a crash.
# Skips (exit 77) only without xvfb-run or xdotool.
set -u
antumbra=$1
source_root=$2
command -v xvfb-run >/dev/null 2>&1 || { echo "SKIP: xvfb-run is not installed"; exit 77; }
command -v xdotool >/dev/null 2>&1 || { echo "SKIP: xdotool is not installed"; exit 77; }
source "$(dirname "$0")/editor_test_setup.sh" "$source_root/data/scenes/atrium.json"
export ANTUMBRA_ROOT="$source_root"  # the runs below start in other working folders
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- log:"; cat "$log"; [ -f "$tmp/driver.txt" ] && cat "$tmp/driver.txt"; exit 1; }
edit_args=(--scene "$tmp/scene.json" --graph "$tmp/graph.json" --size 1024x600)

# check_report FILE [PYTHON CONDITION]...: the layout invariants, then each condition on
# `r` (the report) must hold.
check_report() {
  python3 - "$@" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
def overlap(a, b):
    return (a["x"] < b["x"] + b["width"] and b["x"] < a["x"] + a["width"] and
            a["y"] < b["y"] + b["height"] and b["y"] < a["y"] + a["height"])
v = r["viewport"]
problems = []
for p in r["panels"] + [dict(r["status"], name="status bar"), dict(r["column_handle"], name="splitter")]:
    if overlap(p, v):
        problems.append("%s %s overlaps the viewport %s" % (p["name"], p, v))
    if p["x"] < 0 or p["y"] < 0 or p["x"] + p["width"] > r["window"]["width"] or p["y"] + p["height"] > r["window"]["height"]:
        problems.append("%s %s is outside the window" % (p["name"], p))
if (r["image"]["width"], r["image"]["height"]) != (v["width"], v["height"]):
    problems.append("the image %s is not the viewport's size %s" % (r["image"], v))
s = r["shown"]
if s["x"] < v["x"] or s["y"] < v["y"] or s["x"] + s["width"] > v["x"] + v["width"] or s["y"] + s["height"] > v["y"] + v["height"]:
    problems.append("the image is shown at %s, outside the viewport %s" % (s, v))
for condition in sys.argv[2:]:
    if not eval(condition):
        problems.append("not true: " + condition)
for p in problems:
    print("layout report:", p)
sys.exit(1 if problems else 0)
PY
}

# 1. UI scale 2, the layout file in the default place: under $HOME, nothing in the
# working folder (no imgui.ini, no editor.ini).
mkdir -p "$tmp/home" "$tmp/cwd"
(cd "$tmp/cwd" && env -u ANTUMBRA_CONFIG_DIR -u XDG_CONFIG_HOME HOME="$tmp/home" \
  xvfb-run -a -s "-screen 0 1280x800x24" "$antumbra" edit "${edit_args[@]}" --validation \
  --frames 3 --ui-scale 2 --layout-report "$tmp/scale2.json" >"$log" 2>&1) || fail "edit exited with $?"
grep -q "validation: 0 error(s)" "$log" || fail "no clean validation summary"
[ -f "$tmp/home/.config/antumbra/editor.ini" ] || fail "the layout was not saved under ~/.config/antumbra"
[ -z "$(ls -A "$tmp/cwd")" ] || fail "files left in the working folder: $(ls -A "$tmp/cwd")"
check_report "$tmp/scale2.json" 'r["ui_scale"] == 2' 'r["column_handle"]["width"] == 12' \
  || fail "layout at scale 2"
echo "scale 2: $(tr -d '\n ' < "$tmp/scale2.json" | grep -o '"viewport":{[^}]*}')"

# 2. Drag the column's splitter 100 px left with real X events, quit with Ctrl+Q.
export ANTUMBRA_CONFIG_DIR="$tmp/config"
cat > "$tmp/drag.sh" <<'DRIVER'
#!/usr/bin/env bash
set -u
log="$1/log.txt"
shift
"$@" > "$log" 2>&1 &
editor=$!
source "$editor_driver"
wait_for "first frame presented"
# The splitter: the column's left edge, 400 px from the right of the 1024 px window.
step mousemove 627 300
step mousedown 1
step mousemove 577 300
step mousemove 527 300
step mouseup 1
wait_for "graph resized to 524x570"
quit_editor $editor
DRIVER
chmod +x "$tmp/drag.sh"
xvfb-run -a -s "-screen 0 1280x800x24" "$tmp/drag.sh" "$tmp" "$antumbra" edit \
  "${edit_args[@]}" --frame-log --layout-report "$tmp/dragged.json" > "$tmp/driver.txt" 2>&1
grep -q "editor exit 0" "$tmp/driver.txt" || fail "the dragging run did not exit 0"
check_report "$tmp/dragged.json" 'r["column_width"] == 500' 'r["viewport"]["width"] == 524' \
  || fail "layout after the drag"
grep -q "column_width=500" "$tmp/config/editor.ini" || fail "the dragged width was not saved"

# 3. A restart with the same config folder opens with the dragged layout.
rm -f "$tmp/driver.txt"
xvfb-run -a -s "-screen 0 1280x800x24" "$antumbra" edit "${edit_args[@]}" --frames 3 \
  --layout-report "$tmp/restart.json" >"$log" 2>&1 || fail "the restart exited with $?"
grep -q "editor: layout from $tmp/config/editor.ini" "$log" || fail "the restart did not read the layout"
check_report "$tmp/restart.json" 'r["column_width"] == 500' 'r["viewport"]["width"] == 524' \
  || fail "the layout did not survive the restart"

# 4. A corrupt layout file: the defaults, with a message naming it.
printf '\x7fELF\x01\x00\xff garbage\n[antumbra]\ncolumn_width=wide\n' > "$tmp/config/editor.ini"
xvfb-run -a -s "-screen 0 1280x800x24" "$antumbra" edit "${edit_args[@]}" --frames 2 \
  --layout-report "$tmp/corrupt.json" >"$log" 2>&1 || fail "a corrupt layout file made edit exit $?"
grep -q "editor.ini: line .*defaults used" "$log" || fail "no message about the corrupt layout file"
check_report "$tmp/corrupt.json" 'r["column_width"] == 400' || fail "layout from a corrupt file"
echo "PASS: editor layout test"
