# Sourced by the editor window tests: a temporary folder (removed on exit) with its own
# shader cache and layout folder, a copy of the scene given as $1 and of the default graph
# whose schema reference points back into the tree. Copies, because the editor writes
# recovery files beside what it edits, never into the tree. Needs $source_root; sets $tmp.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ANTUMBRA_CACHE_DIR="$tmp/cache"
# The editor's layout file (editor.ini): here, never the user's own.
export ANTUMBRA_CONFIG_DIR="$tmp/config"
# What the xdotool driver scripts (written into $tmp) source.
export editor_driver
editor_driver="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/editor_driver.sh"
cp "$1" "$tmp/scene.json"
sed 's|"../schema/|"'"$source_root"'/data/schema/|' "$source_root/data/graphs/layered-ssss.json" \
  > "$tmp/graph.json"
