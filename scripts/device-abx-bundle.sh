#!/usr/bin/env bash
# scripts/device-abx-bundle.sh NAME=ROOT [NAME=ROOT ...]: bundles several builds of
# antumbra for scripts/device-abx.py into .abx.tar.xz at the repository root (ignored by
# git through .git/info/exclude); `run` on the device with carry [".abx.tar.xz"], then
#   tar -xJf .abx.tar.xz -C /tmp && OUT=$OUT python3 /tmp/abx/abx.py --pair A:B --group ...
# ROOT is a checkout whose build/app/antumbra is built (its data/ and passes/ go along);
# NAME is how the report names it (its commit when ROOT is a git checkout). The shared
# libraries come from the first build's ../shared/tools/device-bundle.sh plus whatever the
# others link that it lacks (docs/measuring.md, "Several programs in one device call").
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/abx"
first=""
for spec in "$@"; do
  name=${spec%%=*}
  src=$(cd "${spec#*=}" && pwd)
  [ -z "$first" ] && first=$src
  dest=$work/abx/$name
  mkdir -p "$dest/bin"
  cp "$src/build/app/antumbra" "$dest/bin/"
  strip "$dest/bin/antumbra"
  cp -a "$src/data" "$src/passes" "$dest/"
  git -C "$src" rev-parse --short HEAD > "$dest/REV" 2>/dev/null || echo "$name" > "$dest/REV"
done
[ -n "$first" ] || { echo "usage: $0 NAME=ROOT [NAME=ROOT ...]" >&2; exit 2; }
"$repo/../shared/tools/device-bundle.sh" "$first/build/app/antumbra" "$work/b" > /dev/null
mv "$work/b/lib" "$work/abx/lib"
for spec in "$@"; do
  src=$(cd "${spec#*=}" && pwd)
  ldd "$src/build/app/antumbra" | awk '/=> \//{print $1" "$3}' | while read -r so path; do
    [[ "$so" =~ ^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv\.so) ]] && continue
    [ -f "$work/abx/lib/$so" ] || cp -L "$path" "$work/abx/lib/$so"
  done
done
cp "$repo/scripts/device-abx.py" "$work/abx/abx.py"
git_dir=$(git -C "$repo" rev-parse --git-common-dir)
grep -qx "/.abx.tar.xz" "$git_dir/info/exclude" 2>/dev/null || echo "/.abx.tar.xz" >> "$git_dir/info/exclude"
tar -C "$work" -cJf "$repo/.abx.tar.xz" abx
du -sh "$repo/.abx.tar.xz"
