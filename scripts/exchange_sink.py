#!/usr/bin/env python3
"""Object sink after the person lets go, from log.csv files (issue 13).

The release is the first moment after the fingers start closing (gripper_cmd
drops below its open value) when the person's hand has moved more than 1 cm
relative to the object, compared with that closing moment. The sink is the
largest drop of the object's true height (object_z) in the 1.0 s after it.
Also reports, for robot-to-human runs, the TCP's largest displacement between
the pull's onset (the person's hand, at rest once the robot waits for the
pull, moves by 2 mm) and the fingers opening past the object, and within the
0.5 s after that.

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
    t = col(rows, "time")
    cmd = col(rows, "gripper_cmd")
    hand = list(zip(col(rows, "hand_x"), col(rows, "hand_y"), col(rows, "hand_z")))
    obj = list(zip(col(rows, "object_x"), col(rows, "object_y"), col(rows, "object_z")))
    open_w = max(cmd)
    close = next((i for i in range(len(t)) if cmd[i] < 0.5 * open_w and i > 0), None)
    if close is None:
        return None
    rel0 = [h - o for h, o in zip(hand[close], obj[close])]
    for i in range(close, len(t)):
        if cmd[i] >= 0.5 * open_w:  # opened again (missed, retry): look for the next closing
            return None
        rel = [h - o for h, o in zip(hand[i], obj[i])]
        if dist(rel, rel0) > moved:
            z0 = obj[i][2]
            zmin = min(obj[k][2] for k in range(i, len(t)) if t[k] <= t[i] + window)
            return {"release_time": t[i], "sink": z0 - zmin}
    return None


def r2h_pull(rows, moved=0.01):
    t = col(rows, "time")
    width = col(rows, "finger_width")
    cmd = col(rows, "gripper_cmd")
    hand = list(zip(col(rows, "hand_x"), col(rows, "hand_y"), col(rows, "hand_z")))
    tcp = list(zip(col(rows, "tcp_x"), col(rows, "tcp_y"), col(rows, "tcp_z")))
    states = [r["state"] for r in rows]
    start = next((i for i, s in enumerate(states) if "DetectPull" in s or "Release" in s), None)
    if start is None:
        return None
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
        print(f"h2r releases: {len(sinks)}  sink median {1000 * statistics.median(sinks):.1f} mm  worst {1000 * max(sinks):.1f} mm")
    if pulls:
        print(f"r2h pulls: {len(pulls)}  tcp move median {1000 * statistics.median(pulls):.1f} mm  worst {1000 * max(pulls):.1f} mm")


if __name__ == "__main__":
    main(sys.argv[1:])
