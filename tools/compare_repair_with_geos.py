#!/usr/bin/env python3
"""Compares `--repair` (RepairPolygon) with GEOS's make_valid on random invalid polygons.

Generates self-crossing polygons of five kinds (rings in random vertex order; star polygons
with holes that cross the outer ring and each other; stars folded over themselves; small
integer grids, with collinear overlaps and repeated points; stars with out-and-back spikes),
writes them as WKT to `repair_areas --check` (built with the tools: build/tools/repair_areas)
and compares each repaired area with the polygonal part of shapely's make_valid. Every input
whose areas differ by more than 1e-9 (relative) is listed with whether two of its ring edges
overlap; every repaired result is also decomposed and checked. --general-position leaves out
the grids and spikes, whose edges overlap.

Usage: compare_repair_with_geos.py REPAIR_AREAS [--seed 1] [--count 2500] [--general-position]
                                   [--offset X Y] [--scale S]
Needs shapely (Debian: apt install python3-shapely).
"""

import argparse
import math
import random
import subprocess
import sys

try:
    from shapely.geometry import LineString, Polygon
    from shapely.validation import make_valid
except ImportError:
    sys.exit("compare_repair_with_geos.py: needs shapely (Debian: apt install python3-shapely)")


def polygonal_area(geometry):
    if geometry.is_empty:
        return 0.0
    if geometry.geom_type == "Polygon":
        return geometry.area
    if geometry.geom_type in ("MultiPolygon", "GeometryCollection"):
        return sum(polygonal_area(part) for part in geometry.geoms)
    return 0.0


def star(rng, n, cx, cy, radius, jitter, grid):
    points = []
    for k in range(n):
        angle = 2 * math.pi * k / n + rng.uniform(-jitter, jitter)
        r = radius * rng.uniform(0.3, 1.0)
        x, y = cx + r * math.cos(angle), cy + r * math.sin(angle)
        points.append((round(x), round(y)) if grid else (x, y))
    return points


def scattered(rng, n, low, high, grid):
    points = [(rng.uniform(low, high), rng.uniform(low, high)) for _ in range(n)]
    return [(round(x), round(y)) for x, y in points] if grid else points


def random_polygon(rng, kind, general_position):
    grid = not general_position and rng.random() < 0.5
    if kind == 0:  # Random vertex order: many self-crossings.
        return scattered(rng, rng.randint(4, 12), 0, 10, grid), []
    if kind == 1:  # A star whose holes may cross it and each other.
        outer = star(rng, rng.randint(5, 20), 0, 0, 10, 0.5, grid)
        holes = [star(rng, rng.randint(3, 8), rng.uniform(-8, 8), rng.uniform(-8, 8),
                      rng.uniform(1, 6), 0.4, grid) for _ in range(rng.randint(1, 4))]
        return outer, holes
    if kind == 2:  # Angles jittered enough to fold the star over itself.
        return star(rng, rng.randint(5, 25), 0, 0, 10, 2.5, grid), []
    if kind == 3:  # A small grid: collinear overlaps, touching, repeated points.
        holes = [scattered(rng, rng.randint(3, 5), 0, 4, True) for _ in range(rng.randint(0, 2))]
        return scattered(rng, rng.randint(4, 9), 0, 4, True), holes
    outer = star(rng, rng.randint(6, 14), 0, 0, 10, 0.2, grid)  # Out-and-back spikes.
    for _ in range(rng.randint(1, 3)):
        i = rng.randrange(len(outer))
        p = outer[i]
        q = (p[0] + rng.uniform(-5, 5), p[1] + rng.uniform(-5, 5))
        outer[i + 1:i + 1] = [(round(q[0]), round(q[1])) if grid else q, p]
    return outer, []


def wkt(rings):
    def ring(points):
        return "(" + ", ".join("%.17g %.17g" % p for p in points + [points[0]]) + ")"
    return "POLYGON(" + ", ".join(ring(r) for r in rings) + ")"


def edges_overlap(rings):
    edges = [LineString([r[i], r[(i + 1) % len(r)]]) for r in rings for i in range(len(r))
             if r[i] != r[(i + 1) % len(r)]]
    return any(edges[i].intersection(edges[j]).length > 0
               for i in range(len(edges)) for j in range(i + 1, len(edges)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("repair_areas")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=2500)
    parser.add_argument("--general-position", action="store_true")
    parser.add_argument("--offset", type=float, nargs=2, default=(0.0, 0.0))
    parser.add_argument("--scale", type=float, default=1.0)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    kinds = [0, 1, 2] if args.general_position else [0, 1, 2, 3, 4]
    cases = []
    for i in range(args.count):
        outer, holes = random_polygon(rng, kinds[i % len(kinds)], args.general_position)
        rings = [[(args.offset[0] + args.scale * x, args.offset[1] + args.scale * y)
                  for x, y in ring] for ring in [outer] + holes]
        cases.append(rings)
    lines = subprocess.run([args.repair_areas, "--check"], check=True, capture_output=True,
                           text=True, input="\n".join(wkt(r) for r in cases) + "\n").stdout
    counts = {"equal": 0, "differ": 0, "differ without overlapping edges": 0, "refused": 0,
              "check failed": 0}
    for rings, line in zip(cases, lines.splitlines()):
        if line.startswith("error"):
            counts["refused"] += 1
            print("refused:", line[6:], "\n ", wkt(rings))
            continue
        _, area, _, verdict = line.split(" ", 3)
        if verdict.startswith("check-failed"):
            counts["check failed"] += 1
            print(verdict, "\n ", wkt(rings))
        geos = polygonal_area(make_valid(Polygon(rings[0], rings[1:])))
        if abs(float(area) - geos) <= 1e-9 * max(1.0, abs(geos)):
            counts["equal"] += 1
            continue
        counts["differ"] += 1
        overlap = edges_overlap(rings)
        if not overlap:
            counts["differ without overlapping edges"] += 1
        print("differ: ours %.12g, GEOS %.12g%s\n  %s" % (
            float(area), geos, "" if overlap else " (no overlapping edges)", wkt(rings)))
    print(", ".join("%s %d" % item for item in counts.items()))
    return 1 if counts["differ without overlapping edges"] or counts["check failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
