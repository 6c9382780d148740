#!/usr/bin/env python3
"""Writes the synthetic results files of tests/bench/docs_tables_test.cpp: made-up
numbers (never measured) under the scenario names `antumbra bench --list` prints at scale 1
and the graph names of `antumbra quality`. Run from this folder; the output is committed."""
import json

PROVENANCE = {"commit": "0123456789ab", "device": "Fixture GPU", "driver": "Fixture driver 1.0"}


def scenario(name, index, atlas=True, status="ok"):
    passes = [("gbuffer", "gbuffer", 1.5), ("shadowMaps", "point-shadow-atlas", 10.0 + index),
              ("lighting", "tiled-lighting", 0.25), ("tonemap", "tonemap", 0.12)]
    if not atlas:
        passes = [p for p in passes if p[1] != "point-shadow-atlas"]
    out = [{"name": n, "type": t, "medianMs": ms + index / 100.0, "p10Ms": ms, "p90Ms": ms,
            "frames": 60, "cpuMedianMs": 0.01} for n, t, ms in passes]
    frame = sum(p["medianMs"] for p in out)
    if status != "ok":
        out, frame = [], 0.0
    return {"scenario": name, "table": name.split("/")[0], "lights": int(name.split("/")[3].split("l")[0])
            if name.count("/") >= 3 else 16, "movingLights": 64 if "/1024l" in name else
            int(name.split("/")[3][:-1]) if name.startswith("moving/") else 0,
            "scene": "district.json" if "/1024l" in name else "atrium.json", "status": status,
            "detail": "", "frame": {"medianMs": frame, "p10Ms": frame, "p90Ms": frame, "frames": 60},
            "passes": out}


def bench(names, **special):
    scenarios = []
    for i, name in enumerate(names):
        scenarios.append(scenario(name, i, atlas=not any(t in name for t in ("lighting-only", "sdf/")),
                                  status=special.get(name, "ok")))
    return dict(PROVENANCE, frames=60, warmup=10, scale=1.0, scenarios=scenarios)


def write(path, document):
    path = "results/" + path
    with open(path, "w") as f:
        json.dump(document, f, indent=1)
        f.write("\n")


moving = []
for lights in (16, 64, 256, 1024):
    for tech in ("hard", "pcss-11", "ssss-11"):
        for suffix in ("", "/compute", "/compute/screen", "/compute/screen/vis"):
            moving.append(f"moving/{tech}/1080p/{lights}l{suffix}")
write("moving.json", bench(moving))

techniques = [("lighting-only", []), ("hard", []), ("pcf", [5, 11, 23]), ("pcss", [5, 11, 23]),
              ("ssss-blocker", [5, 11, 23]), ("ssss", [5, 11, 23]), ("ssss-min", [5, 11, 23]),
              ("vsm", []), ("evsm2", []), ("evsm4", []), ("msm", []), ("vssm", []), ("sdf", []),
              ("penumbra-wedges", [])]
table1 = [f"table1/{t}{'-' + str(k) if k else ''}/{h}p" for h in (720, 1080)
          for t, ks in techniques for k in (ks or [0])]
write("table1.json", bench(table1))

penumbra = [f"penumbra/{t}-11/1080p/16l/r{r:.2f}m" for r in (0.05, 0.1, 0.25, 0.5, 1.0)
            for t in ("pcss", "ssss", "ssss-min")]
write("penumbra.json", bench(penumbra))

dynamic = [f"dynamic/{t}/1080p/16l{s}" for t in ("hard", "pcss-11", "ssss-11")
           for s in ("", "/nocache", "/compute")]
write("dynamic.json", bench(dynamic, **{"dynamic/ssss-11/1080p/16l/compute": "error"}))


materials = [f"materials/ssss-11/1080p/16l/{scene}{s}" for scene in ("atrium", "atrium-cutouts")
             for s in ("", "/compute", "/compute/screen", "/compute/screen/vis")]
write("materials.json", bench(materials))

# The page pool's rows and the same lights in squares; the paged rows carry the atlas's
# SHD010 note with the pool's counts (the city's with pages missing), the atrium's squares
# row none.
paged = [f"pages/ssss-11/1080p/{rows}/compute/screen/vis/pool{pool}"
         for rows, pool in (("16l-16m", 32), ("1024l-64m", 512), ("1024l-1024m", 512),
                            ("4096l-1024m", 512))]
squares = ["moving/ssss-11/1080p/16l/compute/screen/vis"] + [
    f"many/ssss-11/1080p/{rows}/compute/screen/vis"
    for rows in ("1024l-64m", "1024l-1024m", "4096l-1024m")]
pages = bench(paged + squares)
for i, s in enumerate(pages["scenarios"]):
    name = s["scenario"]
    lights = 16 if "/16l" in name else int(name.split("/")[3].split("l")[0])
    s["lights"], s["movingLights"] = lights, 16 if lights == 16 else int(name.split("-")[-1].split("m")[0])
    s["scene"] = {16: "atrium.json", 1024: "district.json", 4096: "city.json"}[lights]
    s["passes"].insert(2, {"name": "penumbra", "type": "layered-penumbra", "medianMs": 0.2 + i / 100.0,
                           "p10Ms": 0.2, "p90Ms": 0.2, "frames": 60, "cpuMedianMs": 0.01})
    if name.startswith("pages/"):
        pool = {"needed": 100 * (i + 1), "pages": 2048 if lights == 16 else 8192,
                "missing": 3 if lights == 4096 else 0, "kept": 0, "taken": 0, "evicted": 0,
                "bytes": 1 << 27}
        s["notes"] = [{"code": "SHD010", "severity": "note", "pass": "shadowMaps",
                       "message": "shadow faces", "details": {"pool": pool}}]
write("pages.json", pages)


def quality(width, height, scale):
    graphs = []
    for i, graph in enumerate(("hard.json", "pcss.json", "layered-ssss.json")):
        rmse = [0.007, 0.006, 0.005][i] * scale
        regions = {"all": {"pixels": width * height, "rmse": rmse, "psnr": 45.0, "ssim": 0.998},
                   "penumbra": {"pixels": 1000, "rmse": rmse * 6, "psnr": 30.0, "ssim": 0.95},
                   "overlap": {"pixels": 200, "rmse": rmse * 9, "psnr": 25.0, "ssim": 0.9},
                   "silhouette": {"pixels": 500, "rmse": rmse / 2, "psnr": 50.0, "ssim": 0.99}}
        graphs.append({"graph": "data/graphs/" + graph, "renderMs": 10.0, "regions": regions})
    return dict(PROVENANCE, reference="data/graphs/reference.json", referenceMs=100.0,
                scene="data/scenes/atrium.json", width=width, height=height, signal="fixture",
                graphs=graphs, diagnostics=[])


write("quality-640x360.json", quality(640, 360, 1.0))
# The larger size ranks layered first: the ranking column must follow the numbers.
q = quality(1280, 720, 1.0)
q["graphs"][2]["regions"]["all"]["rmse"] = 0.0045
q["graphs"][0]["regions"]["all"]["rmse"] = 0.0065
write("quality-1280x720.json", q)
