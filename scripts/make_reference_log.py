#!/usr/bin/python3
"""Cut a small reference out of a run's log.csv, for tests/app/run/test_reference_run.

The reference keeps every Nth row and a few columns: the state, the TCP
position, the joint positions and torques, the commanded gripper width and
the distance to the person. The test reruns the scenario and compares its
log.csv with the reference to the log's own rounding, so a refactor that
changes behaviour shows up as a failing test.

  handover run scenes/scenarios/default.yaml --out /tmp/ref_default --quiet
  scripts/make_reference_log.py /tmp/ref_default/log.csv \
      tests/app/run/data/reference_default.csv

Regenerate only when behaviour changes on purpose, and say why in the commit.
"""
import csv
import sys

EVERY = 20  # rows of log.csv (5 ms each): one reference row per 100 ms
COLUMNS = ["time", "state", "tcp_x", "tcp_y", "tcp_z"] + [f"q{j}" for j in range(1, 8)] + \
          [f"tau{j}" for j in range(1, 8)] + ["gripper_cmd", "d_human"]


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    missing = [c for c in COLUMNS if rows and c not in rows[0]]
    if missing:
        sys.exit(f"{argv[1]}: no column(s) {', '.join(missing)}")
    with open(argv[2], "w", newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(COLUMNS)
        for i, row in enumerate(rows):
            if i % EVERY == 0:
                out.writerow([row[c] for c in COLUMNS])


if __name__ == "__main__":
    main(sys.argv)
