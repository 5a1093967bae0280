#!/usr/bin/env python3
"""Plots the JSON written by `acd_bench --json` (tools/acd_bench.md).

Three panels, polygons ordered by vertex count:
  top:    components per method at tau_rel = 0 (our four measures and CGAL's partitions), log,
  middle: the same divided by the fewest any method reached on that polygon (1 = best),
  bottom: median time per method (same runs), log scale.

Usage: plot_acd_bench.py acd_bench.json acd_bench.png [--tau-rel 0]
"""

import argparse
import json
import math
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_acd_bench.py: needs matplotlib (Debian: apt install python3-matplotlib, then "
             "run with /usr/bin/python3 if python3 is another interpreter)")

matplotlib.use("Agg")  # No display needed.
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["acd-sl", "acd-sp", "acd-h1", "acd-h2", "cgal-approx", "cgal-greene", "cgal-optimal"]
COLORS = {
    "acd-sl": "#1f77b4",
    "acd-sp": "#d62728",
    "acd-h1": "#ff7f0e",
    "acd-h2": "#9467bd",
    "cgal-approx": "#2ca02c",
    "cgal-greene": "#8c564b",
    "cgal-optimal": "#7f7f7f",
}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="rows written by acd_bench --json")
    parser.add_argument("png", help="picture to write")
    parser.add_argument("--tau-rel", type=float, default=0.0,
                        help="tau_rel of our rows to plot (CGAL rows have no tau); default 0")
    args = parser.parse_args(argv)

    with open(args.json) as f:
        rows = json.load(f)

    # (polygon, method) -> row; ours at the chosen tau_rel, CGAL's (tau_rel null) always.
    cells = {}
    vertices = {}
    for row in rows:
        ours = row["tau_rel"] is not None
        if ours and not math.isclose(row["tau_rel"], args.tau_rel, abs_tol=1e-12):
            continue
        cells[(row["polygon"], row["method"])] = row
        vertices[row["polygon"]] = row["vertices"]
    if not vertices:
        sys.exit(f"plot_acd_bench.py: no rows at tau_rel {args.tau_rel} in {args.json}")
    polygons = sorted(vertices, key=lambda p: (vertices[p], p))
    methods = [m for m in METHODS if any((p, m) in cells for p in polygons)]

    fewest = {}
    for (polygon, _), row in cells.items():
        if row["components"] is not None:
            fewest[polygon] = min(fewest.get(polygon, row["components"]), row["components"])

    width = 0.8 / len(methods)
    fig, (ax_count, ax_ratio, ax_time) = plt.subplots(
        3, 1, figsize=(max(10, 0.55 * len(polygons) + 3), 12), sharex=True)
    for k, method in enumerate(methods):
        xs, counts, ratios, times = [], [], [], []
        for i, polygon in enumerate(polygons):
            row = cells.get((polygon, method))
            if row is None or row["components"] is None:
                continue  # n/a (holes, n too large) or failed: no bar.
            xs.append(i - 0.4 + (k + 0.5) * width)
            counts.append(row["components"])
            ratios.append(row["components"] / fewest[polygon])
            times.append(max(row["median_ms"], 1e-4))
        ax_count.bar(xs, counts, width, label=method, color=COLORS.get(method))
        ax_ratio.bar(xs, ratios, width, label=method, color=COLORS.get(method))
        ax_time.bar(xs, times, width, label=method, color=COLORS.get(method))

    ax_count.set_yscale("log")
    ax_count.set_ylabel("components")
    ax_count.set_title(f"components at tau_rel = {args.tau_rel:g} (ours) and CGAL's convex "
                       "partitions; missing bar = n/a (holes, n > 150 for optimal) or failed")
    ax_count.legend(ncol=len(methods), fontsize="small", loc="upper left")
    ax_count.grid(axis="y", which="both", alpha=0.3)

    ax_ratio.axhline(1.3, color="black", linewidth=0.8, linestyle="--")
    ax_ratio.set_ylim(bottom=0.9)
    ax_ratio.set_ylabel("components / fewest")
    ax_ratio.set_title("components relative to the fewest on each polygon (dashed: 1.3)")
    ax_ratio.grid(axis="y", alpha=0.3)

    ax_time.set_yscale("log")
    ax_time.set_ylabel("median time [ms]")
    ax_time.set_title("median wall time per run")
    ax_time.grid(axis="y", which="both", alpha=0.3)
    ax_time.set_xticks(range(len(polygons)))
    ax_time.set_xticklabels([f"{p} ({vertices[p]})" for p in polygons], rotation=60,
                            ha="right", fontsize="small")

    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"plot_acd_bench.py: wrote {args.png}")


if __name__ == "__main__":
    main(sys.argv[1:])
