#!/usr/bin/env python3
"""Runs `pak inspect --json` on each file of some sets and prints a Markdown table per set:
files, read cleanly, warnings by kind, errors by kind, failures (a crash, or over the time
limit). With --compare N, also draws every k-th file (N per set) with `pak render` and with
Inkscape, and counts the pixels that differ. Called by scripts/icon-survey.sh, which fetches
the sets.

Usage: icon_survey.py --pak PAK [--sample N] [--compare N] [--results TSV] NAME=LISTFILE ...
"""
import argparse
import collections
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

TIME_LIMIT = 5.0  # seconds; a file that takes longer is a failure
PICTURE = 200  # pixels a side of the pictures compared
# Pixels whose colours differ by more than this share of the range count as different: the two
# renderers' anti-aliasing differs by less.
FUZZ = "20%"


def kind_of(message):
    """A message with its particulars (quoted values, ids, numbers) blanked, so messages
    about the same thing count together."""
    message = re.sub(r'"[^"]*"', '"…"', message)
    message = re.sub(r"'[^']*'", "'…'", message)
    message = re.sub(r"url\(#[^)]*\)", "url(#…)", message)
    message = re.sub(r"#[0-9A-Za-z_.:-]+", "#…", message)
    message = re.sub(r"-?\d+(\.\d+)?(e[-+]?\d+)?", "N", message)
    return message


def error_kind(stderr, file):
    """The what of `pak: error: <where>: <what>`, the file name taken out of the where."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    if not lines:
        return "(no message)"
    line = lines[-1]
    line = line.removeprefix("pak: error: ").replace(file, "FILE")
    return kind_of(line)


def sampled(files, limit):
    """Every k-th of the sorted list, so at most `limit` files (all when limit is 0)."""
    if limit <= 0 or len(files) <= limit:
        return files
    step = -(-len(files) // limit)
    return files[::step]


def inspect(pak, file):
    start = time.monotonic()
    try:
        run = subprocess.run([pak, "inspect", "--json", file], capture_output=True, text=True, timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        return {"status": "failure", "detail": f"over {TIME_LIMIT:g} s", "seconds": TIME_LIMIT}
    seconds = time.monotonic() - start
    if run.returncode == 0:
        report = json.loads(run.stdout)["files"][0]
        return {"status": "read", "seconds": seconds, "elements": len(report["elements"]),
                "warnings": [w["message"] for w in report["warnings"]]}
    if run.returncode == 2 and "pak: error:" in run.stderr:
        return {"status": "error", "seconds": seconds, "detail": error_kind(run.stderr, file)}
    return {"status": "failure", "seconds": seconds,
            "detail": f"exit {run.returncode}: " + (run.stderr.strip().splitlines() or [""])[-1][:200]}


def differing_share(pak, file, folder):
    """The share of pixels that differ between Pak's picture of the file and Inkscape's, both
    drawn over white and squeezed to PICTURE × PICTURE; None when either cannot draw it."""
    ours, theirs = os.path.join(folder, "pak.png"), os.path.join(folder, "inkscape.png")
    for picture in (ours, theirs):
        if os.path.exists(picture):
            os.remove(picture)
    try:
        subprocess.run([pak, "render", file, "-o", ours, "--width", str(PICTURE)], capture_output=True,
                       timeout=30)
        subprocess.run(["inkscape", "--export-type=png", f"--export-filename={theirs}", f"--export-width={PICTURE}",
                        "--export-area-page", "--export-background=white", "--export-background-opacity=1", file],
                       capture_output=True, timeout=60)
    except subprocess.TimeoutExpired:
        return None
    if not (os.path.exists(ours) and os.path.exists(theirs)):
        return None
    size = f"{PICTURE}x{PICTURE}!"
    run = subprocess.run(["compare", "-metric", "AE", "-fuzz", FUZZ, "(", ours, "-resize", size, ")",
                          "(", theirs, "-resize", size, ")", "null:"], capture_output=True, text=True)
    try:
        return float(run.stderr.split()[0]) / (PICTURE * PICTURE)
    except (ValueError, IndexError):
        return None


def comparison(pak, name, files, limit):
    """A Markdown paragraph: how far Pak's pictures of `limit` files of the set are from Inkscape's."""
    chosen = sampled(files, limit)
    shares = []
    with tempfile.TemporaryDirectory() as folder:
        for i, file in enumerate(chosen):
            share = differing_share(pak, file, folder)
            if share is not None:
                shares.append((share, file.rsplit("/", 1)[-1]))
            sys.stderr.write(f"\r{name}: compared {i + 1}/{len(chosen)}")
    sys.stderr.write("\n")
    if not shares:
        return "Compared with Inkscape: nothing could be drawn by both.\n"
    shares.sort(reverse=True)
    over = sum(1 for share, _ in shares if share > 0.02)
    worst = ", ".join(f"{file} {100 * share:.1f} %" for share, file in shares[:3])
    return (f"Compared with Inkscape ({len(shares)} files drawn by both, {PICTURE} px a side): median "
            f"{100 * statistics.median(s for s, _ in shares):.2f} % of the pixels differ; {over} files over 2 %; "
            f"most: {worst}.\n")


def table(rows, header):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(cell).replace("|", "\\|") for cell in row) + " |" for row in rows]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--pak", required=True)
    parser.add_argument("--sample", type=int, default=0)
    parser.add_argument("--compare", type=int, default=0)
    parser.add_argument("--results")
    parser.add_argument("sets", nargs="+", metavar="NAME=LISTFILE")
    args = parser.parse_args()

    results = open(args.results, "w") if args.results else None
    for entry in args.sets:
        name, listfile = entry.split("=", 1)
        with open(listfile) as f:
            all_files = [line.strip() for line in f if line.strip()]
        files = sampled(all_files, args.sample)
        counts = collections.Counter()
        warnings = collections.Counter()
        warned_files = collections.Counter()
        examples = {}
        errors = collections.Counter()
        failures = []
        slowest = (0.0, "")
        for file in files:
            result = inspect(args.pak, file)
            counts[result["status"]] += 1
            slowest = max(slowest, (result["seconds"], file))
            short = file.rsplit("/", 1)[-1]
            if result["status"] == "read":
                kinds = [kind_of(m) for m in result["warnings"]]
                if not kinds:
                    counts["clean"] += 1
                if result["elements"] > 1:
                    counts["several elements"] += 1
                for k in kinds:
                    warnings[k] += 1
                    examples.setdefault(k, short)
                for k in set(kinds):
                    warned_files[k] += 1
                detail = "; ".join(result["warnings"])
            elif result["status"] == "error":
                errors[result["detail"]] += 1
                examples.setdefault(result["detail"], short)
                detail = result["detail"]
            else:
                failures.append(f"{short}: {result['detail']}")
                detail = result["detail"]
            if results:
                results.write(f"{name}\t{file}\t{result['status']}\t{result['seconds']:.3f}\t{detail}\n")
            sys.stderr.write(f"\r{name}: {sum(counts[s] for s in ('read', 'error', 'failure'))}/{len(files)}")
        sys.stderr.write("\n")

        step = -(-len(all_files) // len(files)) if files else 1
        sample_note = "" if len(files) == len(all_files) else f" of {len(all_files)} (one in {step})"
        print(f"### {name}\n")
        print(table([[f"{len(files)}{sample_note}", counts["read"], counts["clean"], counts["several elements"],
                      counts["error"], len(failures), f"{slowest[0]:.2f} s"]],
                    ["files", "read", "read cleanly", "read as several elements", "errors", "failures",
                     "slowest"]))
        if warnings:
            print("\nWarnings by kind:\n")
            print(table([[k, n, warned_files[k], examples[k]] for k, n in warnings.most_common()],
                        ["warning", "count", "files", "e.g."]))
        if errors:
            print("\nErrors by kind:\n")
            print(table([[k, n, examples[k]] for k, n in errors.most_common()], ["error", "files", "e.g."]))
        if failures:
            print("\nFailures:\n")
            for failure in failures:
                print(f"- {failure}")
        if args.compare > 0:
            print("\n" + comparison(args.pak, name, all_files, args.compare), end="")
        print()
        sys.stdout.flush()


if __name__ == "__main__":
    main()
