#!/usr/bin/env python3
"""make lint: the layer rules of docs/architecture.md, checked on every #include.

Each source file (C++ and GLSL) belongs to the library of its folder. A quoted #include is
resolved the way the build resolves it (the including file's folder, then the libraries'
include folders) and must land in the same library or one it links, directly or below
(docs/architecture.md, section 1: every arrow points down; the graph is read from there). Besides:
- the Vulkan-free libraries (the graph core, scene, layering, editor model, base, watch,
  the shared interface) include no Vulkan header;
- no pass folder includes another pass folder, and passes/common includes none (what
  passes share lives in passes/common or passes/interface/shared);
- no pass reads a parameter by name from raw JSON (`params.find("x")`, `params["x"]`):
  its hooks and runtime read the typed values through its ParamTable.
tests/, bench/ and fuzz/ are tools over the libraries and may include any of them.

`--root DIR` checks another tree laid out like this one; `--self-test` checks the fixture
under tests/data/lint_layers (which breaks every rule once and must fail with exactly those
findings) and then this repository (which must pass).
"""

import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Folder prefix -> library, most specific first.
MODULES = [
    ("base/", "base"),
    ("framegraph/vulkan/", "fg_vulkan"),
    ("framegraph/", "framegraph"),
    ("engine/core/", "engine"),
    ("engine/scene/", "scene"),
    ("engine/watch/", "watch"),
    ("passes/interface/", "gpu_interface"),
    ("passes/light_layering/core/", "layering"),
    ("passes/", "passes"),
    ("runtime/", "runtime"),
    ("editor/model/", "editor_model"),
    ("editor/app/", "editor_app"),
    ("app/", "app"),
]
TOOLS = ("tests/", "bench/", "fuzz/")

# CMake targets -> the libraries above ("antumbra (exe)" and the app tools share app/).
TARGETS = {
    "antumbra": "app", "antumbra_app_tools": "app", "antumbra_editor_app": "editor_app",
    "antumbra_editor_model": "editor_model", "antumbra_runtime": "runtime",
    "antumbra_passes": "passes", "antumbra_fg_vulkan": "fg_vulkan",
    "antumbra_framegraph": "framegraph", "antumbra_engine": "engine", "antumbra_scene": "scene",
    "antumbra_watch": "watch", "antumbra_gpu_interface": "gpu_interface",
    "antumbra_layering": "layering", "antumbra_layering_scene": "layering",
    "antumbra_base": "base",
}
TARGET_NAME = re.compile(r"\bantumbra(?:_[a-z_]+)?(?:\(_scene\))?")


def read_links(root=ROOT):
    """What each library links directly, read from the graph of docs/architecture.md's
    section 1 (the document is the rule: a link the code needs goes there first)."""
    text = (root / "docs" / "architecture.md").read_text()
    start = text.index("Links from each `CMakeLists.txt`")
    block = text[text.index("```", start) + 3:]
    block = block[:block.index("```")]
    links, current = {module: set() for _, module in MODULES}, None
    for line in block.splitlines():
        for part in line.split(";"):
            head, arrow, tail = part.partition("->")
            if arrow:
                name = TARGET_NAME.search(head)
                current = TARGETS.get(name.group(0).replace("(_scene)", "")) if name else None
            else:
                tail = head
            tail = re.sub(r"\([^)]*private\)", "", tail)  # private third-party links
            for name in TARGET_NAME.findall(tail):
                target = TARGETS.get(name.replace("(_scene)", ""))
                if current and target and target != current:
                    links[current].add(target)
    return links


LINKS = read_links()
VULKAN_FREE = {"base", "framegraph", "scene", "watch", "layering", "editor_model",
               "gpu_interface"}

# The include folders the build adds, in the order a quoted include is searched.
INCLUDE_DIRS = [
    "base/include", "framegraph/include", "framegraph/vulkan/include", "engine/core/include",
    "engine/scene/include", "engine/watch/include", "passes/light_layering/core/include",
    "passes", "passes/interface", "runtime/include", "editor/model/include",
    "editor/app/include", "app",
]
SUFFIXES = {".cpp", ".hpp", ".h", ".comp", ".frag", ".vert", ".glsl", ".in"}
PASS_SHARED = {"common", "interface"}
# Registration and reference generation name every pass type on purpose.
PASS_ROOT_FILES = {"passes/register_builtin_passes.cpp.in", "passes/generate_reference.cpp",
                   "passes/register_builtin_passes.hpp"}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
RAW_PARAM = re.compile(r'\bparams\s*(?:\.\s*(?:find|at|value|contains|count)\s*\(\s*|\[\s*)"')
VULKAN_HEADER = re.compile(r"^(vulkan/|volk\.h|vk_mem_alloc)")


def closure(module):
    seen, todo = set(), [module]
    while todo:
        for dep in LINKS.get(todo.pop(), ()):
            if dep not in seen:
                seen.add(dep)
                todo.append(dep)
    return seen | {module}


def module_of(path):
    for prefix, module in MODULES:
        if path.startswith(prefix):
            return module
    return None


def pass_folder(path):
    """The pass folder of a file under passes/ (None for common, interface and root files)."""
    parts = path.split("/")
    if len(parts) < 3 or parts[0] != "passes" or parts[1] in PASS_SHARED:
        return None
    if path.startswith("passes/light_layering/core/"):
        return None
    return parts[1]


def resolve(root, including, name):
    for base in [Path(including).parent.as_posix(), *INCLUDE_DIRS]:
        candidate = (root / base / name).resolve()
        if candidate.is_file():
            try:
                return candidate.relative_to(root.resolve()).as_posix()
            except ValueError:
                return None
    return None


def source_files(root):
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root).as_posix()
        top = rel.split("/")[0]
        if top.startswith((".", "build", "out")) or not path.is_file():
            continue
        if path.suffix in SUFFIXES and (module_of(rel) or rel.startswith(TOOLS)):
            yield rel


def include_findings(root, rel, number, kind, name):
    module = module_of(rel)
    if module is None:  # tools may include any library
        return []
    if kind == "<":
        if module in VULKAN_FREE and VULKAN_HEADER.match(name):
            return [f"{rel}:{number}: <{name}> is a Vulkan header; {module} is Vulkan-free "
                    "(docs/architecture.md, section 1)"]
        return []
    target = resolve(root, rel, name)
    if target is None:  # a generated or system header
        return []
    findings = []
    target_module = module_of(target)
    if target_module is not None and target_module not in closure(module):
        findings.append(f'{rel}:{number}: "{name}" is in {target_module}, which {module} does '
                        f"not link (docs/architecture.md, section 1: every arrow points down)")
    source_pass, target_pass = pass_folder(rel), pass_folder(target)
    upward = rel.startswith("passes/common/") and target_pass is not None
    across = source_pass is not None and target_pass not in (None, source_pass)
    if (upward or across) and rel not in PASS_ROOT_FILES:
        findings.append(f'{rel}:{number}: "{name}" is in pass folder passes/{target_pass}/; a '
                        "pass includes only its own folder, passes/common and "
                        "passes/interface/shared")
    return findings


def check_file(root, rel):
    findings = []
    text = (root / rel).read_text(errors="replace")
    in_pass = module_of(rel) == "passes" and rel not in PASS_ROOT_FILES
    for number, line in enumerate(text.splitlines(), 1):
        match = INCLUDE.match(line)
        if match:
            findings += include_findings(root, rel, number, match.group(1), match.group(2))
        elif in_pass and RAW_PARAM.search(line):
            findings.append(f"{rel}:{number}: a parameter read by name from JSON; read it "
                            "through the pass's ParamTable (the hooks receive typed values)")
    return findings


def check(root):
    findings, count = [], 0
    for rel in source_files(root):
        count += 1
        findings += check_file(root, rel)
    return findings, count


def report(root):
    findings, count = check(root)
    for finding in findings:
        sys.stderr.write(finding + "\n")
    if findings:
        sys.stderr.write(f"lint: layers: {len(findings)} finding(s)\n")
        return False
    print(f"lint: layers: {count} files keep the layer rules")
    return True


def self_test():
    fixture = ROOT / "tests" / "data" / "lint_layers"
    expected = (fixture / "expected.txt").read_text().split("\n")
    expected = [line for line in expected if line]
    findings, _ = check(fixture)
    got = [f.split(": ", 1)[0] for f in findings]
    if sorted(got) != sorted(expected):
        sys.stderr.write("lint_layers self-test: the fixture's findings differ\n  expected: "
                         f"{sorted(expected)}\n  got: {findings}\n")
        return False
    print(f"lint_layers self-test: the fixture fails with its {len(expected)} findings")
    return report(ROOT)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=ROOT)
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    ok = self_test() if args.self_test else report(args.root)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
