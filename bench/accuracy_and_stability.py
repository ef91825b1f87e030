"""Every figure of how exact graphplan is, in one command: the work-precision table and plot of every
fixture (accuracy.py) and the stability report of every extreme scene (stability.py).

    python bench/accuracy_and_stability.py     # bench/results/accuracy.{md,csv,svg}, stability.md
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import accuracy
import stability

if __name__ == "__main__":
    accuracy.main()
    reports = stability.main()
    sys.exit(0 if all(report.passed for report in reports) else 1)
