"""The sampling planners compared over seeds on one world: how often each finds a path within
the same number of iterations, and how long the paths are, printed and plotted.

    python3 sampling_comparison.py [WORLD.json] [SEEDS] [ITERATIONS] [OUT.png]
"""
import os
import statistics
import sys

import matplotlib.pyplot as plt

import polyplan

here = os.path.dirname(os.path.abspath(__file__))
world_file = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "worlds", "office.json")
seeds = int(sys.argv[2]) if len(sys.argv) > 2 else 20
iterations = int(sys.argv[3]) if len(sys.argv) > 3 else 2000
picture = sys.argv[4] if len(sys.argv) > 4 else "sampling_comparison.png"

world = polyplan.read_world(world_file)
space = polyplan.planner("visibility", world).space  # a translating robot's planners, not an arm's
names = [info.name for info in polyplan.planners() if info.space == space and info.name in ("prm", "lazyprm", "rrt", "rrtstar", "rrtconnect")]
shortest = polyplan.plan(world, planner="visibility")[0].length  # the exact optimum, for scale

print(f"{world_file}: {seeds} seeds, {iterations} iterations each; shortest path {shortest:.3f}\n")
print(f"{'planner':<12} {'solved':>8} {'mean length':>12} {'/ shortest':>11}")
results = {}
for name in names:
    plans = [polyplan.planner(name, world, seed=seed, iterations=iterations, time=60).plan(record=False)
             for seed in range(1, seeds + 1)]
    lengths = [r.length for r in plans if r.found]
    results[name] = lengths
    mean = statistics.mean(lengths) if lengths else float("nan")
    print(f"{name:<12} {len(lengths):>4}/{seeds:<3} {mean:>12.3f} {mean / shortest:>11.3f}")

fig, (rate, length) = plt.subplots(1, 2, figsize=(12, 4.5))
rate.bar(names, [100 * len(results[n]) / seeds for n in names], color="tab:blue")
rate.set_ylabel("solved (%)")
rate.set_ylim(0, 105)
rate.set_title(f"success over {seeds} seeds, {iterations} iterations")
length.boxplot([results[n] or [float("nan")] for n in names], labels=names)
length.axhline(shortest, color="tab:red", ls="--", label=f"shortest {shortest:.2f}")
length.set_ylabel("path length")
length.legend()
length.set_title(os.path.basename(world_file))
fig.savefig(picture, dpi=90, bbox_inches="tight")
print(f"\npicture: {picture}")
