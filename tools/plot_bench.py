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


BUDGET_STYLES = ["-", "--", ":", "-."]
MARKERS = ["o", "s", "^", "D"]


def success_vs_width(runs, out):
    """One panel per (sweep or "built-in worlds") x robot; one series per sampler x planner x
    budget (colour: sampler, line style: budget). Time budgets are left out when the runs also
    have sample budgets (they nearly always succeed and crowd the panel)."""
    have_samples = any(r["sample_budget"] != "0" for r in runs)
    widths_of = defaultdict(set)
    for r in runs:
        if float(r["passage_width"]) > 0:
            widths_of[r["family"]].add(r["passage_width"])
    # panel -> series -> x -> [successes, runs, world]
    panels = defaultdict(lambda: defaultdict(dict))
    for r in runs:
        width, extent = float(r["passage_width"]), float(r["workspace_width"])
        if width <= 0 or extent <= 0 or (have_samples and r["sample_budget"] == "0"):
            continue
        group = r["family"] if len(widths_of[r["family"]]) > 1 else "built-in worlds"
        panel = (group, r["robot"])
        series = (r["sampler"], r["planner"], r["budget"])
        x = 100.0 * width / extent
        cell = panels[panel][series].setdefault(x, [0, 0, r["family"]])
        cell[0] += r["solved"] == "1"
        cell[1] += 1
    if not panels:
        print("plot_bench: no passage widths in runs.csv; skipped success_vs_width.png")
        return
    keys = sorted(panels)
    columns = min(3, len(keys))
    rows = (len(keys) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(6.0 * columns, 4.6 * rows), squeeze=False)
    for ax in axes.flat[len(keys):]:
        ax.axis("off")
    budgets = sorted({s[2] for p in panels.values() for s in p},
                     key=lambda b: (b.endswith(" s"), float(b.split()[0])))
    for ax, key in zip(axes.flat, keys):
        group, robot = key
        for series, points in sorted(panels[key].items()):
            sampler, planner, budget = series
            xs = sorted(points)
            ys = [points[x][0] / points[x][1] for x in xs]
            cis = [wilson(points[x][0], points[x][1]) for x in xs]
            lo = [max(0.0, y - c[0]) for y, c in zip(ys, cis)]
            hi = [max(0.0, c[1] - y) for y, c in zip(ys, cis)]
            b = budgets.index(budget) % len(BUDGET_STYLES)
            joined = group != "built-in worlds" and len(xs) > 1
            # The planner is told by the marker fill: PRM_ACD hollow, the others solid.
            hollow = planner.endswith("_ACD")
            ax.errorbar(xs, ys, yerr=[lo, hi], capsize=2, marker=MARKERS[b], markersize=5,
                        linestyle=(":" if hollow else BUDGET_STYLES[b]) if joined else "none",
                        color=COLOURS.get(sampler), alpha=0.8,
                        markerfacecolor="white" if hollow else COLOURS.get(sampler),
                        label=f"{sampler} {planner} {budget}")
        if group == "built-in worlds":
            labels = {}
            for points in panels[key].values():
                for x, cell in points.items():
                    labels.setdefault(x, set()).add(cell[2])
            for x, names in labels.items():
                ax.annotate("\n".join(sorted(names)), (x, -0.02), xycoords=("data", "axes fraction"),
                            xytext=(0, -28), textcoords="offset points", ha="center", fontsize=6)
        ax.set_xscale("log")
        ax.set_xlabel("passage width [% of workspace width]", labelpad=18 if group == "built-in worlds" else 4)
        ax.set_ylabel("success rate")
        ax.set_ylim(-0.03, 1.03)
        ax.set_title(f"{group}, robot {robot}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "success_vs_width.png"), dpi=100)
    plt.close(fig)


def time_to_solve(runs, out):
    """Box plots of the time to solve per world: time budgets when there are any (else all
    budgets), one box per robot x planner x sampler, coloured by sampler."""
    timed = [r for r in runs if r["sample_budget"] == "0"]
    chosen = timed if timed else runs
    data = OrderedDict()
    for r in chosen:
        if r["solved"] != "1":
            continue
        label = f"{r['sampler']}\n{r['planner']} {r['robot']}" + ("" if timed else f"\n{r['budget']}")
        data.setdefault(r["world"], OrderedDict()).setdefault(label, []).append(float(r["time_s"]))
    if not data:
        print("plot_bench: no solved runs; skipped time_to_solve.png")
        return
    worlds = list(data)
    columns = min(3, len(worlds))
    rows = (len(worlds) + columns - 1) // columns
    widest = max(len(v) for v in data.values())
    fig, axes = plt.subplots(rows, columns, figsize=(max(4.5, 0.38 * widest + 1.2) * columns,
                                                     4.4 * rows), squeeze=False)
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
        ax.set_title(world + (" (time budgets)" if timed else ""))
        ax.grid(True, axis="y", which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_to_solve.png"), dpi=100)
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
