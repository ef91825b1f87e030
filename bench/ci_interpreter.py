"""The processor time of the same work under each CPython that can run the project: which one CI should use.

    python bench/ci_interpreter.py [--python PATH ...] [--rounds N] [--tests TEST_FILE ...]

CI makes its virtual environment with one interpreter, and the suite's time is nearly all the package's own Python
(bench/suite_budget.py): how fast the interpreter itself is counts as much as any change to the package.  This
machine has two builds of CPython 3.11, pyenv's first on the PATH and Debian's in /usr/bin.  Each interpreter given
(by default both) gets a fresh virtual environment with the project installed as CI installs it, then runs every
fixture's `graphplan run`, each in a new process, the interpreters taking turns scene by scene so that the load of
a shared machine falls on both alike; with ``--tests``, those test files too, as the README's test command runs
them (its workers and all).  The figure is the processor time (user and system) each took, summed, and its ratio to
the first interpreter's.

Results go to bench/results/ci_interpreter.json and ci_interpreter.md.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from cold_run import timed, write_results

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
SCENES = sorted((ROOT / "fixtures").glob("*.toml"))


def candidates() -> list[str]:
    """The interpreters compared by default: the first python3 on the PATH, and the distribution's."""
    found = [shutil.which("python3") or sys.executable, "/usr/bin/python3"]
    return [path for k, path in enumerate(found) if Path(path).exists() and path not in found[:k]]


def described(python: str) -> str:
    """The interpreter's version, and whether it calls libpython as a shared library (pyenv's --enable-shared build)
    or has it linked in (Debian's python3)."""
    executable, version = subprocess.run(
        [python, "-c", "import platform, sys; print(sys.executable); print(platform.python_version())"],
        check=True, capture_output=True, text=True).stdout.split()
    linked = subprocess.run(["ldd", str(Path(executable).resolve())], check=False, capture_output=True,
                            text=True).stdout
    return f"{version}, {'libpython shared' if 'libpython' in linked else 'libpython linked in'}"


def environment_of(python: str, scratch: Path, index: int) -> Path:
    """A new virtual environment of ``python`` with the project installed as CI installs it; its interpreter."""
    venv = scratch / f"venv-{index}"
    subprocess.run([python, "-m", "venv", str(venv)], check=True)
    interpreter = venv / "bin" / "python3"
    subprocess.run([str(interpreter), "-m", "pip", "install", "--quiet", f"{ROOT}[test]"], check=True)
    return interpreter


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--python", action="append", help="an interpreter to compare (repeat; default: "
                                                          "python3 on the PATH and /usr/bin/python3)")
    parser.add_argument("--rounds", type=int, default=2, help="how many times each scene is run by each")
    parser.add_argument("--tests", nargs="*", default=[], help="test files run too, as the README runs the suite")
    arguments = parser.parse_args()
    pythons = arguments.python or candidates()
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        interpreters = [environment_of(python, scratch, k) for k, python in enumerate(pythons)]
        # Out of the source tree: `python -m` would put its graphplan first, not the one each environment holds.
        work = scratch / "work"
        work.mkdir()
        environment = dict(os.environ)
        runs = {python: 0.0 for python in pythons}
        for _ in range(arguments.rounds):
            for scene in SCENES:
                for python, interpreter in zip(pythons, interpreters, strict=True):
                    command = [str(interpreter), "-m", "graphplan", "run", str(scene), "--out", str(work / "out")]
                    runs[python] += timed(command, environment, work)[1]
        tests = {python: 0.0 for python in pythons}
        if arguments.tests:
            for python, interpreter in zip(pythons, interpreters, strict=True):
                command = [str(interpreter), "-m", "pytest", "-p", "no:cacheprovider",
                           *(str(ROOT / name) for name in arguments.tests)]
                tests[python] = timed(command, environment, ROOT)[1]
    first = pythons[0]
    result = {"rounds": arguments.rounds, "scenes": [scene.name for scene in SCENES], "tests": arguments.tests,
              "interpreters": [{"python": python, "build": described(python), "runs_cpu_s": round(runs[python], 2),
                                "runs_ratio": round(runs[python] / runs[first], 3),
                                **({"tests_cpu_s": round(tests[python], 2),
                                    "tests_ratio": round(tests[python] / tests[first], 3)} if arguments.tests else {})}
                               for python in pythons]}
    lines = ["# The same work under each interpreter", "",
             f"`python bench/ci_interpreter.py`: every fixture's `graphplan run` ({len(SCENES)} scenes, "
             f"{arguments.rounds} rounds, each in a new process, the interpreters taking turns)"
             + (f", and {len(arguments.tests)} test files as the README runs the suite" if arguments.tests else "")
             + ". Processor time, user and system, summed; the ratio is to the first interpreter's.", "",
             "| interpreter | build | runs, CPU s | ratio |" + (" tests, CPU s | ratio |" if arguments.tests else ""),
             "|---|---|---:|---:|" + ("---:|---:|" if arguments.tests else "")]
    for entry in result["interpreters"]:
        row = f"| `{entry['python']}` | {entry['build']} | {entry['runs_cpu_s']:.1f} | {entry['runs_ratio']:.3f} |"
        if arguments.tests:
            row += f" {entry['tests_cpu_s']:.1f} | {entry['tests_ratio']:.3f} |"
        lines.append(row)
    write_results("ci_interpreter", result, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
