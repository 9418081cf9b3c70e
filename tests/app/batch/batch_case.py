#!/usr/bin/python3
"""ctest cases of `handover batch` (design notes 3-4, docs/outputs.md).

  batch_case.py run     --exe H --out DIR -- ARGS...   run a batch, record its exit code and output
  batch_case.py format  --out DIR --scenarios F...    results.csv / summary.json of that batch
  batch_case.py expect  --out DIR                     the batch exited 0: every run met its `expect:`
  batch_case.py vary    --exe H --out DIR --scenario F --vary N
                                                      two `--vary N` batches: N rows, distinct seeds,
                                                      identical rows but for timing columns

The token @SHIPPED@ stands for every scenes/scenarios/*.yaml (sorted, read
when the test runs; --source-dir gives the repository). Exit 0 when every
check holds, 1 otherwise (reasons on stderr). Python standard library only.
"""
import argparse
import csv
import glob
import json
import math
import os
import shutil
import subprocess
import sys

RESULT_COLUMNS = [
    "scenario", "variant", "seed", "mode", "outcome", "success", "handovers", "aborts", "retries",
    "time_to_grasp", "hand_still_to_grasp", "total_time", "min_human_distance", "human_contacts",
    "object_dropped", "limit_position", "limit_velocity", "limit_torque", "qp_failures", "grasp_error_pos",
    "grasp_error_rot_deg", "control_step_us_median", "control_step_us_p99", "control_step_us_max",
    "realtime_factor", "error",
    "index", "direction", "grasp", "shape", "behaviour", "placement", "hand", "height", "category",
    "expected_outcome", "met", "drop_time", "drop_reason", "qp_relaxed", "limit_guard",
]
TIMING_COLUMNS = {"control_step_us_median", "control_step_us_p99", "control_step_us_max", "realtime_factor"}
OUTCOMES = ["success", "aborted", "hand_contact", "object_drop", "timeout", "no_perception", "unsafe", "error"]

failures = []


def check(cond, msg):
    if not cond:
        failures.append(msg)
    return cond


def finish():
    for f in failures:
        print("FAIL: " + f, file=sys.stderr)
    if failures:
        sys.exit(1)
    print("ok")
    sys.exit(0)


def expand(args, source_dir):
    shipped = sorted(glob.glob(os.path.join(source_dir, "scenes", "scenarios", "*.yaml")))
    out = []
    for a in args:
        out.extend(shipped if a == "@SHIPPED@" else [a])
    return out


def run_batch(exe, args, out_dir, timeout):
    if os.path.isdir(out_dir):
        shutil.rmtree(out_dir)
    cmd = [exe, "batch"] + args + ["--out", out_dir]
    print("running: " + " ".join(cmd), flush=True)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    print(r.stdout + r.stderr, flush=True)
    return r


def read_results(out_dir):
    with open(os.path.join(out_dir, "results.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def as_float(s):
    return float(s) if s != "" else None


def cmd_run(a):
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    r = run_batch(a.exe, expand(a.args, a.source_dir), a.out, a.timeout)
    # recorded next to (not inside) the batch's folder, for the dependent cases
    with open(a.out + ".exit", "w") as f:
        f.write("%d\n" % r.returncode)
    with open(a.out + ".output", "w") as f:
        f.write(r.stdout + r.stderr)
    # this case only says the batch ran; `expect` judges the exit code
    check(r.returncode in (0, 1), "exit code %d (0 or 1 means the batch ran)" % r.returncode)
    for f in ("results.csv", "summary.json", "report.md"):
        check(os.path.isfile(os.path.join(a.out, f)), "no %s written" % f)
    finish()


def cmd_format(a):
    files = expand(a.scenarios, a.source_dir)
    header, rows = read_results(a.out)
    check(header == RESULT_COLUMNS, "results.csv header %s, documented %s" % (header, RESULT_COLUMNS))
    check(len(rows) == len(files), "%d rows for %d scenarios" % (len(rows), len(files)))
    col = {n: i for i, n in enumerate(header)}
    for r in rows:
        check(len(r) == len(header), "row of %d fields: %s" % (len(r), r))
    if failures:
        finish()
    check(sorted(r[col["scenario"]] for r in rows) == sorted(files), "one row a scenario file")
    for r in rows:
        name = os.path.basename(r[col["scenario"]])
        check(r[col["variant"]] == "0", "%s: variant %s, expected 0 (files as written)" % (name, r[col["variant"]]))
        check(r[col["mode"]] in ("human_to_robot", "robot_to_human"), "%s: mode %s" % (name, r[col["mode"]]))
        check(r[col["outcome"]] in OUTCOMES, "%s: outcome %s" % (name, r[col["outcome"]]))
        check(r[col["success"]] == ("1" if r[col["outcome"]] == "success" else "0"), "%s: success flag" % name)
        check(r[col["direction"]] == ("take" if r[col["mode"]] == "human_to_robot" else "give"),
              "%s: direction %s" % (name, r[col["direction"]]))
        check(r[col["category"]] == "/".join(r[col[k]] for k in ("direction", "grasp", "shape", "behaviour")),
              "%s: category %s" % (name, r[col["category"]]))

    with open(os.path.join(a.out, "summary.json")) as f:
        s = json.load(f)
    n = len(rows)
    for k in ("runs", "success_rate", "counts", "rates", "mean_over_successes", "hand_contact_rate", "drop_rate",
              "timeout_rate", "min_human_distance", "human_contacts", "aborts", "retries", "limit_violations",
              "qp_failures"):
        check(k in s, "summary.json has no '%s'" % k)
    if failures:
        finish()
    check(s["runs"] == n, "runs %s, rows %d" % (s["runs"], n))
    outcomes = [r[col["outcome"]] for r in rows]
    for o in OUTCOMES:
        k = outcomes.count(o)
        check(s["counts"].get(o) == k, "counts.%s = %s, results.csv has %d" % (o, s["counts"].get(o), k))
        check(o in s["rates"] and math.isclose(s["rates"][o], k / n, abs_tol=1e-9),
              "rates.%s = %s, expected %g" % (o, s["rates"].get(o), k / n))
    check(math.isclose(s["success_rate"], outcomes.count("success") / n, abs_tol=1e-9), "success_rate")
    check(math.isclose(s["hand_contact_rate"], outcomes.count("hand_contact") / n, abs_tol=1e-9), "hand_contact_rate")
    check(math.isclose(s["drop_rate"], outcomes.count("object_drop") / n, abs_tol=1e-9), "drop_rate")
    check(math.isclose(s["timeout_rate"], outcomes.count("timeout") / n, abs_tol=1e-9), "timeout_rate")
    for k in ("time_to_grasp", "total_time", "hand_still_to_grasp"):
        vals = [as_float(r[col[k]]) for r in rows if r[col["outcome"]] == "success"]
        vals = [v for v in vals if v is not None]
        got = s["mean_over_successes"].get(k, "missing")
        if vals:
            want = sum(vals) / len(vals)
            check(isinstance(got, (int, float)) and math.isclose(got, want, rel_tol=1e-6, abs_tol=1e-6),
                  "mean_over_successes.%s = %s, results.csv gives %g" % (k, got, want))
        else:
            check(got is None, "mean_over_successes.%s = %s with no values" % (k, got))
    dists = [as_float(r[col["min_human_distance"]]) for r in rows]
    dists = [d for d in dists if d is not None]
    if dists:
        check(math.isclose(s["min_human_distance"], min(dists), rel_tol=1e-6, abs_tol=1e-9),
              "min_human_distance %s, smallest row %g" % (s["min_human_distance"], min(dists)))
    for k in ("human_contacts", "aborts", "retries", "qp_failures"):
        check(s[k] == sum(int(r[col[k]]) for r in rows), "total %s" % k)
    for k in ("position", "velocity", "torque"):
        check(s["limit_violations"].get(k) == sum(int(r[col["limit_" + k]]) for r in rows), "total limit %s" % k)
    finish()


def cmd_expect(a):
    with open(a.out + ".exit") as f:
        code = int(f.read().strip())
    # name each unmet expectation (the per-run summaries of `--runs` list them)
    unmet = []
    for path in sorted(glob.glob(os.path.join(a.out, "runs", "*", "summary.json"))):
        with open(path) as f:
            s = json.load(f)
        if s.get("expectation_failures"):
            unmet.append("%s (%s): %s" % (s.get("scenario"), s.get("outcome"), "; ".join(s["expectation_failures"])))
    # whatever each file expects: no shipped scenario may touch the person,
    # drop the object, break a limit or lose the QP (issue: state machine)
    for path in sorted(glob.glob(os.path.join(a.out, "runs", "*", "summary.json"))):
        with open(path) as f:
            s = json.load(f)
        name = s.get("scenario")
        check(s.get("human_contacts") == 0, "%s: %s robot-person contacts" % (name, s.get("human_contacts")))
        check(s.get("object_dropped") is False, "%s: the object was dropped" % name)
        check(s.get("qp_failures") == 0, "%s: %s QP failures" % (name, s.get("qp_failures")))
        lim = s.get("limit_violations", {})
        check(all(lim.get(k) == 0 for k in ("position", "velocity", "torque")), "%s: limit violations %s" % (name, lim))
    for u in unmet:
        print("unmet: " + u, file=sys.stderr)
    check(code == 0, "the batch exited %d: %d scenario(s) missed their expectations" % (code, len(unmet)))
    check(not unmet, "unmet expectations in %d run(s)" % len(unmet))
    check(glob.glob(os.path.join(a.out, "runs", "*", "summary.json")), "no per-run summaries (--runs) to read")
    finish()


def cmd_vary(a):
    tables = []
    for tag in ("a", "b"):
        out = "%s_%s" % (a.out, tag)
        r = run_batch(a.exe, [a.scenario, "--vary", str(a.vary), "--jobs", "2", "--quiet"], out, a.timeout)
        check(r.returncode in (0, 1), "run %s: exit code %d" % (tag, r.returncode))
        if failures:
            finish()
        tables.append(read_results(out))
    (header, rows_a), (_, rows_b) = tables
    col = {n: i for i, n in enumerate(header)}
    check(len(rows_a) == a.vary, "%d rows, expected %d" % (len(rows_a), a.vary))
    if failures:
        finish()
    check(sorted(int(r[col["variant"]]) for r in rows_a) == list(range(1, a.vary + 1)), "variants 1..N")
    seeds = [r[col["seed"]] for r in rows_a]
    check(len(set(seeds)) == a.vary, "seeds not distinct: %s" % seeds)
    # the variants differ in what happened, not only in their seed
    kept = [i for i, n in enumerate(header) if n not in TIMING_COLUMNS and n not in ("variant", "seed")]
    outcomes_of = lambda r: tuple(r[i] for i in kept)
    check(len(set(outcomes_of(r) for r in rows_a)) > 1, "all variants gave identical results")
    # reproducible: the same rows again, timing columns aside
    key = lambda r: int(r[col["variant"]])
    for ra, rb in zip(sorted(rows_a, key=key), sorted(rows_b, key=key)):
        for i, n in enumerate(header):
            if n in TIMING_COLUMNS:
                continue
            check(ra[i] == rb[i], "variant %s column %s: %r then %r" % (ra[col["variant"]], n, ra[i], rb[i]))
    finish()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("case", choices=["run", "format", "expect", "vary"])
    p.add_argument("--exe")
    p.add_argument("--source-dir", default=".")
    p.add_argument("--out", required=True)
    p.add_argument("--scenarios", nargs="*", default=[])
    p.add_argument("--scenario")
    p.add_argument("--vary", type=int, default=3)
    p.add_argument("--timeout", type=float, default=900)
    argv = sys.argv[1:]
    rest = argv.index("--") if "--" in argv else len(argv)
    a = p.parse_args(argv[:rest])
    a.args = argv[rest + 1:]  # the batch's own arguments
    try:
        {"run": cmd_run, "format": cmd_format, "expect": cmd_expect, "vary": cmd_vary}[a.case](a)
    except (OSError, ValueError, KeyError, subprocess.TimeoutExpired) as e:
        failures.append("%s: %s" % (type(e).__name__, e))
        finish()


if __name__ == "__main__":
    main()
