#!/usr/bin/env python3
"""Plots of an `acdplan bench` output folder (reads DIR/runs.csv, writes PNGs into DIR).

  success_vs_width.png  success rate (with 95% Wilson intervals) against the passage width as a
                        share of the workspace width, one line per robot x sampler x planner x
                        budget; worlds of one sweep (family) are joined by lines.
  time_to_solve.png     distributions of the time to solve (solved runs; acd including its
                        decomposition) per world and sampler, log scale.

Usage: tools/plot_bench.py DIR        (Debian: python3-matplotlib)
"""
import csv
import math
import os
import sys
from collections import OrderedDict, defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"acd": "#d62728", "uniform": "#1f77b4", "gaussian": "#2ca02c", "bridge": "#9467bd",
           "obstacle_based": "#8c564b", "max_clearance": "#e377c2"}


def wilson(k, n, z=1.959963984540054):
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = p + z * z / (2 * n)
    spread = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    scale = 1 + z * z / n
    return max(0.0, (centre - spread) / scale), min(1.0, (centre + spread) / scale)


def read_runs(folder):
    with open(os.path.join(folder, "runs.csv"), newline="") as f:
        return list(csv.DictReader(f))


def success_vs_width(runs, out):
    # (family, robot, sampler, planner, budget) -> width share -> [successes, runs]
    cells = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for r in runs:
        width, extent = float(r["passage_width"]), float(r["workspace_width"])
        if width <= 0 or extent <= 0:
            continue
        key = (r["family"], r["robot"], r["sampler"], r["planner"], r["budget"])
        cell = cells[key][100.0 * width / extent]
        cell[0] += r["solved"] == "1"
        cell[1] += 1
    if not cells:
        print("plot_bench: no passage widths in runs.csv; skipped success_vs_width.png")
        return
    families = sorted({k[0] for k in cells})
    fig, axes = plt.subplots(1, len(families), figsize=(5.5 * len(families), 4.5), squeeze=False)
    for ax, family in zip(axes[0], families):
        for key, points in sorted(cells.items()):
            if key[0] != family:
                continue
            xs = sorted(points)
            ys = [points[x][0] / points[x][1] for x in xs]
            cis = [wilson(*points[x]) for x in xs]
            lo = [max(0.0, y - c[0]) for y, c in zip(ys, cis)]
            hi = [max(0.0, c[1] - y) for y, c in zip(ys, cis)]
            label = f"{key[2]} {key[3]} {key[1]} ({key[4]})"
            ax.errorbar(xs, ys, yerr=[lo, hi], marker="o", capsize=3, label=label,
                        color=COLOURS.get(key[2]), linestyle="-" if len(xs) > 1 else "none",
                        alpha=0.85)
        ax.set_xscale("log")
        ax.set_xlabel("passage width [% of workspace width]")
        ax.set_ylabel("success rate")
        ax.set_ylim(-0.03, 1.03)
        ax.set_title(family)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "success_vs_width.png"), dpi=110)
    plt.close(fig)


def time_to_solve(runs, out):
    # world -> sampler label -> times
    data = OrderedDict()
    for r in runs:
        if r["solved"] != "1":
            continue
        label = f"{r['sampler']}\n{r['planner']} {r['robot']}\n{r['budget']}"
        data.setdefault(r["world"], OrderedDict()).setdefault(label, []).append(float(r["time_s"]))
    if not data:
        print("plot_bench: no solved runs; skipped time_to_solve.png")
        return
    worlds = list(data)
    columns = min(3, len(worlds))
    rows = (len(worlds) + columns - 1) // columns
    widest = max(len(v) for v in data.values())
    fig, axes = plt.subplots(rows, columns, figsize=(max(5.0, 0.55 * widest + 1.5) * columns,
                                                     4.2 * rows), squeeze=False)
    for ax in axes.flat[len(worlds):]:
        ax.axis("off")
    for ax, world in zip(axes.flat, worlds):
        labels = list(data[world])
        parts = ax.boxplot([data[world][l] for l in labels], patch_artist=True, widths=0.6)
        for patch, label in zip(parts["boxes"], labels):
            patch.set_facecolor(COLOURS.get(label.split("\n")[0], "#bbbbbb"))
            patch.set_alpha(0.6)
        ax.set_xticks(range(1, len(labels) + 1))
        ax.set_xticklabels(labels, fontsize=6, rotation=90)
        ax.set_yscale("log")
        ax.set_ylabel("time to solve [s]")
        ax.set_title(world)
        ax.grid(True, axis="y", which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_to_solve.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = sys.argv[1]
    runs = read_runs(folder)
    success_vs_width(runs, folder)
    time_to_solve(runs, folder)
    print(f"plot_bench: wrote PNGs into {folder}")


if __name__ == "__main__":
    main()
