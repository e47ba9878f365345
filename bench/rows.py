"""Bench rows (CSV lines on stdin: date, commit, scene, seed, then the rest) grouped for a
summary by scene and the column after the seed (frames, a --time-springs value, …)."""
import sys


def grouped():
    groups = {}
    for line in sys.stdin:
        fields = line.strip().split(",")
        groups.setdefault((fields[2], fields[4]), []).append(fields)
    return groups.items()


def column(rows, i):
    return [float(r[i]) for r in rows]
