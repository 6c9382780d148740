#!/usr/bin/env bash
# quality --out on lavapipe at a tiny size: one error heat map per technique, the size
# of the frame and not blank; the JSON report names them and carries the warning that
# this size cannot rank techniques.
# usage: quality_error_maps_test.sh ANTUMBRA PNG_STATS SOURCE_DIR
set -u
antumbra=$1 png_stats=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

"$antumbra" quality --validation --size 64x36 --format json --out "$tmp/maps" \
  --graph data/graphs/hard.json --graph data/graphs/pcss.json >"$tmp/out" 2>"$tmp/err" ||
  { cat "$tmp/err" >&2; fail "quality exited $?"; }
grep -q '"code": "QU001"' "$tmp/out" || fail "no QU001 in the JSON diagnostics"
grep -q '"errorMapScale"' "$tmp/out" || fail "no errorMapScale in the JSON report"
for technique in hard pcss; do
  map="$tmp/maps/$technique-error.png"
  grep -q "\"errorMap\": \"$map\"" "$tmp/out" || fail "the report does not name $map"
  stats=$("$png_stats" "$map") || fail "$map is not a PNG"
  case "$stats" in
    "64x36 colours=1") fail "$map is blank" ;;
    "64x36 colours="*) ;;
    *) fail "$map: $stats, expected 64x36" ;;
  esac
done
echo "ok: $(ls "$tmp/maps")"
