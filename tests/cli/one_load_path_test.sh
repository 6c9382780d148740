#!/usr/bin/env bash
# One load path and one edit session (docs/architecture.md), kept so: the hosts of the
# library (app/, editor/, runtime/) turn a graph file into a graph only through
# fg::read_graph / fg::compile_graph / RenderSession::load_graph, and the two editors
# reach the renderer only through editor::EditSession. A command that parses or compiles a
# graph itself (parse_graph, fg::compile, the compile_file/compile_text wrappers tests
# use), or an editor host that syncs the scene, loads a graph or reads the cap itself,
# bypasses the path's diagnostics and the session's tests: this fails and names the line.
set -u
root=$1
cd "$root" || exit 2
status=0
report() {  # report RULE GREP-OUTPUT
  [ -z "$2" ] && return
  echo "$2"
  echo "FAIL: $1"
  status=1
}
# The load path's second half is the one place that compiles for a device.
hits=$(grep -rnE '\b(parse_graph|compile_document|compile_file|compile_text)[[:space:]]*\(|\bcompile[[:space:]]*\(' \
  app editor runtime --include='*.cpp' --include='*.hpp' | grep -v '^runtime/src/render_session.cpp:')
report "a host reads or compiles a graph outside the one load path (fg/graph_source.hpp)" "$hits"
hits=$(grep -nE '\.(set_scene|set_lights|load_graph)[[:space:]]*\(|\blayer_cap[[:space:]]*\(' \
  app/edit_script.cpp $(ls editor/app/src/*.cpp | grep -v session_renderer.cpp))
report "an editor host does the edit session's work (antumbra/editor/edit_session.hpp)" "$hits"
[ $status -eq 0 ] && echo "one load path, one edit session: no host bypasses them"
exit $status
