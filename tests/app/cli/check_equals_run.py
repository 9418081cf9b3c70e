#!/usr/bin/python3
"""`handover check` accepts nothing that `handover run` refuses (issue 17).

Runs both commands over every shipped scenario (run on a 0.3 s copy without
expectations) and over a set of bad inputs derived from default.yaml; each bad
input must fail both with exit 2 and the same message, naming the scenario's
file and line. Then checks the output side: names cannot escape out/, failed
writes and unwritable folders exit 2, the tracker's rejected samples are
reported, and the minor command-line items.

Usage: check_equals_run.py --exe HANDOVER --source-dir DIR --work DIR
Exit 0 when every check holds, 1 otherwise (every failure on stderr).
"""
import argparse
import glob
import json
import os
import re
import resource
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time

FAILURES = []


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    FAILURES.append(msg)


def run(exe, args, cwd=None, preexec=None, timeout=240):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True, errors="replace",
                       preexec_fn=preexec, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def derive(src, dst, replace=(), duration=None, drop_expect=False):
    with open(src) as f:
        text = f.read()
    for a, b in replace:
        if a not in text:
            raise SystemExit("%s: no %r to replace" % (src, a))
        text = text.replace(a, b, 1)
    if duration is not None:
        text = re.sub(r"(?m)^duration:.*$", "duration: %s" % duration, text)
    if drop_expect:
        text = re.split(r"(?m)^expect:", text)[0]
    with open(dst, "w") as f:
        f.write(text)
    return dst


# (name, replacements in default.yaml, regular expression the message must match)
BAD = [
    ("config_passwd", [("seed: 1", "seed: 1\nconfig: /etc/passwd")], r"key 'config'.*not a controller config"),
    ("config_passwd_set", [("seed: 1", "seed: 1\nconfig: /etc/passwd\nset:\n  tracking.weight: 1")],
     r"key 'config'.*not a controller config"),
    ("config_fsm", [("seed: 1", "seed: 1\nconfig: config/fsm.yaml")], r"key 'config'.*fsm\.yaml.*unknown key"),
    ("config_duplicate", [("seed: 1", "seed: 1\nconfig: @DUPCFG@")], r"key 'config'.*duplicate key"),
    ("set_zero_weights", [("seed: 1", "seed: 1\nset:\n  posture.weight: 0\n  qp.regularisation: 0")],
     r"key 'set\.qp\.regularisation'"),
    ("set_nan", [("seed: 1", "seed: 1\nset:\n  tracking.weight: .nan")], r"key 'set\.tracking\.weight'.*finite"),
    ("set_word", [("seed: 1", "seed: 1\nset:\n  tracking.weight: abc")], r"key 'set\.tracking\.weight'.*number"),
    ("set_negative", [("seed: 1", "seed: 1\nset:\n  tracking.weight: -1")], r"key 'set\.tracking\.weight'.*range"),
    ("period_max", [("seed: 1", "seed: 1\nset:\n  period: 0.1")], r"key 'set\.period'.*too fast"),
    ("period_small", [("seed: 1", "seed: 1\nset:\n  period: 1.0e-5")], r"key 'set\.period'.*simulator's step"),
    ("stiffness", [("seed: 1", "seed: 1\nset:\n  observation.stiffness: 1.0e7")], r"key 'set\.observation\.stiffness'"),
    ("damping", [("seed: 1", "seed: 1\nset:\n  observation.damping: 1.0e5")], r"key 'set\.observation\.damping'"),
    ("torque_scale", [("seed: 1", "seed: 1\nset:\n  limits.torque.scale: 0.001")], r"key 'set\.limits\.torque\.scale'.*gravity"),
    ("posture_target", [("seed: 1", "seed: 1\nset:\n  posture.target: [3, 0, 0, -1.5, 0, 1.5, 0]")],
     r"key 'set\.posture\.target'"),
    ("grasp_far", [("grasp: {pos: [0, 0, 0.06]", "grasp: {pos: [0, 0, 10]")], r"key 'object\.grasp\.pos\[2\]'"),
    ("grasp_outside", [("grasp: {pos: [0, 0, 0.06]", "grasp: {pos: [0, 0, 0.16]")], r"key 'object\.grasp'.*outside"),
    ("grasp_rolled", [("rpy: [3.1416, 0, 0]", "rpy: [1.1, 0, 0]")], r"key 'object\.grasp'.*wide across"),
    ("hold_far", [("holds_object: {pos: [0, 0, 0.04]", "holds_object: {pos: [0, 0, 0.5]")],
     r"key 'human\.holds_object'.*grip point"),
    ("start_q_limit", [("holds_object: false", "holds_object: false\n  start_q: [2.8973, -0.785, 0, -2.356, 0, 1.571, 0.785]")],
     r"key 'robot\.start_q\[0\]'"),
    ("start_q_table", [("holds_object: false", "holds_object: false\n  start_q: [0, 1.7, 0, -0.3, 0, 1.571, 0.785]")],
     r"key 'robot\.start_q'.*table"),
    ("start_q_person", [("holds_object: false", "holds_object: false\n  start_q: [0, 0.3, 0, -1.6, 0, 1.9, 0.785]"),
                        ("start: {pos: [0.85, 0.25, 0.10]", "start: {pos: [0.5, 0.0, 0.4]")],
     r"key 'robot\.start_q'.*person"),
    ("too_wide", [("shape: cylinder", "shape: box"), ("size: [0.03, 0.20]", "size: [0.1, 0.1, 0.1]"),
                  ("  free_axis: z\n", "")], r"wide across the fingers"),
    ("noise", [("noise: {pos: 0.001", "noise: {pos: 1e300")], r"key 'sensor\.noise\.pos'"),
    ("mass_tiny", [("mass: 0.3", "mass: 1e-12")], r"key 'object\.mass'"),
    ("size_tiny", [("size: [0.03, 0.20]", "size: [1e-12, 0.20]")], r"key 'object\.size\[0\]'"),
    ("duplicate_key", [("seed: 1", "seed: 1\nseed: 2")], r"key 'seed'.*duplicate"),
    ("name_control", [("name: default", "name: \"a\\x01b\"")], r"key 'name'.*control character"),
]


def check_equals_run(a, work):
    shipped = sorted(glob.glob(os.path.join(a.source_dir, "scenes/scenarios/*.yaml")) +
                     glob.glob(os.path.join(a.source_dir, "scenes/scenarios/paper/*.yaml")))
    default = os.path.join(a.source_dir, "scenes/scenarios/default.yaml")
    dupcfg = os.path.join(work, "dup_controller.yaml")
    with open(dupcfg, "w") as f:
        f.write("period: 0.001\nperiod: 0.002\n")
    out = os.path.join(work, "out")
    for path in shipped:
        rc, _, err = run(a.exe, ["check", path])
        if rc != 0:
            fail("check %s: exit %d: %s" % (path, rc, err.strip()))
        short = derive(path, os.path.join(work, "short_" + os.path.basename(path)), duration=0.3, drop_expect=True)
        rc, _, err = run(a.exe, ["run", short, "--out", os.path.join(out, "short"), "--quiet", "--log-every", "0"])
        if rc not in (0, 1):
            fail("check accepts %s, run exits %d: %s" % (path, rc, err.strip()))
    for name, repl, pattern in BAD:
        repl = [(x, y.replace("@DUPCFG@", dupcfg)) for x, y in repl]
        path = derive(default, os.path.join(work, name + ".yaml"), replace=repl)
        rc_c, _, err_c = run(a.exe, ["check", path])
        rc_r, _, err_r = run(a.exe, ["run", path, "--out", os.path.join(out, name), "--quiet", "--log-every", "0"])
        msg_c = err_c.strip().splitlines()[0] if err_c.strip() else ""
        msg_r = err_r.strip().splitlines()[0] if err_r.strip() else ""
        if rc_c != 2 or rc_r != 2:
            fail("%s: check exit %d, run exit %d (both must be 2): %s | %s" % (name, rc_c, rc_r, msg_c, msg_r))
            continue
        if not msg_c.startswith(path + ":") or not re.search(pattern, msg_c):
            fail("%s: check message %r does not name %s:LINE and match %r" % (name, msg_c, path, pattern))
        if msg_r != "handover: error: " + msg_c:
            fail("%s: run says %r, check says %r" % (name, msg_r, msg_c))


def outputs(a, work):
    default = os.path.join(a.source_dir, "scenes/scenarios/default.yaml")
    # a name cannot write outside out/ (run without --out)
    esc = derive(default, os.path.join(work, "escape.yaml"), replace=[("name: default", "name: ../../escaped_by_name")],
                 duration=0.3, drop_expect=True)
    cwd = os.path.join(work, "cwd", "a", "b")
    os.makedirs(cwd, exist_ok=True)
    rc, so, err = run(a.exe, ["run", esc, "--quiet", "--log-every", "0"], cwd=cwd)
    if rc != 0 or not os.path.isfile(os.path.join(cwd, "out", "_._.._escaped_by_name", "summary.json")):
        fail("escaping name: exit %d, files %s: %s" % (rc, os.listdir(cwd), err))
    if os.path.exists(os.path.join(work, "cwd", "escaped_by_name")):
        fail("escaping name: wrote outside out/")

    short = derive(default, os.path.join(work, "short.yaml"), duration=0.3, drop_expect=True)
    # a write that fails (file size limit, as a full disk): exit 2, never an empty summary with exit 0
    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (300, 300))
    full = os.path.join(work, "full")
    rc, _, err = run(a.exe, ["run", short, "--out", full, "--quiet", "--log-every", "0"], preexec=limit)
    if rc != 2 or "write failed" not in err:
        fail("failed summary write: exit %d: %s" % (rc, err.strip()))
    # an output folder that cannot exist fails at once
    blocker = os.path.join(work, "a_file")
    with open(blocker, "w") as f:
        f.write("x")
    rc, so, err = run(a.exe, ["run", short, "--out", os.path.join(blocker, "out"), "--quiet"])
    if rc != 2 or "output folder" not in err or "outcome" in so:
        fail("unwritable --out: exit %d: %s %s" % (rc, so, err))
    rc, so, err = run(a.exe, ["run", short, "--out", os.path.join(work, "v"), "--video",
                              os.path.join(work, "no_such_folder", "a.mp4"), "--quiet"])
    if rc != 2 or "does not exist" not in err or os.path.exists(os.path.join(work, "no_such_folder")):
        fail("--video into a missing folder: exit %d: %s" % (rc, err))
    # input size: /dev/zero is refused at once, naming the file
    rc, _, err = run(a.exe, ["check", "/dev/zero"], timeout=60)
    if rc != 2 or not err.startswith("/dev/zero:"):
        fail("check /dev/zero: exit %d: %s" % (rc, err[:200]))
    # minor items
    rc, _, err = run(a.exe, ["run", short, "--tracker", "udp:22x", "--out", os.path.join(work, "u"), "--quiet"])
    if rc != 2 or "udp:22x" not in err:
        fail("--tracker udp:22x: exit %d: %s" % (rc, err))
    rc, _, err = run(a.exe, ["hold", "--duration", "0.1", "--max-drift-mm", "nan"])
    if rc != 2:
        fail("hold --max-drift-mm nan: exit %d: %s" % (rc, err))
    # plot of a truncated log.csv
    logged = os.path.join(work, "logged")
    rc, _, err = run(a.exe, ["run", short, "--out", logged, "--quiet"])
    if rc != 0:
        fail("run with log: exit %d: %s" % (rc, err))
    else:
        with open(os.path.join(logged, "log.csv")) as f:
            text = f.read()
        # cut the last row in half: it loses fields, whatever its trailing text column holds
        last = text.rstrip("\n").rfind("\n") + 1
        with open(os.path.join(logged, "log.csv"), "w") as f:
            f.write(text[: last + (len(text) - last) // 2])
        rc, _, err = run(a.exe, ["plot", logged])
        if rc == 0 or "truncated" not in err:
            fail("plot of a truncated log.csv: exit %d: %s" % (rc, err))


def tracker(a, work):
    default = os.path.join(a.source_dir, "scenes/scenarios/default.yaml")
    short = derive(default, os.path.join(work, "tracked.yaml"), duration=1.0, drop_expect=True)
    header = ("t,hand_x,hand_y,hand_z,hand_qw,hand_qx,hand_qy,hand_qz,forearm_x,forearm_y,forearm_z,forearm_qw,"
              "forearm_qx,forearm_qy,forearm_qz,upper_arm_x,upper_arm_y,upper_arm_z,upper_arm_qw,upper_arm_qx,"
              "upper_arm_qy,upper_arm_qz")
    rows = ["%g,0.85,0.25,0.1,1,0,0,0,1.0,0.25,0.1,1,0,0,0,1.05,0.2,0.5,1,0,0,0" % (k / 60.0) for k in range(60)]
    csv_path = os.path.join(work, "bom.csv")
    with open(csv_path, "w", encoding="utf-8-sig") as f:  # with a byte-order mark
        f.write(header + "\n" + "\n".join(rows) + "\n")
    out = os.path.join(work, "csv_run")
    rc, so, err = run(a.exe, ["run", short, "--tracker", "csv:" + csv_path, "--out", out, "--quiet", "--log-every", "0"])
    if rc == 2:
        fail("CSV with a byte-order mark refused: %s" % err)
    elif "tracker    csv, 0 samples rejected" not in so:
        fail("CSV run: no tracker line on screen: %s" % so)
    else:
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        t = s.get("tracker") or {}
        if t.get("source") != "csv" or t.get("rejected_samples") != 0 or \
                any(t.get("rejected", {"?": 1}).values()):
            fail("CSV run: summary tracker %r" % s.get("tracker"))

    # UDP: malformed datagrams are counted in the summary and on screen
    probe = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    probe.bind(("127.0.0.1", 0))
    port = probe.getsockname()[1]
    probe.close()
    stop = threading.Event()

    def send():
        s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        while not stop.is_set():
            s.sendto(b"hpose not,numbers", ("127.0.0.1", port))
            time.sleep(0.02)
        s.close()
    th = threading.Thread(target=send)
    th.start()
    out = os.path.join(work, "udp_run")
    try:
        rc, so, err = run(a.exe, ["run", short, "--tracker", "udp:%d" % port, "--out", out, "--quiet", "--log-every", "0"])
    finally:
        stop.set()
        th.join()
    m = re.search(r"tracker    udp, (\d+) samples rejected", so)
    if rc == 2 or not m or int(m.group(1)) < 1:
        fail("UDP run: exit %d, screen %s %s" % (rc, so, err))
    else:
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        if s["tracker"]["source"] != "udp" or s["tracker"]["rejected_samples"] != int(m.group(1)):
            fail("UDP run: summary tracker %r, screen %s" % (s["tracker"], m.group(0)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--part", choices=["check_equals_run", "outputs", "tracker"], required=True)
    a = ap.parse_args()
    a.exe = os.path.abspath(a.exe)
    work = os.path.join(a.work, a.part)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"check_equals_run": check_equals_run, "outputs": outputs, "tracker": tracker}[a.part](a, work)
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
