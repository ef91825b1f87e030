"""The command line: ``graphplan run SCENE``, ``graphplan check SCENE``.

Every :class:`~graphplan.errors.GraphplanError` becomes one line on stderr
and exit status 2, never a traceback.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from .errors import GraphplanError

EXAMPLES = """\
examples:
  graphplan run fixtures/ratchet_crank_rocker.toml              writes output/ratchet_crank_rocker/
  graphplan run fixtures/ratchet_crank_rocker.toml --out report
  graphplan check fixtures/ratchet_crank_rocker.toml            validates and prints the structure formula
"""


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="graphplan",
        description="The plan method of the theory of machines, from one scene file.",
        epilog=EXAMPLES, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    run = commands.add_parser("run", help="analyse a scene and write results.json and the drawings",
                              epilog=EXAMPLES, formatter_class=argparse.RawDescriptionHelpFormatter)
    run.add_argument("scene", type=Path, help="the scene file (TOML)")
    run.add_argument("--out", type=Path, default=None,
                     help="output folder (default: output/<scene file name>)")
    run.add_argument("--figures", action="store_true",
                     help="also draw the report figures with matplotlib (the balancing load over the cycle)")
    check = commands.add_parser("check", help="validate a scene and print its structure formula")
    check.add_argument("scene", type=Path, help="the scene file (TOML)")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    arguments = _parser().parse_args(argv)
    try:
        if arguments.command == "check":
            return _check(arguments.scene)
        return _run(arguments.scene, arguments.out, arguments.figures)
    except GraphplanError as error:
        print(f"graphplan: error: {error}", file=sys.stderr)
        return 2


def _check(path: Path) -> int:
    from .mechanism import build
    from .positions import make_positions
    from .scene import load

    mechanism = build(load(path))
    make_positions(mechanism)
    n, p5, w = mechanism.degrees_of_freedom
    print(f"{path}: ok")
    print(f"structure: {mechanism.structure}")
    print(f"W = 3·{n} − 2·{p5} = {w}")
    return 0


def _run(path: Path, out: Path | None, figures: bool = False) -> int:
    from .analysis import analyse
    from .output import write_folder
    from .render.drawings import positions_svg
    from .report.results import dumps, results
    from .scene import load

    scene = load(path)
    analysis = analyse(scene)
    files = {"results.json": dumps(results(analysis)), "positions.svg": positions_svg(analysis)}
    if analysis.plans:
        from .render.drawings import forces_svg, plan_svg
        from .report.tables import csv_text, markdown

        for plan in analysis.plans:
            files[f"plan_{plan.number}.svg"] = plan_svg(analysis, plan.index, plan.velocity, plan.acceleration)
            if plan.forces is not None:
                files[f"forces_{plan.number}.svg"] = forces_svg(analysis, plan)

        files["errors.md"] = markdown(analysis)
        files["errors.csv"] = csv_text(analysis)
        if any(plan.forces is not None for plan in analysis.plans):
            from .report.forces import markdown as forces_markdown

            files["forces.md"] = forces_markdown(analysis)
    if figures and analysis.equilibrium is not None:
        from .report.figures import balancing_diagram

        files["balancing.svg"] = balancing_diagram(analysis)
    target = out if out is not None else Path("output") / path.stem
    written = write_folder(target, files)
    print(f"{scene.title}")
    print(f"structure: {analysis.mechanism.structure}")
    for warning in analysis.warnings:
        number = int(analysis.positions.numbers[warning.position])
        print(f"warning: position {number}: {warning.detail}")
    for file in written:
        print(f"wrote {file}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
