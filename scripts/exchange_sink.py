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

The sink counts every drop, including the Retract's own descent toward a
stow pose lower than the grasp. "beyond the retract" removes that: the
Retract's pose task is a critically damped PD toward the stow pose (stiffness
of config/controller.yaml pose_task.translation, stow of config/fsm.yaml),
so its planned height from the Retract's start is
z_s + (e0 + (v0 + w e0) t) exp(-w t), w = sqrt(K), e0, v0 the TCP's height
error and vertical speed then; the object's drop minus the planned drop is
what the arm did not mean to do (sagging, slipping, or not reaching the plan).

usage: exchange_sink.py RUN_DIR_OR_LOG...   (a batch's runs/ folder works too)
"""
import csv
import glob
import math
import os
import statistics
import sys

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def retract_plan():
    """(stow TCP height m, pose-task stiffness 1/s^2) from the shipped configs."""
    with open(os.path.join(ROOT, "config", "fsm.yaml")) as f:
        stow_z = yaml.safe_load(f)["params"]["poses"]["stow"]["pos"][2]
    with open(os.path.join(ROOT, "config", "controller.yaml")) as f:
        k = yaml.safe_load(f)["pose_task"]["translation"]["stiffness"]
    return stow_z, k


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
    tcp_z = col(rows, "tcp_z")
    states = [r["state"] for r in rows]
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
            window_rows = [k for k in range(i, len(t)) if t[k] <= t[i] + window]
            zmin = min(obj[k][2] for k in window_rows)
            # the Retract's planned height (see the module doc)
            stow_z, stiffness = retract_plan()
            w = math.sqrt(stiffness)
            r0 = next((k for k in range(close, len(t)) if states[k].endswith("/Retract")), None)
            def planned(k):
                if r0 is None or k < r0:
                    return tcp_z[k if r0 is None else r0] if r0 is not None else tcp_z[i]
                e0 = tcp_z[r0] - stow_z
                v0 = (tcp_z[r0] - tcp_z[r0 - 1]) / (t[r0] - t[r0 - 1]) if r0 > 0 else 0.0
                tau = t[k] - t[r0]
                return stow_z + (e0 + (v0 + w * e0) * tau) * math.exp(-w * tau)
            beyond = max((z0 - obj[k][2]) - (planned(i) - planned(k)) for k in window_rows)
            return {"release_time": t[i], "sink": z0 - zmin, "beyond": max(0.0, beyond)}
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
    sinks, beyond, pulls = [], [], []
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
                beyond.append(r["beyond"])
                print(f"{name:55s} sink {1000 * r['sink']:7.1f} mm at {r['release_time']:.2f} s"
                      f" (beyond the retract's planned descent: {1000 * r['beyond']:.1f} mm)")
    if sinks:
        print(f"h2r releases: {len(sinks)}  sink median {1000 * statistics.median(sinks):.1f} mm  worst {1000 * max(sinks):.1f} mm"
              f"; beyond the retract's plan: median {1000 * statistics.median(beyond):.1f} mm  worst {1000 * max(beyond):.1f} mm")
    if pulls:
        print(f"r2h pulls: {len(pulls)}  tcp move median {1000 * statistics.median(pulls):.1f} mm  worst {1000 * max(pulls):.1f} mm")


if __name__ == "__main__":
    main(sys.argv[1:])
