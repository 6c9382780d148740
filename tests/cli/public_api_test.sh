#!/usr/bin/env bash
# Antumbra's own program is a host of the public API (docs/integration.md): every header
# the command line (app/) and the editor (editor/) include is their own or one the
# installed package ships, so what an engine gets is what the program uses, and it cannot
# rot. Installs the build into a temporary prefix and resolves each quoted include.
set -u
root=$1
build=$2
cd "$root" || exit 2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > "$prefix.log" 2>&1 || { cat "$prefix.log"; exit 2; }
rm -f "$prefix.log"
own=(app editor/model/include editor/model/src editor/app/include editor/app/src)
status=0
checked=0
while IFS=: read -r file line text; do
  header=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<< "$text")
  found=""
  for dir in "$(dirname "$file")" "${own[@]}" "$prefix/include" "$prefix/include/antumbra/passes" \
    "$prefix/include/antumbra/passes/interface"; do
    [ -f "$dir/$header" ] && { found=$dir; break; }
  done
  checked=$((checked + 1))
  if [ -z "$found" ]; then
    echo "$file:$line: includes \"$header\", which the installed package does not ship"
    status=1
  fi
done < <(grep -rnE '^#include "' app editor --include='*.cpp' --include='*.hpp')
if [ $status -eq 0 ]; then
  echo "app/ and editor/: $checked includes, each their own or an installed header"
else
  echo "FAIL: a host of the library includes a header outside the public API"
fi
exit $status
