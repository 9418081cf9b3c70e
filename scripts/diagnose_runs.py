#!/usr/bin/python3
"""Reads failed runs of a benchmark from their logs and says what happened.

  diagnose_runs.py RUN_DIR...                 one paragraph per run (DIR/summary.json, DIR/log.csv)
  diagnose_runs.py --batch OUT --exe H [--max N] [--work DIR]
      re-runs up to N runs of the batch OUT whose outcome missed their
      expectation (spread over outcomes and categories, with logs), then
      prints a table: run, category, outcome, the state it ended or stalled
      in, and the mechanism read from the log (docs/benchmark.md).

Mechanisms are read from log.csv columns (docs/outputs.md), not guessed:
- stalled at a joint limit: the TCP stayed > 3 cm from its target and came
  less than 1 cm closer in the last second of a state that lasted > 2 s,
  while some joint was < 0.1 rad from its limit;
- stalled: the same distance without a joint at its limit (another
  constraint or the task weights hold it);
- QP infeasible: steps with qp_status != 0, and the state they fell in;
- dropped after the grasp (a take): the object sank > 5 cm while the fingers
  were closed;
- touched the person: the onsets of `person_contact`, their state and the
  collision pair nearest its safety distance at that moment;
- never reached / retreated: the state sequence shows Retreat or WaitAgain
  before any grasp.
Python standard library only.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
from collections import Counter, OrderedDict


def load(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(run_dir, "log.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return summary, rows


def fl(r, k):
    try:
        return float(r[k])
    except (KeyError, ValueError):
        return float("nan")


def segments(rows):
    """[(state, first row index, last row index)] in order."""
    segs = []
    for i, r in enumerate(rows):
        if not segs or segs[-1][0] != r["state"]:
            segs.append([r["state"], i, i])
        else:
            segs[-1][2] = i
    return segs


def short(state):
    return state.split("/")[-1]


def tcp_error(r):
    return math.dist((fl(r, "tcp_x"), fl(r, "tcp_y"), fl(r, "tcp_z")), (fl(r, "grasp_x"), fl(r, "grasp_y"), fl(r, "grasp_z")))


def diagnose(summary, rows):
    """(where, mechanism) for one run."""
    if not rows:
        return "-", "no log rows"
    dt = fl(rows[1], "time") - fl(rows[0], "time") if len(rows) > 1 else 0.005
    segs = segments(rows)
    findings = []
    qp_bad = [r for r in rows if r.get("qp_status", "0") not in ("0", "")]
    if qp_bad:
        where = Counter(short(r["state"]) for r in qp_bad).most_common(2)
        findings.append("QP infeasible %d logged steps (%s)" % (len(qp_bad), ", ".join("%s %d" % w for w in where)))
    # stalls: the last second of each state that lasted > 2 s
    for state, a, b in segs:
        span = (b - a) * dt
        name = short(state)
        if span < 2.0 or name.startswith("Wait") or name in ("Idle", "HoldReady", "Done"):
            continue
        tail = rows[max(a, b - int(1.0 / dt)):b + 1]
        err = min(tcp_error(r) for r in tail)
        progress = tcp_error(tail[0]) - tcp_error(tail[-1])
        if err < 0.03 or progress > 0.01:  # there, or still getting there
            continue
        margins = [(min(fl(r, "qmargin%d" % j) for r in tail), j) for j in range(1, 8)]
        m, j = min(margins)
        if m < 0.1:
            findings.append("stalled in %s for %.1f s: TCP %.0f mm from its target, joint %d %.2f rad from its limit"
                            % (name, span, 1e3 * err, j, m))
        else:
            findings.append("stalled in %s for %.1f s: TCP %.0f mm from its target (joints clear, nearest %d at %.2f rad)"
                            % (name, span, 1e3 * err, j, m))
    # touches of the person: when, in which state, and the collision pair then nearest its safety distance
    onsets = [i for i, r in enumerate(rows) if fl(r, "person_contact") > 0.5 and (i == 0 or fl(rows[i - 1], "person_contact") < 0.5)]
    for i in onsets[:3]:
        r = rows[i]
        n = 1
        while i + n < len(rows) and fl(rows[i + n], "person_contact") > 0.5:
            n += 1
        findings.append("touched the person at %.2f s in %s for %.2f s (nearest pair: %s)"
                        % (fl(r, "time"), short(r["state"]), n * dt, r.get("nearest_pair") or "none"))
    # the object sinking in the gripper (a take: the fingers closed on what the person gave)
    closed = [i for i, r in enumerate(rows) if fl(r, "gripper_cmd") < 0.07 and fl(r, "finger_width") < 0.075]
    if closed and summary.get("mode") == "human_to_robot":
        z0 = fl(rows[closed[0]], "object_z")
        zmin = min(fl(rows[i], "object_z") for i in closed)
        if z0 - zmin > 0.05:
            findings.append("object sank %.0f mm while the fingers were closed" % (1e3 * (z0 - zmin)))
    names = [short(s) for s, _, _ in segs]
    if "Retreat" in names and "Grasp" not in names[: names.index("Retreat")]:
        findings.append("retreated before any grasp (%s)" % " > ".join(OrderedDict.fromkeys(names)))
    if summary.get("limit_violations"):
        lv = summary["limit_violations"]
        if any(lv.values()):
            findings.append("limit violations %s" % lv)
    last = short(segs[-1][0])
    return last, "; ".join(findings) if findings else "no mechanism found in the log (read the plots)"


def pick_failures(out_dir, max_runs):
    with open(os.path.join(out_dir, "results.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("met") == "0"]
    # round-robin over (outcome, category) so one frequent failure does not hide the others
    groups = OrderedDict()
    for r in rows:
        groups.setdefault((r["outcome"], r["category"]), []).append(r)
    picked = []
    while len(picked) < max_runs and any(groups.values()):
        for key in list(groups):
            if groups[key] and len(picked) < max_runs:
                picked.append(groups[key].pop(0))
    return picked


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="*")
    ap.add_argument("--batch")
    ap.add_argument("--exe")
    ap.add_argument("--max", type=int, default=30)
    ap.add_argument("--work", default="out/diagnose")
    a = ap.parse_args()
    if a.batch:
        if not a.exe:
            ap.error("--batch needs --exe")
        print("| run | category | outcome | ended in | what the log shows |\n|---|---|---|---|---|")
        for r in pick_failures(a.batch, a.max):
            run_dir = os.path.join(a.work, os.path.splitext(os.path.basename(r["scenario"]))[0])
            subprocess.run([a.exe, "run", r["scenario"], "--out", run_dir, "--quiet"], capture_output=True)
            summary, rows = load(run_dir)
            where, what = diagnose(summary, rows)
            print("| %s | %s | %s | %s | %s |" % (os.path.basename(r["scenario"]), r["category"], summary["outcome"],
                                                 where, what))
        return 0
    if not a.runs:
        ap.error("give run folders, or --batch")
    for d in a.runs:
        summary, rows = load(d)
        where, what = diagnose(summary, rows)
        print("%s: %s, ended in %s: %s" % (d, summary["outcome"], where, what))
    return 0


if __name__ == "__main__":
    sys.exit(main())
