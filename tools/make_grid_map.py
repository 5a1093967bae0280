#!/usr/bin/env python3
"""Writes a seeded grid map in the Moving AI format, for trying `acdplan env` on grid worlds.

Kinds: `noise` (each cell blocked with probability --blocked, as the speckle of a SLAM map),
`maze` (a perfect maze of corridors one cell wide, by randomized depth-first search: WIDTH and
HEIGHT are rounded down to odd numbers), `warehouse` (rows of shelves 10 x 2 cells with aisles
of 2 and a free border of 5, as many as fit, as in the warehouse maps of multi-agent path
finding benchmarks; no randomness). Python's `random` draws the same numbers from a seed
on every platform, so a seed names a map.

Usage: make_grid_map.py noise|maze|warehouse WIDTH HEIGHT OUT.map [--seed 1] [--blocked 0.2]
Example: make_grid_map.py noise 256 256 noise256.map && build/tools/acdplan env noise256.map
"""

import argparse
import random


def noise(width, height, blocked, rng):
    return [[rng.random() < blocked for _ in range(width)] for _ in range(height)]


def maze(width, height, rng):
    cols, rows = (width - 1) // 2, (height - 1) // 2
    if cols < 1 or rows < 1:
        raise SystemExit("make_grid_map.py: a maze needs WIDTH and HEIGHT of at least 3")
    grid = [[True] * (2 * cols + 1) for _ in range(2 * rows + 1)]
    seen = [[False] * cols for _ in range(rows)]
    stack = [(0, 0)]
    seen[0][0] = True
    grid[1][1] = False
    while stack:  # Carve from the newest cell with an unseen neighbour (no recursion limit).
        x, y = stack[-1]
        steps = [(x + dx, y + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))
                 if 0 <= x + dx < cols and 0 <= y + dy < rows and not seen[y + dy][x + dx]]
        if not steps:
            stack.pop()
            continue
        nx, ny = rng.choice(steps)
        seen[ny][nx] = True
        grid[2 * ny + 1][2 * nx + 1] = False
        grid[y + ny + 1][x + nx + 1] = False
        stack.append((nx, ny))
    return grid


def warehouse(width, height):
    length, depth, aisle, border = 10, 2, 2, 5
    grid = [[False] * width for _ in range(height)]
    for y0 in range(border, height - border - depth + 1, depth + aisle):
        for x0 in range(border, width - border - length + 1, length + aisle):
            for y in range(y0, y0 + depth):
                grid[y][x0:x0 + length] = [True] * length
    return grid


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kind", choices=["noise", "maze", "warehouse"])
    parser.add_argument("width", type=int)
    parser.add_argument("height", type=int)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--blocked", type=float, default=0.2, help="noise: share of cells blocked")
    args = parser.parse_args()
    if args.width < 1 or args.height < 1:
        raise SystemExit("make_grid_map.py: WIDTH and HEIGHT must be at least 1")
    rng = random.Random(args.seed)
    if args.kind == "noise":
        grid = noise(args.width, args.height, args.blocked, rng)
    elif args.kind == "maze":
        grid = maze(args.width, args.height, rng)
    else:
        grid = warehouse(args.width, args.height)
    with open(args.out, "w") as out:
        out.write("type octile\nheight %d\nwidth %d\nmap\n" % (len(grid), len(grid[0])))
        for row in grid:
            out.write("".join("@" if cell else "." for cell in row) + "\n")


if __name__ == "__main__":
    main()
