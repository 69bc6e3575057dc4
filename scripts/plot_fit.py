"""Draws DIR/fit.png for `plisse fit -o DIR`: the test data (markers) against the fitted model's
nominal stress (lines), one colour per test, from DIR/fit.csv and DIR/curves.csv.

Usage: /usr/bin/python3 scripts/plot_fit.py DIR TITLE
Needs Debian's python3-matplotlib (hence /usr/bin/python3).
"""
import csv
import sys
from pathlib import Path

from plisse_study.figures import LinkRefused, plt, save


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(directory, title):
    out = Path(directory)
    points, curves = read(out / "fit.csv"), read(out / "curves.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for k, mode in enumerate(["uniaxial", "equibiaxial", "planar"]):
        data = [r for r in points if r["mode"] == mode]
        if not data:
            continue
        colour = f"C{k}"
        line = [r for r in curves if r["mode"] == mode]
        ax.plot([float(r["stretch"]) for r in line], [float(r["model_stress"]) for r in line],
                "-", color=colour, lw=1.2, label=f"{mode}: fit")
        ax.plot([float(r["stretch"]) for r in data], [float(r["stress"]) for r in data],
                "o", color=colour, ms=4, mfc="none", label=f"{mode}: data")
    ax.set_xlabel("stretch λ")
    ax.set_ylabel("nominal stress [MPa]")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, out / "fit.png", dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_fit.py DIR TITLE")
    try:
        main(sys.argv[1], sys.argv[2])
    except LinkRefused as e:
        print(f"plisse fit: {e}", file=sys.stderr)
        sys.exit(2)
