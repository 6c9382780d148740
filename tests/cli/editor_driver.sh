# Sourced by the scripts that drive an editor window with xdotool (under xvfb-run, with
# `edit --frame-log` writing to $log): waiting on the log's frame lines, so each event is
# seen by a frame of its own however slow lavapipe is. Needs $log; the editor's pid is
# the caller's.
frames() { grep -c '^editor: frame ' "$log"; }
# Waits (up to 60 s) until `pattern` is in the log.
wait_for() {
  for _ in $(seq 1 600); do grep -q "$1" "$log" && return 0; sleep 0.1; done
  echo "timed out waiting for: $1"
  return 1
}
# Each event, then two whole frames: the frame that polled it has finished with it.
step() {
  local before
  before=$(frames)
  xdotool "$@"
  for _ in $(seq 1 600); do [ "$(frames)" -ge $((before + 2)) ] && return 0; sleep 0.1; done
  echo "timed out after: xdotool $*"
}
# `n` more whole frames.
settle() {
  local before
  before=$(frames)
  for _ in $(seq 1 600); do [ "$(frames)" -ge $((before + $1)) ] && return 0; sleep 0.1; done
  echo "timed out waiting for $1 frames"
}
# Ctrl+Q, then waits (up to 60 s) for the editor ($1) to close and says how it exited.
quit_editor() {
  xdotool key ctrl+q  # no frames follow: the editor closes
  for _ in $(seq 1 600); do kill -0 "$1" 2>/dev/null || break; sleep 0.1; done
  kill "$1" 2>/dev/null && echo "the editor did not close on Ctrl+Q"
  wait "$1"
  echo "editor exit $?"
}
