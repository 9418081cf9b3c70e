#!/usr/bin/python3
"""Draws the plots of one `handover run` from DIR/log.csv into DIR/*.png.

Columns read (see docs/outputs.md); plots whose columns are missing are skipped:
  time, state,
  sensed_{x,y,z,roll,pitch,yaw}, sensed_valid   measured object pose
  obs_{x,y,z,roll,pitch,yaw}                     observed object (observation task)
  grasp_{x,y,z,roll,pitch,yaw}, tcp_{...}        tracking reference and TCP
  q1..q7, qmargin1..qmargin7                     joints, distance to the nearest limit (rad)
  d_human, d_table, d_self                       smallest distances (m)
  load_share, load_f{x,y,z}, ff_f{x,y,z},        the physical exchange: load share, wrist load and
  grip_force, object_z, tcp_z                    feed-forward (N, world), grip force (N), heights (m)
Usage: plot_run.py DIR   (exit 2 if DIR/log.csv is missing or unreadable)
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

AXES = ("x", "y", "z")
ANGLES = ("roll", "pitch", "yaw")


def read_log(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames or []
    if not rows:
        raise ValueError("no rows")
    # a truncated or padded row (a run killed mid-write, a full disk) is an
    # error, not a plot with holes
    for i, r in enumerate(rows):
        n = sum(1 for k in header if r.get(k) is not None) + len(r.get(None) or [])
        if n != len(header):
            raise ValueError("row %d has %d fields, the header %d (truncated file?)" % (i + 2, n, len(header)))
    cols = {}
    for key in rows[0].keys():
        vals = []
        for r in rows:
            v = r[key]
            try:
                vals.append(float(v))
            except (TypeError, ValueError):
                vals.append(v)
        cols[key] = vals
    return cols


def has(cols, *names):
    return all(n in cols for n in names)


def state_spans(cols):
    """(start, end, name) of each contiguous state in the log."""
    if "state" not in cols:
        return []
    t, s = cols["time"], cols["state"]
    spans, start = [], 0
    for i in range(1, len(s) + 1):
        if i == len(s) or s[i] != s[start]:
            spans.append((t[start], t[i - 1], str(s[start])))
            start = i
    return spans


def shade_states(ax, spans, label=False):
    names = sorted({n for _, _, n in spans})
    cmap = plt.get_cmap("tab20")
    colour = {n: cmap(i % 20) for i, n in enumerate(names)}
    for a, b, n in spans:
        ax.axvspan(a, b, color=colour[n], alpha=0.15, lw=0,
                   label=n.split("/")[-1] if label else None)
    return colour


def unwrap(vals):
    out, off = [], 0.0
    for i, v in enumerate(vals):
        if i and v + off - out[-1] > math.pi:
            off -= 2 * math.pi
        elif i and v + off - out[-1] < -math.pi:
            off += 2 * math.pi
        out.append(v + off)
    return out


def masked(cols, name, valid=None):
    vals = cols[name]
    if valid is None:
        return vals
    return [v if ok else float("nan") for v, ok in zip(vals, valid)]


def pose_figure(cols, solid, dashed, title, solid_label, dashed_label, out):
    """The paper's figures 5 and 6: position (left) and RPY (right)."""
    t = cols["time"]
    valid = None
    if dashed == "sensed" and "sensed_valid" in cols:
        valid = [v == 1.0 for v in cols["sensed_valid"]]
    fig, (ax_p, ax_r) = plt.subplots(1, 2, figsize=(12, 4.2))
    for i, a in enumerate(AXES):
        c = "C%d" % i
        ax_p.plot(t, cols["%s_%s" % (solid, a)], c, label="%s %s" % (solid_label, a))
        ax_p.plot(t, masked(cols, "%s_%s" % (dashed, a), valid), c + "--", label="%s %s" % (dashed_label, a))
    for i, a in enumerate(ANGLES):
        c = "C%d" % i
        ax_r.plot(t, cols["%s_%s" % (solid, a)], c, label="%s %s" % (solid_label, a))
        ax_r.plot(t, masked(cols, "%s_%s" % (dashed, a), valid), c + "--", label="%s %s" % (dashed_label, a))
    ax_p.set(xlabel="time (s)", ylabel="position (m)", title=title + ": position")
    ax_r.set(xlabel="time (s)", ylabel="angle (rad)", title=title + ": roll, pitch, yaw")
    for ax in (ax_p, ax_r):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def paths_3d(cols, out):
    """The paper's figure 7: 3D paths of the grasp frame and the TCP."""
    fig = plt.figure(figsize=(6.5, 5.5))
    ax = fig.add_subplot(111, projection="3d")
    for name, colour, label in (("grasp", "C0", "grasp frame"), ("tcp", "C1", "TCP")):
        x, y, z = (cols["%s_%s" % (name, a)] for a in AXES)
        ax.plot(x, y, z, colour, label=label)
        ax.scatter([x[0]], [y[0]], [z[0]], c=colour, marker="s", s=40)
        ax.scatter([x[-1]], [y[-1]], [z[-1]], c=colour, marker="o", s=40)
    ax.set(xlabel="x (m)", ylabel="y (m)", zlabel="z (m)",
           title="3D paths (square: start, circle: end)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def timeline(cols, spans, out):
    t = cols["time"]
    fig, ax = plt.subplots(figsize=(12, 3.6))
    colour = shade_states(ax, spans)
    names = list(colour)
    for a, b, n in spans:
        y = names.index(n)
        ax.plot([a, b], [y, y], color=colour[n], lw=8, solid_capstyle="butt")
    ax.set_yticks(range(len(names)))
    ax.set_yticklabels(names, fontsize=7)
    ax.set(xlabel="time (s)", title="state machine timeline", xlim=(t[0], t[-1]))
    ax.grid(alpha=0.3, axis="x")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def joint_margins(cols, spans, out):
    t = cols["time"]
    fig, ax = plt.subplots(figsize=(12, 4))
    shade_states(ax, spans)
    for j in range(1, 8):
        ax.plot(t, cols["qmargin%d" % j], label="joint %d" % j)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set(xlabel="time (s)", ylabel="distance to nearest limit (rad)", title="joint-limit margins")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def distances(cols, spans, out):
    t = cols["time"]
    fig, ax = plt.subplots(figsize=(12, 4))
    shade_states(ax, spans, label=True)
    for name, label in (("d_human", "robot - person"), ("d_table", "robot - table"), ("d_self", "self")):
        if name in cols:
            ax.plot(t, [min(v, 1.0) if isinstance(v, float) else float("nan") for v in cols[name]], label=label)
    ax.set(xlabel="time (s)", ylabel="smallest distance (m, clipped at 1)", title="distances")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=4)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def exchange(cols, spans, out):
    """The physical exchange: who carries the object, the wrist load, the grip."""
    t = cols["time"]
    fig, (ax_s, ax_f, ax_z) = plt.subplots(3, 1, figsize=(12, 8), sharex=True)
    shade_states(ax_s, spans, label=True)
    ax_s.plot(t, cols["load_share"], label="load share (robot)")
    ax_s.set(ylabel="share of the weight", ylim=(-0.05, 1.1), title="physical exchange")
    ax_s.legend(fontsize=7, ncol=4)
    shade_states(ax_f, spans)
    for a in AXES:
        ax_f.plot(t, cols["load_f" + a], label="load f" + a)
    if has(cols, "ff_fz"):
        ax_f.plot(t, cols["ff_fz"], "--", label="feed-forward fz")
    if has(cols, "grip_force"):
        ax_f.plot(t, cols["grip_force"], ":", label="grip force")
    ax_f.set(ylabel="N (world)")
    ax_f.legend(fontsize=7, ncol=5)
    shade_states(ax_z, spans)
    for name in ("object_z", "tcp_z"):
        if name in cols:
            ax_z.plot(t, cols[name], label=name)
    ax_z.set(xlabel="time (s)", ylabel="height (m)")
    ax_z.legend(fontsize=7)
    for ax in (ax_s, ax_f, ax_z):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        print("usage: plot_run.py DIR", file=sys.stderr)
        return 2
    run_dir = argv[1]
    log = os.path.join(run_dir, "log.csv")
    try:
        cols = read_log(log)
    except (OSError, ValueError, csv.Error) as e:
        print("%s: cannot read the run log: %s" % (log, e), file=sys.stderr)
        return 2
    for k in [k for k in cols if k.endswith(("roll", "pitch", "yaw"))]:
        cols[k] = unwrap(cols[k])
    spans = state_spans(cols)
    made = []
    pose_cols = lambda p: ["%s_%s" % (p, a) for a in AXES + ANGLES]  # noqa: E731
    if has(cols, *pose_cols("obs"), *pose_cols("sensed")):
        pose_figure(cols, "obs", "sensed", "observed (solid) vs measured (dashed) object",
                    "obs", "meas", os.path.join(run_dir, "observation.png"))
        made.append("observation.png")
    if has(cols, *pose_cols("tcp"), *pose_cols("grasp")):
        pose_figure(cols, "tcp", "grasp", "TCP (solid) vs grasp frame (dashed)",
                    "tcp", "grasp", os.path.join(run_dir, "tracking.png"))
        paths_3d(cols, os.path.join(run_dir, "paths3d.png"))
        made += ["tracking.png", "paths3d.png"]
    if spans:
        timeline(cols, spans, os.path.join(run_dir, "timeline.png"))
        made.append("timeline.png")
    if has(cols, *["qmargin%d" % j for j in range(1, 8)]):
        joint_margins(cols, spans, os.path.join(run_dir, "joint_margins.png"))
        made.append("joint_margins.png")
    if has(cols, "d_human"):
        distances(cols, spans, os.path.join(run_dir, "distances.png"))
        made.append("distances.png")
    if has(cols, "load_share", "load_fx", "load_fy", "load_fz"):
        exchange(cols, spans, os.path.join(run_dir, "exchange.png"))
        made.append("exchange.png")
    print("plots: " + ", ".join(made) if made else "plots: none (columns missing)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
