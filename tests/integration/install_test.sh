#!/usr/bin/env bash
# The installed package as a host sees it (docs/integration.md, "Installing and finding the
# package"): `cmake --install` of this build into a temporary prefix, the consumer project
# of tests/integration/consumer/ configured and built against it, then the prefix moved and
# everything run again from the new place.
#   framegraph (CPU): no path of this machine's source or build folder in any installed file;
#     every quoted #include of an installed header or shader resolves inside the prefix;
#     find_package(Antumbra COMPONENTS framegraph) with every other dependency's package
#     disabled (Vulkan first), graph_check built and run; moved: `antumbra validate` of the
#     installed graphs, the consumer reconfigured and run again.
#   runtime (GPU, lavapipe): find_package(Antumbra), render_frames (two validated frames of
#     the installed default graph and scene through a RenderSession) built and run; moved:
#     `antumbra validate` and `antumbra render --validation`, the consumer reconfigured,
#     rebuilt and run again.
#   host (GPU, lavapipe): examples/host, an engine with its own window, device and overlay
#     (docs/integration.md, "A host in 200 lines"), built against the prefix; headless and
#     validated, its frame of examples/host/scene.json within the golden tolerance of
#     `antumbra render`'s, its overlay changing the overlay's rows alone; windowed under Xvfb
#     when xvfb-run is there; moved: reconfigured, rebuilt and run on its scene built in code.
#   The GPU modes skip (77) without a Vulkan device, unless ANTUMBRA_REQUIRE_GPU is set (CI),
#   where they fail.
# Usage: install_test.sh framegraph|runtime|host BUILD_DIR SOURCE_DIR CMAKE GENERATOR CXX
#          [CCACHE [PNG_COMPARE]]
set -u
mode=$1
build=$2
source_root=$3
cmake=$4
generator=$5
cxx=$6
ccache=${7:-}
png_compare=${8:-}  # tests/integration/png_compare.cpp, built in this build (host mode)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
log="$tmp/log.txt"
: >"$log"
fail() { echo "FAIL: $*"; echo "--- log:"; tail -n 80 "$log"; exit 1; }
started=$(date +%s.%N)
elapsed() { awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $started }"; }
step() { echo "[$(elapsed) s] $*"; }

# Outside every source tree, so the programs cannot find data/ by walking up from here.
cd "$tmp" || fail "cannot enter $tmp"
unset ANTUMBRA_ROOT
"$cmake" --install "$build" --prefix "$tmp/P" >>"$log" 2>&1 || fail "cmake --install failed"
step "installed into a temporary prefix"

# The projects' sources and build folders lie under $tmp, and ccache sees paths relative to
# it, so a rerun (another temporary folder, another clone) hits the cache.
project=consumer  # the project configure() builds: tests/integration/consumer or examples/host
if [ "$mode" = host ]; then
  project=host
  cp -r "$source_root/examples/host" "$tmp/host"
else
  cp -r "$source_root/tests/integration/consumer" "$tmp/consumer"
fi
export CCACHE_BASEDIR="$tmp" CCACHE_NOHASHDIR=true
# configure BUILD_FOLDER PREFIX [cmake arguments...]
configure() {
  local dir=$1 prefix=$2
  shift 2
  "$cmake" -S "$tmp/$project" -B "$tmp/$dir" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
    ${ccache:+-DCMAKE_CXX_COMPILER_LAUNCHER="$ccache"} -DCMAKE_PREFIX_PATH="$prefix" "$@" \
    >>"$log" 2>&1 || fail "configuring the $project against $prefix failed"
  grep -q "Antumbra_DATA_DIR: $prefix/share/antumbra\$" "$log" ||
    fail "Antumbra_DATA_DIR is not $prefix/share/antumbra"
  "$cmake" --build "$tmp/$dir" --parallel 2 >>"$log" 2>&1 ||
    fail "building the $project against $prefix failed"
}
# run NAME COMMAND...: the command's output goes to the log; fails on a non-zero exit.
run() {
  local name=$1
  shift
  "$@" >>"$log" 2>&1 || fail "$name exited with $?"
}
# The first program to touch the GPU exited with $1: 77 is no Vulkan device, a skip unless
# ANTUMBRA_REQUIRE_GPU is set.
require_device() {
  if [ "$1" -eq 77 ]; then
    case "${ANTUMBRA_REQUIRE_GPU:-0}" in
      "" | 0) echo "SKIP: no Vulkan device"; exit 77 ;;
      *) fail "ANTUMBRA_REQUIRE_GPU is set, but there is no usable Vulkan device" ;;
    esac
  fi
  [ "$1" -eq 0 ] || fail "$2 exited with $1"
}

# The path as an ERE. A path of one component ("/src") would also match inside
# "engine/core/src/x.cpp", so it must stand alone there: after no letter or slash.
path_pattern() {
  local escaped
  # shellcheck disable=SC2016 # sed, not the shell, reads the $
  escaped=$(printf '%s' "$1" | sed 's/[][\.*^$()+?{}|]/\\&/g')
  case "$1" in
    /*/*) printf '%s' "$escaped" ;;
    *) printf '(^|[^[:alnum:]._/-])%s(/|$|[^[:alnum:]._-])' "$escaped" ;;
  esac
}

check_no_build_paths() {
  local path p pattern hits f
  for path in "$source_root" "$build"; do
    for p in "$path" "$(realpath "$path")"; do
      pattern=$(path_pattern "$p")
      hits=$(grep -rIlE "$pattern" "$tmp/P")
      [ -z "$hits" ] || fail "installed files name $p: $hits"
      for f in "$tmp"/P/lib/*.a "$tmp/P/bin/antumbra"; do
        if strings "$f" | grep -qE "$pattern"; then fail "$f holds the path $p"; fi
      done
    done
  done
}

# Every quoted #include of an installed header (from its own folder or the package's include
# folders) and of an installed shader (from its own folder, as the shader compiler resolves
# them) names an installed file.
check_includes() {
  local file dir name
  local roots=("$tmp/P/include" "$tmp/P/include/antumbra/passes"
    "$tmp/P/include/antumbra/passes/interface")
  while IFS= read -r -d '' file; do
    dir=$(dirname "$file")
    while IFS= read -r name; do
      [ -e "$dir/$name" ] && continue
      case "$file" in "$tmp/P/share/"*) fail "${file#"$tmp/"} includes $name: not installed" ;; esac
      found=0
      for root in "${roots[@]}"; do [ -e "$root/$name" ] && found=1; done
      [ $found -eq 1 ] || fail "${file#"$tmp/"} includes \"$name\": not installed"
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$file")
  done < <(find "$tmp/P/include" "$tmp/P/share/antumbra/passes" -type f -print0)
}

case "$mode" in
  framegraph)
    check_no_build_paths
    check_includes
    step "no build-machine path; every include resolves"
    # No package but nlohmann_json may be looked for: the graph core needs nothing else.
    disabled=()
    for package in Vulkan glslang spdlog fmt glm TinyGLTF PkgConfig Threads; do
      disabled+=("-DCMAKE_DISABLE_FIND_PACKAGE_$package=ON")
    done
    configure fg "$tmp/P" -DCONSUMER_COMPONENTS=framegraph "${disabled[@]}"
    [ -e "$tmp/fg/render_frames" ] && fail "the framegraph-only consumer built render_frames"
    run graph_check "$tmp/fg/graph_check"
    step "framegraph-only consumer built and run"
    mv "$tmp/P" "$tmp/P2"
    run "antumbra validate" "$tmp/P2/bin/antumbra" validate "$tmp"/P2/share/antumbra/data/graphs/*.json
    configure fg "$tmp/P2" -DCONSUMER_COMPONENTS=framegraph "${disabled[@]}"
    run graph_check "$tmp/fg/graph_check"
    step "moved prefix: validate, consumer reconfigured and run"
    ;;
  runtime)
    configure full "$tmp/P"
    run graph_check "$tmp/full/graph_check"
    "$tmp/full/render_frames" "$tmp/consumer.png" >>"$log" 2>&1
    require_device $? render_frames
    [ -s "$tmp/consumer.png" ] || fail "render_frames wrote no image"
    step "consumer built and run: two validated frames"
    mv "$tmp/P" "$tmp/P2"
    run "antumbra validate" "$tmp/P2/bin/antumbra" validate "$tmp"/P2/share/antumbra/data/graphs/*.json
    run "antumbra render" "$tmp/P2/bin/antumbra" render --validation --size 160x90 --frames 2 \
      --out "$tmp/x.png"
    [ -s "$tmp/x.png" ] || fail "antumbra render wrote no image"
    step "moved prefix: antumbra validate and render"
    rm "$tmp/consumer.png"
    configure full "$tmp/P2"
    run render_frames "$tmp/full/render_frames" "$tmp/consumer.png"
    [ -s "$tmp/consumer.png" ] || fail "render_frames wrote no image"
    step "moved prefix: consumer reconfigured, rebuilt and run"
    ;;
  host)
    configure host-build "$tmp/P"
    scene="$tmp/host/scene.json"
    small=(--headless --validation --frames 3 --size 160x90)
    "$tmp/host-build/host" "${small[@]}" --no-overlay --scene "$scene" --out "$tmp/a.png" \
      >>"$log" 2>&1
    require_device $? host
    run "antumbra render" "$tmp/P/bin/antumbra" render --scene "$scene" --size 160x90 --frames 3 \
      --out "$tmp/b.png"
    run "comparing host's and antumbra render's frames" "$png_compare" "$tmp/a.png" "$tmp/b.png"
    step "host built and run: its frame of scene.json is antumbra render's"
    "$tmp/host-build/host" "${small[@]}" --scene "$scene" --out "$tmp/o.png" >"$tmp/o.txt" \
      2>>"$log" || fail "host with its overlay exited with $?"
    cat "$tmp/o.txt" >>"$log"
    rows=$(sed -n 's/^host: overlay rows \([0-9]*\)-\([0-9]*\)$/\1 \2/p' "$tmp/o.txt")
    [ -n "$rows" ] || fail "host named no overlay rows"
    # shellcheck disable=SC2086 # two numbers
    run "comparing with and without the overlay" "$png_compare" "$tmp/a.png" "$tmp/o.png" \
      --rows $rows
    step "the overlay changed its rows alone"
    if command -v xvfb-run >/dev/null; then
      run "host in a window" xvfb-run -a "$tmp/host-build/host" --validation --frames 3 \
        --size 160x90
      step "host in a window under Xvfb"
      # The window resized after its first frame, as a user drags its border: a new
      # swapchain, RenderSession::resize and the new images bound, under validation.
      xvfb-run -a "$tmp/host-build/host" --validation --frames 40 --size 160x90 \
        --resize 200x120 >"$tmp/resized.txt" 2>&1 || fail "host in a resized window exited with $?"
      cat "$tmp/resized.txt" >>"$log"
      grep -q "^host: window resized to 200x120$" "$tmp/resized.txt" \
        || fail "the host's window was resized, but it never said so: $(cat "$tmp/resized.txt")"
      step "host in a window resized to 200x120 under Xvfb"
    fi
    mv "$tmp/P" "$tmp/P2"
    rm "$tmp/o.png"
    configure host-build "$tmp/P2"
    run host "$tmp/host-build/host" "${small[@]}" --out "$tmp/o.png"
    [ -s "$tmp/o.png" ] || fail "host wrote no image"
    step "moved prefix: host reconfigured, rebuilt and run on its scene built in code"
    ;;
  *) fail "unknown mode '$mode' (framegraph, runtime or host)" ;;
esac
echo "PASS: installed package ($mode), $(elapsed) s"
