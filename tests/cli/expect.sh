#!/usr/bin/env bash
# expect.sh CODE [--stdout REGEX] [--stdout-not REGEX] [--stderr REGEX] -- COMMAND...
# Runs COMMAND and fails unless it exits with CODE and its output matches (and stdout
# has no line matching the --stdout-not REGEX).
set -u
want=$1; shift
out_re=""; out_not_re=""; err_re=""
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --stdout) out_re=$2; shift 2 ;;
    --stdout-not) out_not_re=$2; shift 2 ;;
    --stderr) err_re=$2; shift 2 ;;
    *) echo "expect.sh: unknown option $1" >&2; exit 99 ;;
  esac
done
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
timeout 600 "$@" >"$tmp/out" 2>"$tmp/err"
got=$?
status=0
if [ "$got" != "$want" ]; then echo "exit code $got, expected $want" >&2; status=1; fi
if [ -n "$out_re" ] && ! grep -Eq -- "$out_re" "$tmp/out"; then echo "stdout does not match /$out_re/" >&2; status=1; fi
if [ -n "$out_not_re" ] && grep -Eq -- "$out_not_re" "$tmp/out"; then echo "stdout matches /$out_not_re/" >&2; status=1; fi
if [ -n "$err_re" ] && ! grep -Eq -- "$err_re" "$tmp/err"; then echo "stderr does not match /$err_re/" >&2; status=1; fi
if [ "$status" != 0 ]; then
  echo "--- command: $*" >&2
  echo "--- stdout:" >&2; head -c 4000 "$tmp/out" >&2
  echo "--- stderr:" >&2; head -c 4000 "$tmp/err" >&2
fi
exit $status
