#!/usr/bin/env python3
"""Plots the JSON written by `acd3d_bench --json` (tools/acd3d_bench.md).

One small panel per mesh that has a volume (a solid as read or after repair): hull volume /
mesh volume against the number of parts (log scale), our decompositions as lines through their
tau_rel settings (solid ACD, surface ACD), the solid ACD capped by max_hulls as a diamond,
V-HACD as one star. Lower left is better; the dotted line is the 1.10 target. Meshes without a volume (open, not repairable) are listed in the title.

Usage: plot_acd3d_bench.py acd3d_bench.json acd3d_bench.png
"""

import argparse
import json
import math
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_acd3d_bench.py: needs matplotlib (Debian: apt install python3-matplotlib, then "
             "run with /usr/bin/python3 if python3 is another interpreter)")

matplotlib.use("Agg")  # No display needed.
import matplotlib.pyplot as plt  # noqa: E402

STYLES = {
    "acd-solid": dict(color="#d62728", marker="o", linestyle="-"),
    "acd-surface": dict(color="#1f77b4", marker="s", linestyle="--"),
    "vhacd": dict(color="#2ca02c", marker="*", linestyle="none", markersize=12),
}
CAPPED_STYLE = dict(color="#d62728", marker="D", linestyle="none", fillstyle="none")


def capped(row):
    """Whether the row is one of ours merged down by a max_hulls cap (its own point, not on the
    line through the tau_rel settings)."""
    return bool(row.get("max_hulls"))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="rows written by acd3d_bench --json")
    parser.add_argument("png", help="picture to write")
    args = parser.parse_args(argv)

    with open(args.json) as f:
        rows = json.load(f)

    meshes, without_volume = [], []
    for row in rows:
        if row["mesh"] in meshes or row["mesh"] in without_volume:
            continue
        (meshes if row["mesh_volume"] else without_volume).append(row["mesh"])
    if not meshes:
        sys.exit(f"plot_acd3d_bench.py: no mesh with a volume in {args.json}")

    columns = min(6, len(meshes))
    lines = math.ceil(len(meshes) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(3.2 * columns, 2.8 * lines + 0.8),
                             squeeze=False)
    for index, mesh in enumerate(meshes):
        ax = axes[index // columns][index % columns]
        for method, style in STYLES.items():
            points = sorted(
                (row["parts"], row["volume_ratio"], row["tau_rel"]) for row in rows
                if row["mesh"] == mesh and row["method"] == method
                and row["volume_ratio"] is not None and not capped(row))
            if not points:
                continue
            ax.plot([p[0] for p in points], [p[1] for p in points], label=method, **style)
            for parts, ratio, tau_rel in points:
                if tau_rel is not None:
                    ax.annotate(f"{tau_rel:g}", (parts, ratio), fontsize="x-small",
                                textcoords="offset points", xytext=(3, 3))
        for row in rows:
            if row["mesh"] == mesh and capped(row) and row["volume_ratio"] is not None:
                ax.plot([row["parts"]], [row["volume_ratio"]],
                        label=f"{row['method']}, max_hulls {row['max_hulls']}", **CAPPED_STYLE)
                ax.annotate(f"{row['tau_rel']:g}", (row["parts"], row["volume_ratio"]),
                            fontsize="x-small", textcoords="offset points", xytext=(3, -9))
        ax.axhline(1.10, color="black", linewidth=0.7, linestyle=":")
        ax.set_xscale("log")
        ax.set_title(mesh, fontsize="small")
        ax.tick_params(labelsize="x-small")
        ax.grid(alpha=0.3, which="both")
        if index % columns == 0:
            ax.set_ylabel("hull vol / vol", fontsize="small")
        if index // columns == lines - 1:
            ax.set_xlabel("parts", fontsize="small")
    for index in range(len(meshes), lines * columns):
        axes[index // columns][index % columns].axis("off")
    handles, labels = [], []
    for ax_line in axes:
        for ax in ax_line:
            for h, l in zip(*ax.get_legend_handles_labels()):
                if l not in labels:
                    handles.append(h)
                    labels.append(l)
    fig.legend(handles, labels, loc="upper right", bbox_to_anchor=(0.99, 0.93), ncol=len(labels),
               fontsize="small")
    title = ("hull volume / mesh volume vs parts (ours: one point per tau_rel, labelled; open "
             "diamond: merged down to max_hulls; dotted: 1.10)")
    if without_volume:
        title += "\nno volume (not plotted): " + ", ".join(without_volume)
    fig.suptitle(title, fontsize="small", x=0.02, y=0.99, ha="left")
    fig.tight_layout(rect=(0, 0, 1, 0.86))
    fig.savefig(args.png, dpi=100)
    print(f"plot_acd3d_bench.py: wrote {args.png}")


if __name__ == "__main__":
    main(sys.argv[1:])
