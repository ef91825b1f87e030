"""What drawing the force analysis larger on the course sheets costs: the sheets' run with the search for room as it
is, with no search, and with every way tried, largest first, until one packs.

    python bench/course_sheets.py [--sheet SHEET ...] [--locale LOCALE ...]

A course sheet with room for it draws a force sheet's groups cut free and polygons a standard step or more larger
(`render/force_sheet_choice.py` `larger_where_room`): it tries ways of `LARGER_FORCE_STEPS` (`first_fitting`: from
`PROBE_STEPS`, then the middle of those a failure or a fit leaves), each a force sheet laid out afresh with its
labels placed and the sheets packed again.  For every fixture and every starter, in each locale, on the scene's own
sheet (and each `--sheet` given), a fresh interpreter runs `graphplan run --only sheets` (`run.run`) after an
untimed run that loads the modules, each run with the label placements remembered by the run before forgotten: as
it is; with `LARGER_FORCE_STEPS` empty (no search: the record's scales); and with `first_fitting` trying every way
in order, largest first, until one packs (the first search, with none of its ways ruled out by another's).  Each
run gives its processor time, the time spent in `larger_where_room` alone, the sheets written, and how many force sheets
it drew larger; the two searches must draw the same ones larger.

Times are processor times (the machine is shared), compared as ratios within one interpreter.  Results go to
bench/results/course_sheets.json and course_sheets.md.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from cold_run import write_results
from sheet_cuts import STARTERS, in_fresh_interpreter, refused, scene_of

WAYS = ("as it is", "no search", "largest first")


def one(name: str, locale: str, sheet: str | None) -> dict:
    """The three runs of one scene in one locale on one sheet (``None``: the scene's own), in this interpreter."""
    from graphplan import run as run_module
    from graphplan.memo import RecentMemo
    from graphplan.render import force_marks, labels
    from graphplan.render import force_sheet_choice as choice_module
    from graphplan.render import sheet as sheet_module

    own_search, own_first = choice_module.larger_where_room, choice_module.first_fitting
    usual = choice_module.LARGER_FORCE_STEPS
    spent = {"search_s": 0.0, "larger": 0}

    def timed_search(parts, *rest, **options):
        start = time.process_time()
        chosen, pages = own_search(parts, *rest, **options)
        spent["search_s"] += time.process_time() - start
        spent["larger"] += sum(new is not old for new, old in zip(chosen, parts, strict=True))
        return chosen, pages

    def every_way(ways, taken):
        return next((tried for tried in map(taken, ways) if tried is not None), None)

    def timed_run(steps, first, scratch: Path) -> dict:
        choice_module.LARGER_FORCE_STEPS, choice_module.first_fitting = steps, first
        spent.update(search_s=0.0, larger=0)
        # Placements remembered from the run before would make a way laid out there free here.
        labels._placements, force_marks._grown_unions = RecentMemo(), RecentMemo()
        scratch.mkdir(parents=True)
        scene = scene_of(name, scratch)
        out = scratch / "out"
        start = time.process_time()
        run_module.run(scene, out, only=["sheets"], locale=locale, sheet=sheet)
        used = time.process_time() - start
        return {"cpu_s": used, "search_s": spent["search_s"], "larger": spent["larger"],
                "sheets": len(list(out.glob("sheet_*.svg")))}

    # Timed where the course sheets ask for it and where the choice for the order does.
    sheet_module.larger_where_room = choice_module.larger_where_room = timed_search
    try:
        with tempfile.TemporaryDirectory() as scratch_name:
            scratch = Path(scratch_name)
            timed_run(usual, own_first, scratch / "warm")
            runs = {"as it is": timed_run(usual, own_first, scratch / "a"),
                    "no search": timed_run((), own_first, scratch / "b"),
                    "largest first": timed_run(usual, every_way, scratch / "c")}
    finally:
        sheet_module.larger_where_room = choice_module.larger_where_room = own_search
        choice_module.first_fitting = own_first
        choice_module.LARGER_FORCE_STEPS = usual
    return {"scene": name, "locale": locale, "sheet": sheet or "scene's", "runs": runs}


def measured(name: str, locale: str, sheet: str | None) -> dict:
    """:func:`one` in a fresh interpreter, so that no scene's layouts or caches reach another's."""
    return in_fresh_interpreter(Path(__file__), name, locale, sheet)


def table(rows: list[dict]) -> str:
    lines = [("| scene | locale | sheet | sheets (as it is / no search / largest first) | force sheets drawn larger | "
              "run s (as it is / no search / largest first) | search's share of the run (as it is / largest first) "
              "|"),
             "|---|---|---|---|---|---|---|"]
    for row in rows:
        if "error" in row:
            lines.append(refused(row, 3))
            continue
        runs = row["runs"]
        lines.append(
            f"| {row['scene']} | {row['locale']} | {row['sheet']} | "
            + " / ".join(str(runs[way]["sheets"]) for way in WAYS) + f" | {runs['as it is']['larger']} | "
            + " / ".join(f"{runs[way]['cpu_s']:.2f}" for way in WAYS) + " | "
            + " / ".join(f"{100 * runs[way]['search_s'] / runs[way]['cpu_s']:.1f} %"
                         for way in ("as it is", "largest first")) + " |")
    return "\n".join(lines)


def summarised(rows: list[dict]) -> None:
    """The rows, with what they add up to, written as bench/results/course_sheets.json and .md."""
    measured_rows = [row for row in rows if "runs" in row]
    refused = len(rows) - len(measured_rows)
    with_search = [row for row in measured_rows if row["runs"]["as it is"]["search_s"] > 0]

    def median_ratio(way: str) -> float:
        return statistics.median(row["runs"][way]["cpu_s"] / row["runs"]["no search"]["cpu_s"]
                                 for row in with_search) if with_search else float("nan")

    more_sheets = sum(row["runs"]["as it is"]["sheets"] > row["runs"]["no search"]["sheets"] for row in measured_rows)
    larger = sum(row["runs"]["as it is"]["larger"] > 0 for row in measured_rows)
    shares = [row["runs"]["as it is"]["search_s"] / row["runs"]["as it is"]["cpu_s"] for row in with_search]
    differ = sum(row["runs"]["as it is"]["larger"] != row["runs"]["largest first"]["larger"] for row in with_search)
    result = {"rows": rows, "measured": len(measured_rows), "refused": refused, "with_search": len(with_search),
              "drawn_larger": larger, "more_sheets_than_no_search": more_sheets,
              "median_run_ratio_to_no_search": {way: median_ratio(way) for way in ("as it is", "largest first")},
              "search_share_of_run": {"median": statistics.median(shares) if shares else 0.0,
                                      "most": max(shares, default=0.0)},
              "larger_count_differs_from_largest_first": differ}
    ratios = result["median_run_ratio_to_no_search"]
    share = result["search_share_of_run"]
    markdown = (
        "# Course sheets: what drawing the force analysis larger where there is room costs\n\n"
        f"{len(rows)} runs (every fixture and starter, in each locale and on each sheet measured), "
        f"{len(measured_rows)} measured, {refused} refused (a drawing no such sheet holds). The search ran in "
        f"{len(with_search)} of them and drew a force sheet larger in **{larger}**; it took more sheets than no "
        f"search in **{more_sheets}** runs (it must take none). The sheets' run with the search as it is took a "
        f"median **{ratios['as it is']:.3f}** of the run without it, the search from the largest way down "
        f"{ratios['largest first']:.3f}; the search alone a median {100 * share['median']:.1f} % of the run, at "
        f"most {100 * share['most']:.1f} %. The two searches drew a different number of force sheets larger in "
        f"{differ} runs.\n\n"
        + table(rows) + "\n\n"
        "Run s: the processor seconds of `run.run(..., only=['sheets'])` after a run that loaded the modules, in a "
        "fresh interpreter per scene. Search's share: the processor time spent in `force_sheet_choice.larger_where_room` (each way "
        "laid out, labelled and packed) over the run's.\n"
        "Regenerate with `python bench/course_sheets.py --sheet A1 --sheet A3`.\n")
    write_results("course_sheets", result, markdown)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sheet", action="append", default=[], help="also measure on this sheet (A1, A3, ...)")
    parser.add_argument("--locale", action="append", default=[], help="measure in this locale (default: en)")
    parser.add_argument("--one", nargs=2, metavar=("SCENE", "LOCALE"), help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.one:
        sheet = arguments.sheet[0] if arguments.sheet else None
        print(json.dumps(one(*arguments.one, sheet)))
        return
    names = [str(path.relative_to(ROOT)) for path in sorted((ROOT / "fixtures").glob("*.toml"))]
    names += [f"new:{kind}" for kind in STARTERS]
    rows = []
    for sheet in (None, *arguments.sheet):
        for name in names:
            for locale in arguments.locale or ["en"]:
                rows.append(measured(name, locale, sheet))
                print(json.dumps(rows[-1]), flush=True)
    summarised(rows)


if __name__ == "__main__":
    main()
