#!/usr/bin/python3
"""ctest cases of the benchmark commands (docs/benchmark.md).

  benchmark_case.py generate --exe H --out DIR
      `generate --count 1000 --seed 1` twice: 1000 files, byte-identical, all
      accepted by `handover check`; a bad --mode is refused
  benchmark_case.py shards --exe H --out DIR
      a small generated benchmark run whole, and as two shards run by GNU
      parallel then merged: the same report.md and summary.json, and the same
      results.csv but for wall-clock columns; `report` rewrites the same
      report.md; merging an incomplete set of shards is refused

Exit 0 when every check holds, 1 otherwise (reasons on stderr).
"""
import argparse
import csv
import filecmp
import glob
import os
import shutil
import subprocess
import sys

TIMING_COLUMNS = {"control_step_us_median", "control_step_us_p99", "control_step_us_max", "realtime_factor"}
failures = []


def check(cond, msg):
    if not cond:
        failures.append(msg)
    return cond


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    return p.returncode, p.stdout + p.stderr


def generate(args):
    a, b = os.path.join(args.out, "a"), os.path.join(args.out, "b")
    for d in (a, b):
        shutil.rmtree(d, ignore_errors=True)
        code, out = run([args.exe, "generate", "--count", "1000", "--seed", "1", "--out", d])
        check(code == 0, f"generate into {d} exited {code}: {out}")
    fa = sorted(os.listdir(a))
    check(len(fa) == 1000, f"{len(fa)} files, expected 1000")
    check(fa == sorted(os.listdir(b)), "the same seed gave other file names")
    same, diff, errs = filecmp.cmpfiles(a, b, fa, shallow=False)
    check(not diff and not errs, f"the same seed gave other contents: {(diff + errs)[:3]}")
    code, out = run([args.exe, "check"] + [os.path.join(a, f) for f in fa])
    check(code == 0, f"check refused generated files: {out[-2000:]}")
    check(out.count(": ok (") == 1000, "check did not report 1000 files ok")
    code, out = run([args.exe, "generate", "--count", "3", "--mode", "sideways", "--out", os.path.join(args.out, "c")])
    check(code == 2 and "sideways" in out, f"a bad --mode: exit {code}, {out}")


def rows(path):
    with open(path, newline="") as f:
        return [{k: v for k, v in r.items() if k not in TIMING_COLUMNS} for r in csv.DictReader(f)]


def shards(args):
    gen = os.path.join(args.out, "scenarios")
    shutil.rmtree(args.out, ignore_errors=True)
    code, out = run([args.exe, "generate", "--count", "4", "--seed", "3", "--out", gen])
    if not check(code == 0, f"generate exited {code}: {out}"):
        return
    files = sorted(glob.glob(os.path.join(gen, "*.yaml")))
    whole = os.path.join(args.out, "whole")
    code, out = run([args.exe, "batch"] + files + ["--jobs", "2", "--quiet", "--out", whole])
    check(code in (0, 1), f"the whole batch exited {code}: {out}")
    # the shards, as a scheduler would start them (GNU parallel, Debian's `parallel`)
    shard_dir = os.path.join(args.out, "shard{}")
    code, out = run(["parallel", "--will-cite", "--jobs", "2", args.exe, "batch"] + files +
                    ["--jobs", "1", "--quiet", "--shard", "{}/2", "--out", shard_dir, ":::", "1", "2"])
    check(code in (0, 1, 2), f"parallel exited {code}: {out}")  # parallel's exit = failed jobs (1 = expectations)
    s1, s2 = os.path.join(args.out, "shard1"), os.path.join(args.out, "shard2")
    n1, n2 = len(rows(os.path.join(s1, "results.csv"))), len(rows(os.path.join(s2, "results.csv")))
    check(n1 == 2 and n2 == 2, f"shards hold {n1} and {n2} runs, expected 2 and 2")
    merged = os.path.join(args.out, "merged")
    code, out = run([args.exe, "merge", s1, s2, "--out", merged])
    check(code == 0, f"merge exited {code}: {out}")
    for name in ("report.md", "summary.json"):
        check(filecmp.cmp(os.path.join(whole, name), os.path.join(merged, name), shallow=False),
              f"merged {name} differs from the unsharded one")
    check(rows(os.path.join(whole, "results.csv")) == rows(os.path.join(merged, "results.csv")),
          "merged results.csv differs from the unsharded one (timing columns aside)")
    # `compare` of a batch with its own merged shards: no category moves
    code, out = run([args.exe, "compare", whole, merged, "--out", os.path.join(args.out, "compare.md")])
    check(code == 0 and "| all |" in out and "**worse** |" not in out and "+0.0" in out,
          f"compare whole vs merged: exit {code}, {out[:600]}")
    # `report` computes the same report from results.csv
    before = open(os.path.join(whole, "report.md")).read()
    os.remove(os.path.join(whole, "report.md"))
    code, out = run([args.exe, "report", whole])
    check(code == 0 and open(os.path.join(whole, "report.md")).read() == before, f"report: exit {code}, {out}")
    # an incomplete set of shards is refused, naming what is missing
    code, out = run([args.exe, "merge", s1, "--out", os.path.join(args.out, "half")])
    check(code == 2 and "2/2" in out and "missing" in out, f"merging one shard of two: exit {code}, {out}")
    code, out = run([args.exe, "merge", s1, s1, "--out", os.path.join(args.out, "twice")])
    check(code == 2 and "twice" in out, f"merging a shard twice: exit {code}, {out}")
    code, out = run([args.exe, "batch", files[0], "--shard", "3/2", "--out", os.path.join(args.out, "bad")])
    check(code == 2 and "3/2" in out, f"--shard 3/2: exit {code}, {out}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case", choices=["generate", "shards"])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    {"generate": generate, "shards": shards}[args.case](args)
    for f in failures:
        print("FAIL: " + f, file=sys.stderr)
    if failures:
        sys.exit(1)
    print("ok")


if __name__ == "__main__":
    main()
