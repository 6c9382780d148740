#!/usr/bin/env bash
# The node view driven by real input events (Xvfb + xdotool, lavapipe, validation on), from
# the default window size on the default graph: F2 opens it; the palette adds a
# colour-grade pass; two drags wire it between lighting and tonemap; its exposure set in
# the graph panel brightens the frame; Ctrl+Z takes that back, Ctrl+Shift+Z brings it
# again; Ctrl+S saves. Checked in screenshots (F12 with --shots: the wire drawn, the image
# brighter, then as before, then brighter), the saved graph (the pass, its bindings, its
# exposure) and the layout report (the node view beside the viewport, not over it).
# Widgets are found where the editor says they are (--frame-log prints the node view's
# ports and the graph panel's fields). Skips (exit 77) only without xvfb-run or xdotool.
set -u
antumbra=$1
source_root=$2
png_stats=$3
command -v xvfb-run >/dev/null 2>&1 || { echo "SKIP: xvfb-run is not installed"; exit 77; }
command -v xdotool >/dev/null 2>&1 || { echo "SKIP: xdotool is not installed"; exit 77; }
source "$(dirname "$0")/editor_test_setup.sh" "$source_root/tests/data/editor/viewport.json"
mkdir -p "$tmp/shots"

cat > "$tmp/input.sh" <<'INPUT'
#!/usr/bin/env bash
set -u
log="$2/log.txt"
"$1" edit --validation --frame-log --shots "$2/shots" --scene "$2/scene.json" \
  --graph "$2/graph.json" --layout-report "$2/report.json" > "$log" 2>&1 &
editor=$!
source "$editor_driver"
# Where the editor last said a target is: "X Y".
at() { grep ": at [0-9]* [0-9]*: $1\$" "$log" | tail -1 | sed 's/.*: at \([0-9]*\) \([0-9]*\): .*/\1 \2/'; }
shot() { step key F12; settle 2; }
# ImGui (1.86) reads keys as held or not once a frame: a key pressed and released within one
# frame is never seen, so Enter is held over a frame. (Typed text and the window's own
# shortcuts are queued events, and a quick click is latched: those need no holding.)
enter() { step keydown Return; step keyup Return; }
drag() {
  local x1 y1 x2 y2
  read -r x1 y1 <<<"$(at "port $1")"
  read -r x2 y2 <<<"$(at "port $2")"
  echo "drag $1 ($x1 $y1) -> $2 ($x2 $y2)"
  step mousemove "$x1" "$y1" mousedown 1
  step mousemove $(((x1 + x2) / 2)) $(((y1 + y2) / 2))
  step mousemove "$x2" "$y2"
  step mouseup 1
  settle 3
}
wait_for "first frame presented"
settle 2
shot                                   # shot-1: before
step key F2
wait_for "node view: at [0-9]* [0-9]*: port tonemap.hdr in"
settle 2
read -r x y <<<"$(at "button Add pass")"
step mousemove "$x" "$y" click 1
settle 2
step type colour-grade
enter
wait_for "port colour-grade.source in"
settle 3
drag "lighting.hdr out" "colour-grade.source in"
drag "colour-grade.hdr out" "tonemap.hdr in"
settle 3
# The wire from the new pass to tonemap: its midpoint (the curve's, by symmetry).
read -r x1 y1 <<<"$(at "port colour-grade.hdr out")"
read -r x2 y2 <<<"$(at "port tonemap.hdr in")"
echo "wire $(((x1 + x2) / 2)) $(((y1 + y2) / 2))" > "$2/wire.txt"
# Off the node view: the port the last drag ended on shows a tooltip, which may cover
# the wire's midpoint (it did once a node grew a port and the layout moved).
step mousemove 200 200
settle 2
shot                                   # shot-2: wired, exposure 0 (the image as before)
wait_for "graph panel: at [0-9]* [0-9]*: param colour-grade.exposure"
read -r x y <<<"$(at "param colour-grade.exposure")"
# Ctrl+click turns the drag field into a text field with its text selected.
step mousemove "$x" "$y" keydown ctrl
step mousedown 1
step mouseup 1
step keyup ctrl
settle 2
step type 2
enter
settle 4
shot                                   # shot-3: two stops brighter
step mousemove 200 200
step key ctrl+z
settle 4
shot                                   # shot-4: undone
step key ctrl+shift+z
settle 4
shot                                   # shot-5: redone
step key ctrl+s
settle 3
quit_editor $editor
INPUT
chmod +x "$tmp/input.sh"
start=$(date +%s.%N)
xvfb-run -a -s "-screen 0 1400x800x24" "$tmp/input.sh" "$antumbra" "$tmp" > "$tmp/driver.txt" 2>&1
end=$(date +%s.%N)
log="$tmp/log.txt"
fail() { echo "FAIL: $*"; echo "--- driver:"; cat "$tmp/driver.txt"; echo "--- log:"; grep -v "^node view: at\|^graph panel: at" "$log"; exit 1; }
grep -q "editor exit 0" "$tmp/driver.txt" || fail "the editor did not exit 0 on Ctrl+Q"
grep -q "validation: 0 error(s)" "$log" || fail "no clean validation summary"
for n in 1 2 3 4 5; do [ -s "$tmp/shots/shot-$n.png" ] || fail "no screenshot shot-$n.png"; done

# The saved graph: the pass, wired from lighting's hdr and into tonemap, exposure 2.
python3 - "$tmp/graph.json" <<'PY' || fail "the saved graph is not wired as dragged"
import json, sys
g = json.load(open(sys.argv[1]))
passes = {p["name"]: p for p in g["passes"]}
grade = next(p for p in g["passes"] if p["type"] == "colour-grade")
assert grade["in"]["source"] == passes["lighting"]["out"]["hdr"], grade
out = grade["out"]["hdr"]
assert passes["tonemap"]["in"]["hdr"] == out, passes["tonemap"]
assert out in g["resources"], out
assert grade.get("params", {}).get("exposure") == 2, grade
print("saved:", grade["name"], grade["in"], grade["out"], grade.get("params"))
PY

# The viewport (the report's, in pixels): brightness in each shot.
read -r vx vy vw vh <<<"$(python3 -c "
import json; r = json.load(open('$tmp/report.json'))
v = r['viewport']; n = r.get('node_view')
assert n, 'no node view in the layout report'
assert n['y'] >= v['y'] + v['height'] or n['x'] >= v['x'] + v['width'], 'the node view covers the viewport'
print(v['x'], v['y'], v['width'], v['height'])")" || fail "the layout report: node view missing or over the viewport"
mean() { "$png_stats" "$tmp/shots/shot-$1.png" "$vx" "$vy" "$vw" "$vh" | awk '{ sub("mean=", ""); print ($1 + $2 + $3) / 3 }'; }
m1=$(mean 1) m2=$(mean 2) m3=$(mean 3) m4=$(mean 4) m5=$(mean 5)
echo "viewport means: before $m1, wired $m2, exposure 2 $m3, undone $m4, redone $m5"
# The node view took height from the viewport between shots 1 and 2, so shot 2 (not 1) is
# the base: the wired pass at exposure 0 changes nothing, exposure 2 brightens.
awk -v a="$m2" -v b="$m3" 'BEGIN { exit !(b > a * 1.2 + 1) }' || fail "exposure 2 did not brighten the frame"
awk -v a="$m2" -v b="$m4" 'BEGIN { d = b - a; exit !(d < 2 && d > -2) }' || fail "Ctrl+Z did not bring the frame back"
awk -v a="$m3" -v b="$m5" 'BEGIN { d = b - a; exit !(d < 2 && d > -2) }' || fail "Ctrl+Shift+Z did not redo the exposure"
# The wire drawn from colour-grade to tonemap: an image-coloured pixel at its middle.
read -r _ wx wy < "$tmp/wire.txt"
found=""
for dy in -2 -1 0 1 2; do
  p=$("$png_stats" "$tmp/shots/shot-2.png" "$wx" $((wy + dy)))
  read -r r g b <<<"${p#pixel=}"
  [ "$b" -gt 180 ] && [ "$r" -lt 170 ] && found="$p at $wx $((wy + dy))"
done
[ -n "$found" ] || fail "no wire drawn at $wx $wy between colour-grade.hdr and tonemap.hdr"
echo "wire: $found"
echo "PASS: node view test in $(awk "BEGIN { printf \"%.1f\", $end - $start }") s"
