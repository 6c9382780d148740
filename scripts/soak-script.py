#!/usr/bin/env python3
"""Writes an edit script that soaks the headless editor (docs/robustness.md, "Soak").

The script marks the device memory after the first reload, then makes EDITS edits (light
moves and changes, added lights, undo and redo, parameter edits, camera moves, clicks,
saves) and RELOADS reloads (alternately of a shader the graph uses, changed on disk so that
it really recompiles, and of the graph file, changed on disk), puts every light, the graph
file and the shader back as they were, and expects the device memory in use within
--memory-percent of the mark. Run it with

    antumbra edit --headless --scene SCENE --graph GRAPH --script OUT

where SHADER (a path relative to the script's folder, or absolute) is one of the graph's
shaders in a copy of the tree (ANTUMBRA_ROOT): the soak rewrites it.
"""

import argparse
import json
import random
import sys
from pathlib import Path


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", required=True, help="the scene file the editor opens")
    parser.add_argument("--graph", required=True, help="the graph file the editor opens")
    parser.add_argument("--shader", required=True,
                        help="a shader the graph uses (rewritten by the soak)")
    parser.add_argument("--edits", type=int, default=10000)
    parser.add_argument("--reloads", type=int, default=500)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--memory-percent", type=float, default=1.0)
    parser.add_argument("--out", required=True, help="the script to write")
    args = parser.parse_args(argv)
    if args.edits < 0 or args.reloads < 1:
        parser.error("--edits must be 0 or more and --reloads 1 or more")
    return args


def point_lights(scene_path):
    """The scene's point and spot lights with the fields the soak changes, as they are."""
    scene = json.loads(Path(scene_path).read_text())
    lights = []
    for light in scene.get("lights", []):
        if light.get("type", "point") not in ("point", "spot") or "name" not in light:
            continue
        lights.append({
            "name": light["name"],
            "position": light.get("position", [0, 0, 0]),
            "intensity": light.get("intensity", 1.0),
            "size": light.get("size", 0.1),
        })
    if not lights:
        sys.exit(f"soak-script: {scene_path} has no named point or spot light to edit")
    return lights


class Soak:
    """The steps, with the count of edits made so far."""

    def __init__(self, rng, lights):
        self.rng = rng
        self.lights = lights
        self.steps = []
        self.edits = 0

    def add(self, step, edit=True):
        self.steps.append(step)
        self.edits += 1 if edit else 0

    def random_edit(self):
        light = self.rng.choice(self.lights)
        choice = self.rng.randrange(8)
        if choice == 0:
            x, y, z = light["position"]
            jitter = [round(self.rng.uniform(-0.5, 0.5), 3) for _ in range(3)]
            self.add({"do": "set-light", "light": light["name"],
                      "position": [x + jitter[0], max(0.2, y + jitter[1]), z + jitter[2]]})
        elif choice == 1:
            self.add({"do": "set-light", "light": light["name"],
                      "intensity": round(self.rng.uniform(1.0, 30.0), 2),
                      "size": round(self.rng.uniform(0.05, 0.5), 3)})
        elif choice == 2:  # a light comes and goes again
            self.add({"do": "add-light", "position": [round(self.rng.uniform(-2, 8), 2), 2, 0]})
            self.add({"do": "undo"})
            self.add({"do": "redo"})
            self.add({"do": "undo"})
        elif choice == 3:
            self.add({"do": "set-light", "light": light["name"],
                      "color": [round(self.rng.uniform(0.2, 1.0), 2) for _ in range(3)]})
            self.add({"do": "undo"})
        elif choice == 4:  # a graph edit and its undo: two graph reloads
            self.add({"do": "set-param", "pass": "tonemap", "name": "exposure",
                      "value": round(self.rng.uniform(0.5, 2.0), 3)})
            self.add({"do": "undo"})
        elif choice == 5:  # a look around, then home (a click must find lights in front)
            self.add({"do": "camera", "orbit": [self.rng.randint(-40, 40),
                                                self.rng.randint(-20, 20)]})
            self.add({"do": "camera", "reset": True})
        elif choice == 6:
            self.add({"do": "click", "at": light["name"]})
        else:
            self.add({"do": "save"})

    def reload(self, index, files):
        """Odd reloads change the shader on disk, even ones the graph file."""
        if index % 2 == 1:
            text = files["shader_text"] + f"\n// soak: reload {index}\n"
            self.add({"do": "write-file", "path": files["shader"], "text": text}, edit=False)
        else:
            text = files["graph_text"] if index % 4 == 0 else files["graph_variant"]
            self.add({"do": "write-file", "path": "$graph", "text": text}, edit=False)
        self.add({"do": "reload"}, edit=False)
        self.add({"expect": "reload-ok"}, edit=False)

    def restore(self, files):
        """Every light, the camera, the graph file and the shader as they were."""
        for light in self.lights:
            self.add({"do": "set-light", "light": light["name"], "position": light["position"],
                      "intensity": light["intensity"], "size": light["size"]}, edit=False)
        self.add({"do": "camera", "reset": True}, edit=False)
        self.add({"do": "write-file", "path": files["shader"], "text": files["shader_text"]},
                 edit=False)
        self.add({"do": "write-file", "path": "$graph", "text": files["graph_text"]}, edit=False)
        self.add({"do": "reload"}, edit=False)
        self.add({"expect": "reload-ok"}, edit=False)


def graph_variant(graph_text):
    """The graph file with another tone curve: a change the reload must take."""
    graph = json.loads(graph_text)
    for render_pass in graph.get("passes", []):
        if render_pass.get("type") == "tonemap":
            params = render_pass.setdefault("params", {})
            params["operator"] = "reinhard" if params.get("operator") != "reinhard" else "aces"
            return json.dumps(graph, indent=2) + "\n"
    sys.exit("soak-script: the graph has no tonemap pass to change")


def main(argv):
    args = parse_args(argv)
    graph_text = Path(args.graph).read_text()
    shader_path = Path(args.shader)
    files = {
        "shader": str(shader_path),
        "shader_text": shader_path.read_text(),
        "graph_text": graph_text,
        "graph_variant": graph_variant(graph_text),
    }
    soak = Soak(random.Random(args.seed), point_lights(args.scene))
    soak.add({"do": "reload"}, edit=False)
    soak.add({"expect": "reload-ok"}, edit=False)
    soak.add({"do": "mark-memory"}, edit=False)
    for index in range(1, args.reloads + 1):
        while soak.edits < args.edits * index // args.reloads:
            soak.random_edit()
        soak.reload(index, files)
    soak.restore(files)
    soak.add({"expect": "memory-within", "percent": args.memory_percent, "extraAllocations": 0},
             edit=False)
    soak.add({"do": "save"}, edit=False)
    script = {
        "description": f"scripts/soak-script.py --edits {args.edits} --reloads {args.reloads} "
                       f"--seed {args.seed}: {soak.edits} edits, {args.reloads} reloads",
        "steps": soak.steps,
    }
    Path(args.out).write_text(json.dumps(script, indent=1) + "\n")
    print(f"soak-script: {args.out}: {len(soak.steps)} steps, {soak.edits} edits, "
          f"{args.reloads} reloads")


if __name__ == "__main__":
    main(sys.argv[1:])
