#!/usr/bin/env python3
"""Runs scenarios with two builds of hydrodda and compares what they write, file by file.

For a change that must not alter results (a refactoring, a new module layout): every run
folder must hold the same files with the same bytes, apart from wall-clock timings, and the
program must print the same lines and exit with the same code.

    scripts/compare_run_folders.py OLD_BINARY NEW_BINARY SCENARIO... [--resume-after N]

Compared for each scenario:
  - `check SCENARIO`: its output and exit code;
  - `run SCENARIO -o DIR`: the exit code, the log (progress lines, which carry elapsed seconds
    and are printed at most once a second, left out) and every file of the run folder, figures
    included: summary.json without "timings", checkpoint.bin byte for byte (before format 4,
    which holds no timings, with its timing values zeroed), every other file byte for byte;
  - with --resume-after N, for coupled scenarios: `run --stop-after N` then `run --resume`,
    compared the same way.
Exit code 0 when everything agrees, 1 otherwise; the differences are listed.
"""

import argparse
import json
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROGRESS_LINE = re.compile(r"\[\d+\.\d s\]$")


def run(binary, arguments, log):
    start = time.monotonic()
    result = subprocess.run([binary, *arguments], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    log.write_text(result.stdout)
    return result.returncode, time.monotonic() - start


def log_lines(text, folder_names):
    """The log without progress lines, with the run folders' paths made the same."""
    lines = [line for line in text.splitlines() if not PROGRESS_LINE.search(line)]
    joined = "\n".join(lines)
    for name in folder_names:
        joined = joined.replace(str(name), "<folder>")
    return joined


def checkpoint_without_timings(data):
    """checkpoint.bin with the seconds of its timings zeroed: magic, version, byte-order mark,
    scenario hash, scenario file, converged, history rows, measure rows (format 2 and later),
    written iterations, then the timings (count, then name and seconds for each); what follows
    the timings (format 3: the coupling loop's Aitken state) is compared as it is."""
    if data.startswith((b"hydrodda transient checkpoint\n", b"hydrodda coupled transient checkpoint\n")):
        return bytes(data)  # a transient run's: no timings
    (version,) = struct.unpack_from("<q", data, len("hydrodda checkpoint\n"))
    if version >= 4:  # no timings: compared byte for byte
        return bytes(data)
    data = bytearray(data)
    at = len("hydrodda checkpoint\n") + 8 + 4 + 8

    def integer():
        nonlocal at
        (value,) = struct.unpack_from("<q", data, at)
        at += 8
        return value

    def skip_string():
        nonlocal at
        length = integer()
        at += length

    skip_string()  # scenario file
    integer()  # converged
    (version,) = struct.unpack_from("<q", data, len("hydrodda checkpoint\n"))
    for _ in range(2 if version >= 2 else 1):  # history rows, then (format 2) measure rows
        for _ in range(integer()):
            for _ in range(integer()):
                skip_string()
    iterations = integer()  # written iterations
    at += 8 * iterations
    for _ in range(integer()):
        skip_string()
        data[at:at + 8] = bytes(8)
        at += 8
    return bytes(data)


def summary_without_timings(text):
    summary = json.loads(text)
    summary.pop("timings", None)
    return summary


def compare_folders(old, new, label, problems):
    old_files = sorted(p.relative_to(old) for p in old.rglob("*") if p.is_file())
    new_files = sorted(p.relative_to(new) for p in new.rglob("*") if p.is_file())
    if old_files != new_files:
        problems.append(f"{label}: files differ: only old {sorted(set(old_files) - set(new_files))}, "
                        f"only new {sorted(set(new_files) - set(old_files))}")
    for name in sorted(set(old_files) & set(new_files)):
        a, b = (old / name).read_bytes(), (new / name).read_bytes()
        if name.name == "summary.json":
            same = summary_without_timings(a) == summary_without_timings(b)
            # The text too, so that a change of format or number printing shows.
            strip = lambda t: re.sub(rb'"timings": \{[^}]*\}', b"", t)
            same = same and strip(a) == strip(b)
        elif name.name == "checkpoint.bin":
            same = checkpoint_without_timings(a) == checkpoint_without_timings(b)
        else:
            same = a == b
        if not same:
            problems.append(f"{label}: {name} differs")
    return len(old_files)


def compare_runs(binaries, scenario, work, arguments_list, label, problems):
    """Runs each argument list in turn with both binaries (into work/old and work/new) and
    compares the exit codes and logs of each, then the folders."""
    folders = {side: work / side / label for side in ("old", "new")}
    seconds = {}
    for step, arguments in enumerate(arguments_list):
        codes, logs = {}, {}
        for side, binary in binaries.items():
            args = [a.replace("{dir}", str(folders[side])) for a in arguments]
            log = work / side / f"{label}.{step}.log"
            codes[side], elapsed = run(binary, args, log)
            seconds[side] = seconds.get(side, 0.0) + elapsed
            logs[side] = log_lines(log.read_text(), [folders[side]])
        if codes["old"] != codes["new"]:
            problems.append(f"{label} ({' '.join(arguments)}): exit code {codes['old']} → {codes['new']}")
        if logs["old"] != logs["new"]:
            problems.append(f"{label} ({' '.join(arguments)}): the printed lines differ\n--- old\n{logs['old']}\n"
                            f"--- new\n{logs['new']}")
    count = compare_folders(folders["old"], folders["new"], label, problems)
    return count, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old", help="the hydrodda binary before the change")
    parser.add_argument("new", help="the hydrodda binary after it")
    parser.add_argument("scenarios", nargs="+", type=Path)
    parser.add_argument("--resume-after", type=int, metavar="N",
                        help="also stop coupled runs after pass N and resume them")
    parser.add_argument("--keep", type=Path, help="keep the run folders here (default: a temporary folder)")
    args = parser.parse_args()
    binaries = {"old": str(Path(args.old).resolve()), "new": str(Path(args.new).resolve())}

    work = args.keep or Path(tempfile.mkdtemp(prefix="hydrodda-compare-"))
    for side in ("old", "new"):
        (work / side).mkdir(parents=True, exist_ok=True)
    problems = []
    for scenario in args.scenarios:
        label = scenario.stem
        for side in ("old", "new"):
            shutil.rmtree(work / side / label, ignore_errors=True)
        count, seconds = compare_runs(binaries, scenario, work, [["check", str(scenario)]], label + ".check", problems)
        count, seconds = compare_runs(binaries, scenario, work, [["run", str(scenario), "-o", "{dir}"]], label, problems)
        print(f"{scenario}: {count} files, old {seconds['old']:.1f} s, new {seconds['new']:.1f} s", flush=True)
        text = scenario.read_text()
        coupled = re.search(r"^\[mechanics\]", text, re.M) and re.search(r"^\[flow\]", text, re.M)
        if args.resume_after and coupled:
            resumed = label + ".resumed"
            for side in ("old", "new"):
                shutil.rmtree(work / side / resumed, ignore_errors=True)
            count, seconds = compare_runs(
                binaries, scenario, work,
                [["run", str(scenario), "-o", "{dir}", "--stop-after", str(args.resume_after)],
                 ["run", "--resume", "{dir}"]], resumed, problems)
            print(f"{scenario} (stopped after {args.resume_after}, resumed): {count} files, "
                  f"old {seconds['old']:.1f} s, new {seconds['new']:.1f} s", flush=True)
    if problems:
        print(f"\n{len(problems)} difference(s):")
        for p in problems:
            print("  " + p)
        return 1
    print(f"\nno difference in {len(args.scenarios)} scenario(s); folders in {work}")
    if not args.keep:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
