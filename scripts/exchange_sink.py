#!/usr/bin/env python3
"""Object sink after the person lets go, from log.csv files (issue 13).

The release is the first moment after the fingers start closing (gripper_cmd
drops below its open value), on a grasp the state machine confirms, when the
person's hand has moved more than 1 cm relative to the object, compared with
that closing moment. The sink is the largest drop of the object's true height
(object_z) in the 1.0 s after it.
Also reports, for robot-to-human runs, the TCP's largest displacement between
the pull's onset (the person's hand, at rest once the robot waits for the
pull, moves by 2 mm) and the fingers opening past the object, and within the
0.5 s after that.

The sink counts every drop, the Retract's own motion included: after a take
the Retract lifts the object off the person's hand before its carry lowers
it (config/fsm.yaml `lift_off`), so a sink beyond 10 mm is the arm giving
way under the weight, the object slipping, or a carry started too early.

usage: exchange_sink.py RUN_DIR_OR_LOG...   (a batch's runs/ folder works too)
"""
import csv
import glob
import math
import os
import statistics
import sys


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def col(rows, name):
    return [float(r[name]) for r in rows]


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def h2r_sink(rows, window=1.0, moved=0.01):
    """The sink after the first grasp the robot made (the state machine went on
    to WaitForRelease): fingers that closed on nothing, or on an object the
    person then took away, are no release."""
    t = col(rows, "time")
    cmd = col(rows, "gripper_cmd")
    hand = list(zip(col(rows, "hand_x"), col(rows, "hand_y"), col(rows, "hand_z")))
    obj = list(zip(col(rows, "object_x"), col(rows, "object_y"), col(rows, "object_z")))
    states = [r["state"] for r in rows]
    open_w = max(cmd)
    closings = [i for i in range(1, len(t)) if cmd[i] < 0.5 * open_w <= cmd[i - 1]]
    for close in closings:
        rel0 = [h - o for h, o in zip(hand[close], obj[close])]
        grasped = False
        for i in range(close, len(t)):
            if cmd[i] >= 0.5 * open_w:  # opened again (missed, retry): the next closing
                break
            grasped = grasped or states[i].endswith("/WaitForRelease")
            rel = [h - o for h, o in zip(hand[i], obj[i])]
            if dist(rel, rel0) > moved:
                if not grasped:
                    break
                z0 = obj[i][2]
                zmin = min(obj[k][2] for k in range(i, len(t)) if t[k] <= t[i] + window)
                return {"release_time": t[i], "sink": z0 - zmin}
    return None


def r2h_pull(rows):
    t = col(rows, "time")
    width = col(rows, "finger_width")
    cmd = col(rows, "gripper_cmd")
    hand = list(zip(col(rows, "hand_x"), col(rows, "hand_y"), col(rows, "hand_z")))
    tcp = list(zip(col(rows, "tcp_x"), col(rows, "tcp_y"), col(rows, "tcp_z")))
    states = [r["state"] for r in rows]
    # the pull that was answered: the DetectPull just before the first Release
    # (one that timed out, the receiver never pulling, released nothing)
    release = next((i for i, s in enumerate(states) if s.endswith("/Release")), None)
    if release is None:
        return None
    start = release
    while start > 0 and states[start - 1].endswith("/DetectPull"):
        start -= 1
    # the pull's onset: the person's hand (at rest while the robot waits for the pull) moves 2 mm
    pull = next((i for i in range(start, len(t)) if dist(hand[i], hand[start]) > 0.002), None)
    if pull is None:
        return None
    # the release: the fingers open past the object
    opened = next((i for i in range(pull, len(t)) if width[i] > width[start] + 0.005), len(t) - 1)
    d = max(dist(tcp[k], tcp[pull]) for k in range(pull, opened + 1))
    # and how far the arm keeps going in the 0.5 s after letting go (yanked, or pushing back)
    after = max(dist(tcp[k], tcp[pull]) for k in range(pull, len(t)) if t[k] <= t[opened] + 0.5)
    return {"pull_time": t[pull], "tcp_move": d, "tcp_after": after}


def main(args):
    logs = []
    for a in args:
        if os.path.isdir(a):
            logs += sorted(glob.glob(os.path.join(a, "**", "log.csv"), recursive=True))
        else:
            logs.append(a)
    sinks, pulls = [], []
    for p in logs:
        rows = load(p)
        if not rows:
            continue
        name = os.path.basename(os.path.dirname(p))
        states = {r["state"] for r in rows}
        if any("RobotToHuman" in s for s in states):
            r = r2h_pull(rows)
            if r:
                pulls.append(r["tcp_move"])
                print(f"{name:55s} pull  tcp_move {1000 * r['tcp_move']:7.1f} mm at {r['pull_time']:.2f} s"
                      f" (within 0.5 s after letting go: {1000 * r['tcp_after']:.1f} mm)")
        else:
            r = h2r_sink(rows)
            if r:
                sinks.append(r["sink"])
                print(f"{name:55s} sink {1000 * r['sink']:7.1f} mm at {r['release_time']:.2f} s")
    if sinks:
        over = sum(1 for s in sinks if s > 0.010)
        print(f"h2r releases: {len(sinks)}  sink median {1000 * statistics.median(sinks):.1f} mm"
              f"  worst {1000 * max(sinks):.1f} mm  over 10 mm: {over}")
    if pulls:
        over = sum(1 for p in pulls if p > 0.020)
        print(f"r2h pulls: {len(pulls)}  tcp move median {1000 * statistics.median(pulls):.1f} mm"
              f"  worst {1000 * max(pulls):.1f} mm  over 20 mm: {over}")


if __name__ == "__main__":
    main(sys.argv[1:])
