#!/usr/bin/python3
"""Draws a release (human to robot) or a pull (robot to human), before and after
a change, from two runs' log.csv (docs/method.md, "The physical exchange").

  plot_exchange.py release BEFORE_LOG AFTER_LOG OUT.png [LABEL_A LABEL_B]
  plot_exchange.py pull    BEFORE_LOG AFTER_LOG OUT.png [LABEL_A LABEL_B]

(the labels default to "before" and "after")

Time is counted from the release (the person's hand 1 cm off the object after
a confirmed grasp) or from the pull's onset (the waiting receiver's hand moves
2 mm), as scripts/exchange_sink.py finds them. Rows: the object's height (a
release) or the TCP's displacement (a pull); the load share and the grip
force; the load on the wrist along the vertical. Debian's python3 with
matplotlib.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exchange_sink  # noqa: E402


def release_time(rows):
    r = exchange_sink.h2r_sink(rows)
    return None if r is None else r["release_time"]


def pull_time(rows):
    r = exchange_sink.r2h_pull(rows)
    return None if r is None else r["pull_time"]


def draw(kind, before, after, out, labels=("before", "after")):
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    ax2 = axes[1].twinx()  # the grip force beside the load share
    for label, path, style in ((labels[0], before, "--"), (labels[1], after, "-")):
        rows = exchange_sink.load(path)
        t0 = release_time(rows) if kind == "release" else pull_time(rows)
        if t0 is None:
            print(f"{path}: no {kind} found", file=sys.stderr)
            return 1
        t = [x - t0 for x in exchange_sink.col(rows, "time")]
        lo, hi = (-1.0, 2.5) if kind == "release" else (-0.5, 0.5)
        keep = [i for i, x in enumerate(t) if lo <= x <= hi]
        tt = [t[i] for i in keep]
        i0 = min(range(len(t)), key=lambda i: abs(t[i]))
        if kind == "release":
            z = exchange_sink.col(rows, "object_z")
            axes[0].plot(tt, [1000 * (z[i] - z[i0]) for i in keep], style, label=f"object height, {label}")
        else:
            p = list(zip(*(exchange_sink.col(rows, "tcp_" + a) for a in "xyz")))
            axes[0].plot(tt, [1000 * math.dist(p[i], p[i0]) for i in keep], style, label=f"TCP displacement, {label}")
        share = exchange_sink.col(rows, "load_share")
        grip = exchange_sink.col(rows, "grip_force")
        axes[1].plot(tt, [share[i] for i in keep], style, label=f"load share, {label}")
        ax2.plot(tt, [grip[i] for i in keep], style, color="tab:red", alpha=0.6, label=f"grip force, {label}")
        fz = exchange_sink.col(rows, "load_fz")
        axes[2].plot(tt, [fz[i] for i in keep], style, label=f"wrist load, vertical, {label}")
    limit = 10 if kind == "release" else 20
    axes[0].axhline(-limit if kind == "release" else limit, color="grey", lw=0.8, ls=":")  # a sink is down
    axes[0].set_ylabel("mm")
    axes[0].set_title(f"{'Release: the person lets go' if kind == 'release' else 'Pull: the receiver takes the object'}"
                      f" (t = 0), dotted: {limit} mm")
    axes[1].set_ylabel("load share")
    ax2.set_ylabel("grip force (N)", color="tab:red")
    axes[2].set_ylabel("N")
    axes[2].set_xlabel(f"time from the {kind} (s)")
    for ax in axes:
        ax.axvline(0.0, color="black", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    ax2.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)
    return 0


def main(argv):
    if len(argv) not in (4, 6) or argv[0] not in ("release", "pull"):
        print(__doc__, file=sys.stderr)
        return 2
    return draw(*argv[:4], labels=tuple(argv[4:6]) if len(argv) == 6 else ("before", "after"))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
