#!/usr/bin/python3
"""One ctest case of the `handover` command line.

Runs HANDOVER ARGS..., then checks the exit code, that stdout+stderr match a
regular expression, that files exist (non-empty), and optionally that an MP4
is a playable H.264 video. Before running it can remove stale outputs and
write a scenario derived from a shipped one (so the copy follows the shipped
file as it is tuned). The token @SHIPPED@ in ARGS expands to every
scenes/scenarios/*.yaml (sorted), read when the test runs.

Usage: cli_case.py --exe HANDOVER --exit N [options] -- ARGS...
Exit 0 when every check holds, 1 otherwise (the reason on stderr).
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def derive_scenario(src, dst, duration, expect_lines, name):
    """Copies SRC to DST, replacing the top-level `duration:` and `name:` lines
    and the whole top-level `expect:` block (dropped, or replaced by EXPECT_LINES)."""
    with open(src) as f:
        lines = f.read().splitlines()
    out, in_expect, saw_duration = [], False, False
    for line in lines:
        top_level = bool(re.match(r"[A-Za-z_]", line))
        if in_expect and top_level:
            in_expect = False
        if in_expect:
            continue
        if line.startswith("expect:"):
            in_expect = True
            continue
        if duration is not None and line.startswith("duration:"):
            line = "duration: %s" % duration
            saw_duration = True
        if name is not None and line.startswith("name:"):
            line = "name: %s" % name
        out.append(line)
    if duration is not None and not saw_duration:
        fail("%s has no top-level duration line to replace" % src)
    if expect_lines:
        out.append("expect:")
        out.extend("  " + e for e in expect_lines)
    os.makedirs(os.path.dirname(dst) or ".", exist_ok=True)
    with open(dst, "w") as f:
        f.write("\n".join(out) + "\n")


def check_video(path, ffprobe, min_frames):
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        fail("no video at %s" % path)
    r = subprocess.run([ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0",
                        "-show_entries", "stream=codec_name,nb_read_frames,width,height",
                        "-of", "json", path], capture_output=True, text=True)
    if r.returncode != 0:
        fail("ffprobe cannot read %s: %s" % (path, r.stderr.strip()))
    streams = json.loads(r.stdout).get("streams", [])
    if not streams:
        fail("%s has no video stream" % path)
    s = streams[0]
    print("video: %s" % s)
    if s.get("codec_name") != "h264":
        fail("codec %s, expected h264" % s.get("codec_name"))
    frames = int(s.get("nb_read_frames", 0))
    if frames <= min_frames:
        fail("%d frames decoded, expected more than %d" % (frames, min_frames))
    if int(s.get("width", 0)) <= 0 or int(s.get("height", 0)) <= 0:
        fail("bad frame size %sx%s" % (s.get("width"), s.get("height")))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--source-dir", required=True, help="repository root (for @SHIPPED@)")
    p.add_argument("--exit", type=int, required=True, help="expected exit code")
    p.add_argument("--match", action="append", default=[], help="regex stdout+stderr must match (repeatable)")
    p.add_argument("--clean", action="append", default=[], help="remove before running (repeatable)")
    p.add_argument("--files", action="append", default=[], help="must exist and be non-empty after (repeatable)")
    p.add_argument("--each-shipped-ok", action="store_true",
                   help="every @SHIPPED@ file must be reported as '<file>: ok'")
    p.add_argument("--derive", nargs=2, metavar=("SRC", "DST"), help="write DST from the shipped SRC first")
    p.add_argument("--duration", help="derived scenario: duration")
    p.add_argument("--name", help="derived scenario: name")
    p.add_argument("--expect", action="append", default=[], help="derived scenario: an expect line, 'key: value'")
    p.add_argument("--copy-config", metavar="DST", help="copy the source tree's config/ to DST first")
    p.add_argument("--config-edit", nargs=3, action="append", default=[], metavar=("FILE", "OLD", "NEW"),
                   help="in the copy's FILE, replace the text OLD (which must be there) by NEW (repeatable)")
    p.add_argument("--video", help="an MP4 to check with ffprobe after the run")
    p.add_argument("--ffprobe", default="ffprobe")
    p.add_argument("--min-frames", type=int, default=10)
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("args", nargs=argparse.REMAINDER)
    a = p.parse_args()
    args = a.args[1:] if a.args and a.args[0] == "--" else a.args

    for c in a.clean:
        if os.path.isdir(c):
            shutil.rmtree(c)
        elif os.path.exists(c):
            os.remove(c)
    if a.derive:
        derive_scenario(a.derive[0], a.derive[1], a.duration, a.expect, a.name)
    if a.copy_config:
        if os.path.isdir(a.copy_config):
            shutil.rmtree(a.copy_config)
        shutil.copytree(os.path.join(a.source_dir, "config"), a.copy_config)
    for name, old, new in a.config_edit:
        if not a.copy_config:
            fail("--config-edit needs --copy-config")
        path = os.path.join(a.copy_config, name)
        with open(path) as f:
            text = f.read()
        if old not in text:
            fail("%s has no %r to replace" % (path, old))
        with open(path, "w") as f:
            f.write(text.replace(old, new, 1))

    shipped = sorted(glob.glob(os.path.join(a.source_dir, "scenes", "scenarios", "*.yaml")))
    cmd = [a.exe]
    for arg in args:
        if arg == "@SHIPPED@":
            if not shipped:
                fail("no shipped scenarios found")
            cmd.extend(shipped)
        else:
            cmd.append(arg)

    print("running: " + " ".join(cmd), flush=True)
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout)
    except subprocess.TimeoutExpired:
        fail("timed out after %g s" % a.timeout)
    out = r.stdout + r.stderr
    print(out)
    if r.returncode != a.exit:
        fail("exit code %d, expected %d" % (r.returncode, a.exit))
    for m in a.match:
        if not re.search(m, out, re.S):
            fail("output does not match %r" % m)
    if a.each_shipped_ok:
        for f in shipped:
            if not re.search(re.escape(f) + r": ok \(", out):
                fail("%s not reported ok" % f)
    for f in a.files:
        if not os.path.isfile(f) or os.path.getsize(f) == 0:
            fail("missing or empty: %s" % f)
    if a.video:
        check_video(a.video, a.ffprobe, a.min_frames)
    print("ok")


if __name__ == "__main__":
    main()
