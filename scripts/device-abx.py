#!/usr/bin/env python3
"""Interleaved multi-program GPU A/B: for each scenario group, every round runs every side's
`antumbra bench` in turn, so drift hits all sides alike. Results are written to $OUT after each
group, so a run cut short still returns what it measured.

  abx.py --pair BASE:HEAD [--pair ...] --group '[SIDE+SIDE@]pat1,pat2' [--group ...] [--rounds 2]
         [--budget SECONDS] -- BENCH_ARGS...

A group prefixed with 'SIDE+SIDE@' runs only those sides (a pair whose sides did not both run
a group simply has no rows for it), so one call can hold groups that matter to one pair only.

  --as NEW=SIDE        NEW runs SIDE's program (for the same program under another --env)
  --env SIDE:VAR=VALUE  VAR=VALUE in SIDE's environment (repeatable)
  --extra SIDE:ARG     ARG appended to SIDE's bench arguments (repeatable), e.g. --steps for
                       the sides whose program has it (an older base may not)

The last lines printed are each pair's frame and top-level pass ratios, so that a call whose
files do not all come back still shows the result.
"""
import argparse, csv, os, shutil, statistics, subprocess, sys, time

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser()
ap.add_argument("--pair", action="append", required=True)
ap.add_argument("--group", action="append", required=True)
ap.add_argument("--rounds", type=int, default=2)
ap.add_argument("--budget", type=float, default=1e9)
ap.add_argument("--tag", default="ab")
ap.add_argument("--as", dest="aliases", action="append", default=[])
ap.add_argument("--env", dest="envs", action="append", default=[])
ap.add_argument("--extra", dest="extras", action="append", default=[])
args, bench = ap.parse_known_args()
if bench and bench[0] == "--":
    bench = bench[1:]
pairs = [p.split(":") for p in args.pair]
sides = []
for p in pairs:
    for s in p:
        if s not in sides:
            sides.append(s)
out = os.environ.get("OUT", "/tmp")
env = dict(os.environ)
env["LD_LIBRARY_PATH"] = os.path.join(here, "lib") + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
icd = "/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json"
if not env.get("VK_DRIVER_FILES") and os.path.exists(icd):
    env["VK_DRIVER_FILES"] = icd
program = dict(a.split("=", 1) for a in args.aliases)  # side -> the side whose program it runs
side_env = {}
for e in args.envs:
    side, assignment = e.split(":", 1)
    var, value = assignment.split("=", 1)
    side_env.setdefault(side, {})[var] = value
side_args = {}
for e in args.extras:
    side, arg = e.split(":", 1)
    side_args.setdefault(side, []).append(arg)
rows = {s: [] for s in sides}  # side -> list of (round, scenario, pass, type, median)
start = time.time()
log = open(os.path.join(out, f"{args.tag}-log.txt"), "w")


def say(msg):
    line = f"[{time.time() - start:6.0f}s] {msg}"
    print(line, flush=True)
    log.write(line + "\n")
    log.flush()


def rev(side):
    try:
        name = open(os.path.join(here, program.get(side, side), "REV")).read().strip()
    except OSError:
        name = side
    extra = " ".join(f"{k}={v}" for k, v in side_env.get(side, {}).items())
    return f"{name} ({side}{', ' + extra if extra else ''})" if side in program or extra else name


def load_means(side):
    per = {}
    for rnd, sc, ps, ty, med in rows[side]:
        per.setdefault((sc, ps, ty), {})[rnd] = med
    return {k: statistics.mean(v.values()) for k, v in per.items() if len(v) == args.rounds}


def write_report(final):
    with open(os.path.join(out, f"{args.tag}.md"), "w") as md:
        for b, h in pairs:
            base, head = load_means(b), load_means(h)
            md.write(f"# GPU A/B: base {rev(b)}, head {rev(h)} (means of {args.rounds} interleaved runs, ms)\n\n")
            md.write("| scenario | pass | type | base | head | head/base |\n| --- | --- | --- | --- | --- | --- |\n")
            worse = []
            for key in sorted(set(base) & set(head)):
                bv, hv = base[key], head[key]
                ratio = hv / bv if bv > 0 else float("inf")
                flag = " **slower**" if ratio >= 1.05 and hv - bv >= 0.02 else ""
                if flag:
                    worse.append((key, bv, hv, ratio))
                md.write(f"| {key[0]} | {key[1]} | {key[2]} | {bv:.3f} | {hv:.3f} | {ratio:.3f}{flag} |\n")
            md.write("\n")
            if worse:
                md.write(f"{len(worse)} row(s) >= 5 % and >= 0.02 ms slower in head:\n")
                for (s, p, t), bv, hv, r in worse:
                    md.write(f"- {s} {p}: {bv:.3f} -> {hv:.3f} ms ({r:.3f}x)\n")
            else:
                md.write("no row >= 5 % (and >= 0.02 ms) slower in head\n")
            md.write("\n" if final else "\n(partial)\n\n")
    for s in sides:
        with open(os.path.join(out, f"{args.tag}-{s}.csv"), "w") as f:
            w = csv.writer(f)
            w.writerow(["round", "scenario", "pass", "type", "median_ms"])
            w.writerows(rows[s])


for gi, group in enumerate(args.group):
    if time.time() - start > args.budget:
        say(f"budget spent: groups {gi}.. not run")
        break
    group_sides = sides
    if "@" in group:
        named, group = group.split("@", 1)
        group_sides = [s for s in named.split("+") if s]
        unknown = [s for s in group_sides if s not in sides]
        if unknown:
            sys.exit(f"group names sides that no --pair names: {unknown}")
    pats = [p for p in group.split(",") if p]
    for rnd in range(1, args.rounds + 1):
        for side in group_sides:
            dst = f"/tmp/abx-run/{side}-{rnd}-{gi}"
            shutil.rmtree(dst, ignore_errors=True)
            own = program.get(side, side)
            cmd = [os.path.join(here, own, "bin", "antumbra"), "bench", *bench, *side_args.get(side, [])]
            for p in pats:
                cmd += ["--scenario", p]
            cmd += ["--out", dst]
            t0 = time.time()
            r = subprocess.run(cmd, cwd=os.path.join(here, own), env={**env, **side_env.get(side, {})},
                               capture_output=True, text=True)
            if r.returncode != 0:
                say(f"{side} round {rnd} group {group}: rc {r.returncode}\n{(r.stdout + r.stderr)[-1500:]}")
            try:
                for row in csv.DictReader(open(os.path.join(dst, "bench.csv"))):
                    if row.get("status", "ok") == "ok" and row.get("median_ms"):
                        rows[side].append((rnd, row["scenario"], row["pass"], row.get("pass_type", ""), float(row["median_ms"])))
            except OSError as e:
                say(f"{side}: no bench.csv ({e})")
            say(f"group {gi} '{group}' round {rnd} {side}: {time.time() - t0:.0f}s")
    write_report(False)
write_report(True)
say("done")
print(open(os.path.join(out, f"{args.tag}.md")).read())
print("summary (head/base; frame and passes, no steps):")
for b, h in pairs:
    base, head = load_means(b), load_means(h)
    for key in sorted(set(base) & set(head)):
        if key[2].startswith("step:") or base[key] <= 0:
            continue
        print(f"  {h}/{b} {key[0]} {key[1]}: {base[key]:.3f} -> {head[key]:.3f} ({head[key] / base[key]:.3f})")
