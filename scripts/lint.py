#!/usr/bin/env python3
"""make lint: clang-format and clang-tidy over the project's own C++ sources.

clang-format: every tracked .cpp/.hpp/.h file must already be formatted (no diff).
Layers: the include rules of docs/architecture.md (scripts/lint_layers.py).
GLSL: every tracked shader (.comp .frag .vert .glsl ...) must be formatted by the same
.clang-format, and no function in a shader or in a header the shaders share with C++
(passes/**/*_interface.h, passes/interface/shared/*.h) may exceed 80 lines, counted as
clang-tidy counts C++ functions. Both run in --format-only too (make format-check).
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


def check_format(files, what="", extra=()):
    result = run(["clang-format", "--dry-run", "--Werror", *extra, *files], cwd=ROOT)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        sys.stderr.write(f"lint: clang-format{what}: the files above are not formatted "
                         f"(run clang-format -i {' '.join(extra)} on them)\n")
        return False
    print(f"lint: clang-format{what}: {len(files)} files formatted")
    return True


# Shaders, and the headers the shaders share with C++ (docs/architecture.md, "One source for
# CPU and GPU"; the C++ stage formats those). tests/lint/ holds deliberately broken shaders
# that tests/lint feeds in by name.
GLSL_STAGES = ["*.comp", "*.frag", "*.vert", "*.geom", "*.tesc", "*.tese", "*.glsl"]
GLSL_HEADERS = ["passes/*_interface.h", "passes/interface/shared/*.h"]
GLSL_FIXTURES = "tests/lint/"
# clang-tidy's readability-function-size.LineThreshold in .clang-tidy.
MAX_FUNCTION_LINES = 80


def tracked_glsl():
    out = run(["git", "ls-files", *GLSL_STAGES, *GLSL_HEADERS], cwd=ROOT, check=True).stdout
    return [line for line in out.splitlines() if line and not line.startswith(GLSL_FIXTURES)]


def check_glsl_format(files):
    """clang-format reads the shaders as C++ (it does for these extensions) with the C++ style.

    Include sorting is off: in GLSL a #include is pasted text, and several shaders define
    macros or declare blocks that a later include reads, so their order is meaning.
    """
    stages = [f for f in files if not f.endswith(".h")]
    return check_format(stages, " (GLSL)", ("--sort-includes=false",)) if stages else True


def strip_comments(text):
    """The text with comments and string literals blanked, newlines kept (for line numbers)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


# The head of a function definition: a return type, the name and the parameters, then "{".
# ANTUMBRA_PUSH_CONSTANTS(Name) { has no type before its "name", so it is no function.
FUNCTION_HEAD = re.compile(r"(?:^|[\s;])(?!return\b|else\b)[A-Za-z_]\w*(?:\s*\[[^\]]*\])?"
                           r"\s+([A-Za-z_]\w*)\s*\((?:[^;{}()]|\([^;{}()]*\))*\)\s*(?:const\s*)?$")


class BraceState:
    """The open braces, each None or the function it opens (name, the name's line, the
    brace's line), and the text read since the last statement or brace (the head)."""

    def __init__(self):
        self.stack = []
        self.head = ""

    def copy(self):
        other = BraceState()
        other.stack = list(self.stack)
        other.head = self.head
        return other


def directive(state, line, conditionals):
    """Preprocessor conditionals: every arm is read, each starting from the state before the
    #if, and after #endif the first arm's state goes on (arms balance their braces alike)."""
    word = re.match(r"\s*#\s*(\w*)", line).group(1)
    if word in ("if", "ifdef", "ifndef"):
        conditionals.append([state.copy(), None])
    elif word in ("elif", "else") and conditionals:
        if conditionals[-1][1] is None:
            conditionals[-1][1] = state.copy()
        return conditionals[-1][0].copy()
    elif word == "endif" and conditionals:
        _, first_arm = conditionals.pop()
        return first_arm if first_arm is not None else state
    state.head = ""
    return state


def code(state, text, number, functions):
    for char in text:
        if char == "{":
            inside = any(entry is not None for entry in state.stack)
            match = None if inside else FUNCTION_HEAD.search(state.head)
            # clang-tidy reports at the name; the head may span lines.
            name_line = number - state.head[match.start(1):].count("\n") if match else 0
            state.stack.append((match.group(1), name_line, number) if match else None)
            state.head = ""
        elif char == "}":
            entry = state.stack.pop() if state.stack else None
            if entry is not None:
                functions.append((entry[1], entry[0], number - entry[2]))
            state.head = ""
        elif char == ";":
            state.head = ""
        else:
            state.head += char
    state.head += "\n"


def glsl_functions(text):
    """(line of the name, name, lines) of every function definition in the text.

    Lines are counted as clang-tidy's readability-function-size counts them for
    LineThreshold: the line of the closing brace minus the line of the opening one, blank
    and comment lines included. #define bodies are skipped (a macro is no function).
    """
    state = BraceState()
    conditionals = []
    functions = []
    continued = False
    for number, line in enumerate(strip_comments(text).splitlines(), 1):
        in_directive = continued or line.lstrip().startswith("#")
        if in_directive and not continued:
            state = directive(state, line, conditionals)
        elif not in_directive:
            code(state, line, number, functions)
        continued = in_directive and line.rstrip().endswith("\\")
    return functions


def check_glsl_function_size(files):
    failures = 0
    count = 0
    for name in files:
        functions = glsl_functions((ROOT / name).read_text())
        count += len(functions)
        for line, function, lines in functions:
            if lines <= MAX_FUNCTION_LINES:
                continue
            failures += 1
            sys.stderr.write(f"{name}:{line}: function '{function}' has {lines} lines "
                             f"(max {MAX_FUNCTION_LINES}): split it into named helpers\n")
    if failures:
        sys.stderr.write(f"lint: {failures} GLSL function(s) longer than {MAX_FUNCTION_LINES} "
                         "lines\n")
        return False
    print(f"lint: GLSL: {count} functions in {len(files)} files, each at most "
          f"{MAX_FUNCTION_LINES} lines")
    return True


def check_glsl(files):
    missing = [name for name in files if not (ROOT / name).is_file()]
    if missing:
        sys.stderr.write(f"lint: no such GLSL file (paths are relative to {ROOT}): "
                         f"{', '.join(missing)}\n")
        return False
    ok = check_glsl_format(files)
    return check_glsl_function_size(files) and ok


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
    # Every .clang-tidy of the tree (tests/ narrows the checks): a change to any of them
    # checks every unit again.
    configs = run(["git", "ls-files", ".clang-tidy", "*/.clang-tidy"], cwd=ROOT,
                  check=True).stdout.split()
    salt = (version + "".join((ROOT / f).read_text() for f in sorted(configs))).encode()
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
    parser.add_argument("--glsl", nargs="*", metavar="FILE",
                        help="only the GLSL checks, over FILEs (default: every tracked shader)")
    args = parser.parse_args()
    if args.glsl is not None:
        return 0 if check_glsl(args.glsl or tracked_glsl()) else 1
    cache = Path(os.environ.get("ANTUMBRA_TIDY_CACHE",
                                Path.home() / ".cache" / "antumbra-tidy"))
    sources = tracked_sources()
    ok = check_format(sources)
    ok = check_promoted_commands(sources) and ok
    ok = lint_layers.report(ROOT) and ok
    ok = check_glsl(tracked_glsl()) and ok
    if not args.format_only:
        ok = check_tidy((ROOT / args.build).resolve() if not Path(args.build).is_absolute()
                        else Path(args.build), args.jobs, cache) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
