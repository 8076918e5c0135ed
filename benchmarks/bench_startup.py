"""Start-up of terminal commands against ``python -c "import numpy"``: ratios in one run.

Each command runs as a user runs it (a fresh process of the installed ``bearingload`` script,
output discarded), interleaved with the baseline, best of ``--runs`` wall times each. The numbers
are ratios to the baseline measured in the same run, never absolute limits.

    python benchmarks/bench_startup.py [--runs 10]
"""

from __future__ import annotations

import argparse
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
    "solve 306 (catalogue)": [str(BIN / "bearingload"), "solve", "306", "--load", "300kgf"],
    "table k": [str(BIN / "bearingload"), "table", "k"],
}  # fmt: skip


def best_times(runs: int) -> dict[str, float]:
    """Best wall time [s] of each command over ``runs`` interleaved rounds."""
    best = dict.fromkeys(COMMANDS, float("inf"))
    for _ in range(runs):
        for name, argv in COMMANDS.items():
            start = time.perf_counter()
            subprocess.run(argv, stdout=subprocess.DEVNULL, check=True)
            best[name] = min(best[name], time.perf_counter() - start)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=10)
    runs = parser.parse_args().runs
    best = best_times(runs)
    base = best['python -c "import numpy"']
    print(f"start-up, best of {runs} runs each (ratio to python -c 'import numpy')")
    for name, seconds in best.items():
        print(f"  {name:26s} {seconds * 1e3:7.1f} ms  x{seconds / base:.2f}")


if __name__ == "__main__":
    main()
