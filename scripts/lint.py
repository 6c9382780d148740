#!/usr/bin/env python3
"""make lint: clang-format and clang-tidy over the project's own C++ sources.

clang-format: every tracked .cpp/.hpp/.h file must already be formatted (no diff).
Layers: the include rules of docs/architecture.md (scripts/lint_layers.py).
Vulkan 1.3 core commands: no source calls those a Vulkan 1.2 device offers only through
extensions (vkCmdBeginRendering, ...); they go through engine/core's vk_commands.hpp.
clang-tidy: every translation unit of the build's compile_commands.json that lives in the
repository is checked with the repository's .clang-tidy. Its WarningsAsErrors (naming,
function size) fail the run; other findings are printed and counted.

clang-tidy is slow (seconds per file), so a clean result is remembered outside the clone
(ANTUMBRA_TIDY_CACHE, default ~/.cache/antumbra-tidy) under a key made of the clang-tidy
version, the .clang-tidy file and the preprocessed translation unit: a file is checked
again only when it, or anything it includes, changed. Failures are never cached.
"""

import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path

import lint_layers

ROOT = Path(__file__).resolve().parent.parent


def run(cmd, **kwargs):
    return subprocess.run(cmd, capture_output=True, text=True, **kwargs)


def tracked_sources():
    out = run(["git", "ls-files", "*.cpp", "*.hpp", "*.h"], cwd=ROOT, check=True).stdout
    return [line for line in out.splitlines() if line]


def check_format(files):
    result = run(["clang-format", "--dry-run", "--Werror", *files], cwd=ROOT)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        sys.stderr.write("lint: clang-format: the files above are not formatted "
                         "(run clang-format -i on them)\n")
        return False
    print(f"lint: clang-format: {len(files)} files formatted")
    return True


# Vulkan 1.3 commands that a 1.2 device (RenderDoc 1.24 reports every device as one) has
# only under their KHR names: called directly, they crash there. vk_commands.cpp binds them.
PROMOTED_COMMANDS = re.compile(
    r"\bvk(CmdBeginRendering|CmdEndRendering|CmdPipelineBarrier2|CmdWriteTimestamp2|"
    r"QueueSubmit2|GetDeviceImageMemoryRequirements|GetDeviceBufferMemoryRequirements|"
    r"CmdSetEvent2|CmdWaitEvents2|CmdResetEvent2|CmdCopyBuffer2|CmdCopyImage2|CmdBlitImage2|"
    r"CmdCopyBufferToImage2|CmdCopyImageToBuffer2|CmdResolveImage2)\s*\(")
PROMOTED_ALLOWED = {"engine/core/src/vk_commands.cpp"}


def check_promoted_commands(files):
    failures = 0
    for name in files:
        if name in PROMOTED_ALLOWED or not (ROOT / name).is_file():
            continue
        text = (ROOT / name).read_text(errors="replace")
        for number, line in enumerate(text.splitlines(), 1):
            match = PROMOTED_COMMANDS.search(line)
            if match:
                failures += 1
                sys.stderr.write(f"{name}:{number}: vk{match.group(1)} is Vulkan 1.3 core; call "
                                 "its antumbra::gpu wrapper (antumbra/gpu/vk_commands.hpp), "
                                 "which Vulkan 1.2 devices support through extensions\n")
    if failures:
        sys.stderr.write(f"lint: {failures} direct call(s) of Vulkan 1.3 commands\n")
        return False
    print(f"lint: Vulkan 1.3 commands: {len(files)} files call none directly")
    return True


def preprocess_key(entry, salt):
    """The TU as the compiler sees it (no line markers, so the clone's path does not matter)."""
    args = entry.get("arguments") or shlex.split(entry["command"])
    # Drop the launcher (ccache through cmake -E env ...) and the output.
    while args and not (args[0].endswith("c++") or args[0].endswith("g++") or
                        args[0].endswith("clang++") or args[0].endswith("cc") or
                        args[0].endswith("gcc") or args[0].endswith("clang")):
        args = args[1:]
    clean = []
    skip = False
    for a in args:
        if skip:
            skip = False
            continue
        if a in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
            continue
        if a in ("-c", "-MD", "-MMD"):
            continue
        clean.append(a)
    result = run([*clean, "-E", "-P"], cwd=entry["directory"])
    digest = hashlib.sha256(salt)
    # __FILE__ expands to absolute paths: hash them relative to the clone.
    text = result.stdout.replace(str(ROOT), "") if result.returncode == 0 else None
    digest.update(text.encode() if text is not None else os.urandom(16))
    digest.update(entry["file"].replace(str(ROOT), "").encode())
    return digest.hexdigest()


def tidy_one(entry, build, cache, salt):
    """(file, ok, from cache, findings): ok is false when an error-level finding exists."""
    key = preprocess_key(entry, salt)
    marker = cache / key
    if marker.exists():
        return entry["file"], True, True, marker.read_text().replace("@ROOT@", str(ROOT))
    # The database holds GCC's command lines: clang must not fail on GCC-only warning flags.
    result = run(["clang-tidy", "-p", str(build), "--quiet",
                  "--extra-arg=-Wno-unknown-warning-option", entry["file"]], cwd=ROOT)
    findings = result.stdout
    ok = result.returncode == 0 and " error: " not in findings
    if ok:
        marker.write_text(findings.replace(str(ROOT), "@ROOT@"))
    return entry["file"], ok, False, findings + ("" if ok else result.stderr)


def check_tidy(build, jobs, cache):
    database = build / "compile_commands.json"
    if not database.exists():
        sys.stderr.write(f"lint: {database} is missing (configure first: make configure)\n")
        return False
    entries = [e for e in json.loads(database.read_text())
               if Path(e["file"]).resolve().is_relative_to(ROOT)
               and not Path(e["file"]).resolve().is_relative_to(build.resolve())]
    cache.mkdir(parents=True, exist_ok=True)
    version = run(["clang-tidy", "--version"]).stdout
    salt = (version + (ROOT / ".clang-tidy").read_text()).encode()
    failures = 0
    cached = 0
    warnings = 0
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(tidy_one, e, build, cache, salt) for e in entries]
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            file, ok, hit, output = future.result()
            cached += hit
            name = os.path.relpath(file, ROOT)
            warnings += output.count(" warning: ")
            if not ok:
                failures += 1
            sys.stdout.write(output)
            if not hit:
                print(f"lint: clang-tidy [{done}/{len(entries)}] {name}: "
                      f"{'clean' if ok else 'FAILED'}", flush=True)
    print(f"lint: clang-tidy: {len(entries)} translation units ({cached} unchanged since their "
          f"last run), {failures} with findings, {warnings} warnings, "
          f"{time.monotonic() - started:.0f} s")
    return failures == 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.environ.get("BUILD", "build"))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--format-only", action="store_true")
    args = parser.parse_args()
    cache = Path(os.environ.get("ANTUMBRA_TIDY_CACHE",
                                Path.home() / ".cache" / "antumbra-tidy"))
    sources = tracked_sources()
    ok = check_format(sources)
    ok = check_promoted_commands(sources) and ok
    ok = lint_layers.report(ROOT) and ok
    if not args.format_only:
        ok = check_tidy((ROOT / args.build).resolve() if not Path(args.build).is_absolute()
                        else Path(args.build), args.jobs, cache) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
