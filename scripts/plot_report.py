#!/usr/bin/python3
"""Draws DIR/report.png from a batch's DIR/results.csv (docs/benchmark.md).

For each benchmark factor (direction, grasp family, shape, behaviour, where the
person stands, hand, height), a stacked bar per value: the share of each
outcome, with the share of runs that ended as expected (ok) marked on top.
Usage: plot_report.py DIR. Debian's python3 with matplotlib.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OUTCOMES = ["success", "aborted", "hand_contact", "object_drop", "timeout", "no_perception", "unsafe", "error"]
COLOURS = ["#4c9a4c", "#8fb8de", "#d62728", "#ff7f0e", "#9467bd", "#e7c54a", "#8c564b", "#555555"]
FACTORS = [("direction", "direction"), ("grasp", "grasp family"), ("shape", "shape"), ("behaviour", "behaviour"),
           ("placement", "person stands"), ("hand", "hand"), ("height", "height")]


def main():
    if len(sys.argv) != 2:
        print("usage: plot_report.py DIR", file=sys.stderr)
        return 2
    d = sys.argv[1]
    path = os.path.join(d, "results.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        print(f"plot_report: {path}: {e}", file=sys.stderr)
        return 2
    if not rows or "direction" not in rows[0]:
        print(f"plot_report: {path}: no runs, or not a results.csv of this version", file=sys.stderr)
        return 2
    fig, axes = plt.subplots(2, 4, figsize=(18, 8.5))
    for ax, (key, title) in zip(axes.flat, FACTORS):
        values = sorted({r[key] for r in rows})
        bottoms = [0.0] * len(values)
        groups = {v: [r for r in rows if r[key] == v] for v in values}
        for o, colour in zip(OUTCOMES, COLOURS):
            shares = [100.0 * sum(r["outcome"] == o for r in groups[v]) / len(groups[v]) for v in values]
            ax.bar(values, shares, bottom=bottoms, color=colour, label=o)
            bottoms = [b + s for b, s in zip(bottoms, shares)]
        for i, v in enumerate(values):
            ok = 100.0 * sum(r["met"] == "1" for r in groups[v]) / len(groups[v])
            ax.text(i, 102, f"ok {ok:.0f}%\nn={len(groups[v])}", ha="center", va="bottom", fontsize=8)
        ax.set_ylim(0, 122)
        ax.set_title(title)
        ax.set_ylabel("% of runs")
        ax.tick_params(axis="x", rotation=30, labelsize=8)
    # the last panel: time to grasp over successful take runs, by grasp family
    ax = axes.flat[-1]
    families = sorted({r["grasp"] for r in rows})
    data = [[float(r["hand_still_to_grasp"]) for r in rows
             if r["grasp"] == g and r["outcome"] == "success" and r["hand_still_to_grasp"]] for g in families]
    keep = [(g, x) for g, x in zip(families, data) if x]
    if keep:
        ax.boxplot([x for _, x in keep], labels=[g for g, _ in keep], showfliers=False)
    ax.set_title("hand still to grasp (successful runs)")
    ax.set_ylabel("s")
    ax.tick_params(axis="x", rotation=30, labelsize=8)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(OUTCOMES))
    fig.suptitle(f"Handover benchmark: {len(rows)} runs")
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    fig.savefig(os.path.join(d, "report.png"), dpi=90)
    return 0


if __name__ == "__main__":
    sys.exit(main())
