"""Start-up of terminal commands against ``python -c "import numpy"``: ratios in one run.

Each command runs as a user runs it (a fresh process of the installed ``bearingload`` script,
output discarded), interleaved with the baseline: one round runs the baseline and then every
command once. Printed per command: the best wall time over the rounds, its ratio to the best
baseline, and the medians over the rounds of the paired ratios (command / the baseline of the
same round) of the wall time and of the CPU time (user + system of the process), which a busy
machine disturbs least. The numbers are ratios to the baseline measured in the same run, never
absolute limits.

    python benchmarks/bench_startup.py [--runs 15]
"""

from __future__ import annotations

import argparse
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

BIN = Path(sys.executable).parent
COMMANDS = {
    'python -c "import numpy"': [sys.executable, "-c", "import numpy"],
    "solve (z, K given)": [
        str(BIN / "bearingload"), "solve", "--balls", "8", "--load", "300kgf",
        "--stiffness", "4700kgf/mm^1.5", "--clearance", "20um",
    ],
    "solve 306 -F 1kN": [str(BIN / "bearingload"), "solve", "306", "-F", "1kN"],
    "solve 6205 -F 1kN --speed 3000 (ball dynamics)": [
        str(BIN / "bearingload"), "solve", "6205", "-F", "1kN", "--speed", "3000",
    ],
    "table k": [str(BIN / "bearingload"), "table", "k"],
}  # fmt: skip


def _cpu() -> float:
    """CPU seconds (user + system) of the finished child processes so far."""
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def paired_times(runs: int) -> dict[str, list[tuple[float, float]]]:
    """(wall, CPU) seconds of each command over ``runs`` interleaved rounds, one per round."""
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in COMMANDS}
    for _ in range(runs):
        for name, argv in COMMANDS.items():
            cpu, start = _cpu(), time.perf_counter()
            subprocess.run(argv, stdout=subprocess.DEVNULL, check=True)
            times[name].append((time.perf_counter() - start, _cpu() - cpu))
    return times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    runs = parser.parse_args().runs
    times = paired_times(runs)
    base = times['python -c "import numpy"']
    print(f"start-up, {runs} interleaved rounds (ratios to python -c 'import numpy')")
    print(f"  {'':26s} {'wall':>9s}  {'wall':>6s}  {'median of paired ratios':>23s}")
    print(f"  {'command':26s} {'best':>9s}  {'ratio':>6s}  {'wall':>11s}  {'CPU':>9s}")
    for name, pairs in times.items():
        wall = min(w for w, _ in pairs)
        ratio = {k: statistics.median(t[k] / b[k] for t, b in zip(pairs, base, strict=True))
                 for k in (0, 1)}  # fmt: skip
        print(f"  {name:26s} {wall * 1e3:6.1f} ms  x{wall / min(w for w, _ in base):5.2f}"
              f"  x{ratio[0]:10.2f}  x{ratio[1]:8.2f}")  # fmt: skip


if __name__ == "__main__":
    main()
