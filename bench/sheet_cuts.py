"""How many sheets the force sheets take as the run chooses their cuts, against more cuts tried and a search of
every combination of cuts.

    python bench/sheet_cuts.py [--sheet SHEET ...] [--budget SECONDS] [--jobs N]

A force sheet that no sheet holds whole stands in parts; `force_rows.Rows.cuts` offers the first
`force_rows.MOST_CUTS` cuts into as many parts (least paper first), and the run (`render/sheet.py` `course_panels`)
chooses among them and each sheet's rows apart with `force_sheet_choice.CutChoice.fewest(combined=True)`: greedily,
a force sheet after another, each taking the first way that saves a sheet, then, where the sheets' ways make no more
than `MOST_COMBINATIONS` combinations, every combination packed for one that saves a sheet more.  For every fixture
and every starter that has force sheets, in en, ru and zh, on the scene's own sheet (and each `--sheet` given), a
fresh interpreter runs `graphplan run` (`run.run`) three times: as it is, with `MOST_CUTS = 8` and with every cut
(`MOST_CUTS` patched), after an untimed run that loads the modules.  The last run's choice (its cuts, the load
diagrams packed after them) is then made again by the package's own functions: as the run makes it (for its
time: its sheets are those the run laid out), greedy alone (`fewest_sheets_cuts`) over the first 4, the first 8 and
all the cuts (each sheet's cuts cut short), and every combination of each sheet's ways, its cuts and its rows apart,
packed in turn (`CutChoice.pages`), stopped after `--budget` processor seconds (the search then says how far it
came): the fewest sheets of all, and the fewest of those that keep the load diagrams after every force sheet
(`packing.reads_in_order`).  Every figure counts the sheets that `pack` lays the parts on, as the run's sheet_N.svg
of forces are packed: the run's own as it draws them (each drawn larger where the sheets have room, the load
diagrams then put after the force sheets where that costs no sheet, `force_sheet_choice.read_after_forces`), the
others' before any force sheet is drawn larger.

Times are processor times (the machine is shared): each run's own, and each choice's as a fraction of the run
as it is; so ``--jobs`` runs that many interpreters at a time (the 189 runs took 16 processor minutes, 8 minutes
two at a time on two processors).  Results go to bench/results/sheet_cuts.json and sheet_cuts.md.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from cold_run import write_results

LOCALES = ("en", "ru", "zh")
# The starters that make force sheets (`graphplan new KIND`); the flywheel and the rotor have no linkage.
STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")
MORE_CUTS = 8
ALL_CUTS = 10**9
# The choices measured against every combination: the run's own, and the greedy choice alone over 4, 8 and all cuts.
CHOICES = ("run", "greedy/4", f"greedy/{MORE_CUTS}", "greedy/all")
NAMES = {"run": "the run's choice"}
BUDGET_S = 60.0


def scene_of(name: str, scratch: Path):
    """The scene of a fixture (its path) or a starter (``new:KIND``), read from a file as a user's is."""
    import graphplan
    from graphplan.starters import starter

    if name.startswith("new:"):
        path = scratch / f"{name[4:]}.toml"
        path.write_text(starter(name[4:]), encoding="utf-8")
        return graphplan.load(path)
    return graphplan.load(ROOT / name)


def one(name: str, locale: str, sheet: str | None, budget: float) -> dict:
    """The measurement of one scene in one locale on one sheet (``None``: the scene's own), in this interpreter."""
    from graphplan import run as run_module
    from graphplan.errors import SceneError
    from graphplan.memo import RecentMemo
    from graphplan.render import force_rows, packing
    from graphplan.render import sheet as sheet_module
    from graphplan.render.packing import pack, reads_in_order

    def forget_layouts() -> None:
        # Each choice timed as the run makes it, from no layout remembered: the packing remembers the pages it laid
        # out afresh (`packing._LAID_OUT_AFRESH`), and the run and the choices before would have filled it.
        packing._LAID_OUT_AFRESH = RecentMemo()

    own = sheet_module.fewest_sheets_cuts
    own_choice = sheet_module.CutChoice
    calls: list[tuple] = []

    # The run chooses its cuts through a `force_sheet_choice.CutChoice` that `course_panels` makes: each one made
    # there is a call's arguments, the run's own choice the last.
    class Recorded(own_choice):
        def __init__(self, cuts, after, chosen, form, rows_apart=()):
            super().__init__(cuts, after, chosen, form, rows_apart)
            calls.append((cuts, after, chosen, form, (rows_apart,) if rows_apart else ()))

    # And the force sheets as the run lays them out in the end (`CoursePanels.forces`: its parts, drawn larger where
    # the sheets have room, then the load diagrams), the run's own the last.
    own_panels = sheet_module.course_panels
    laid: list = []

    def recorded_panels(*arguments, **options):
        laid.append(own_panels(*arguments, **options))
        return laid[-1]

    def timed_run(most: int, scratch: Path) -> float:
        calls.clear()
        laid.clear()
        force_rows.MOST_CUTS = most
        scratch.mkdir(parents=True)
        scene = scene_of(name, scratch)
        start = time.process_time()
        run_module.run(scene, scratch / f"out-{most}", locale=locale, sheet=sheet)
        return time.process_time() - start

    usual = force_rows.MOST_CUTS
    sheet_module.CutChoice = Recorded
    sheet_module.course_panels = recorded_panels
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        timed_run(usual, scratch / "warm")  # the modules loaded, as every later run finds them
        runs = {"4": timed_run(usual, scratch / "a"), str(MORE_CUTS): timed_run(MORE_CUTS, scratch / "b"),
                "all": timed_run(ALL_CUTS, scratch / "c")}
    force_rows.MOST_CUTS = usual
    sheet_module.CutChoice = own_choice
    sheet_module.course_panels = own_panels
    result: dict = {"scene": name, "locale": locale, "sheet": sheet or "scene's", "run_cpu_s": runs}
    if not calls:
        result["force_sheets"] = 0
        return result
    # The run's own: the μl choice's calls come before it.  Each sheet's rows apart are given to the greedy choice
    # as the run gives them, and are among each sheet's ways in the combinations below.
    cuts, after, chosen, form, rows_apart = calls[-1]
    every = own_choice(cuts, after, chosen, form, *rows_apart)
    result.update(force_sheets=len(cuts), cuts=[len(ways) for ways in cuts], ways=[len(ways) for ways in every.ways_of],
                  sheet=chosen)
    read_after = any(panel.reads_after for panel in after)

    def taken(parts) -> tuple[float, bool]:
        """The sheets the parts (a flat list) take with the drawings after them, and whether those read after the
        force sheets stand after them all."""
        try:
            pages = pack([*parts, *after], chosen, form)
        except SceneError:
            return math.inf, True
        return len(pages), not read_after or reads_in_order(pages)

    base = runs["4"]
    # The run's own: its sheets and order as it lays the force sheets out, and the time of its choice made again as
    # `course_panels` makes it (the greedy choice, then every combination of the ways where they are few,
    # `force_sheet_choice.MOST_COMBINATIONS`).
    final = laid[-1].forces
    assert final[len(final) - len(after):] == tuple(after), "the run's last layout is not its last choice's"
    forget_layouts()
    start = time.process_time()
    own_choice(cuts, after, chosen, form, *rows_apart).fewest(combined=True)
    used = time.process_time() - start
    sheets, in_order = taken(final[:len(final) - len(after)])
    choices = {"run": {"sheets": sheets, "in_order": in_order, "cpu_s": used, "of_run": used / base}}
    for label, most in (("greedy/4", usual), (f"greedy/{MORE_CUTS}", MORE_CUTS), ("greedy/all", ALL_CUTS)):
        forget_layouts()
        start = time.process_time()
        parts = own([ways[:most] for ways in cuts], after, chosen, form, *rows_apart)
        used = time.process_time() - start
        sheets, in_order = taken(parts)
        choices[label] = {"sheets": sheets, "in_order": in_order, "cpu_s": used, "of_run": used / base}
    # Every combination of the ways, those of the sheets with one way fixed, until the budget is spent.
    varied = [k for k, ways in enumerate(every.ways_of) if len(ways) > 1]
    total = math.prod(len(every.ways_of[k]) for k in varied)
    forget_layouts()
    start = time.process_time()
    best, best_in_order, tried = math.inf, math.inf, 0
    for combination in itertools.product(*(range(len(every.ways_of[k])) for k in varied)):
        if time.process_time() - start > budget:
            break
        picks = [0] * len(cuts)
        for k, index in zip(varied, combination, strict=True):
            picks[k] = index
        sheets = every.sheets_taken(picks)
        best = min(best, sheets)
        if not read_after or every.reads_in_order(picks):
            best_in_order = min(best_in_order, sheets)
        tried += 1
    used = time.process_time() - start
    choices["exhaustive"] = {"sheets": best, "in_order_sheets": best_in_order, "cpu_s": used, "of_run": used / base,
                             "combinations": total, "tried": tried, "complete": tried == total}
    result["choices"] = choices
    result["run_sheets"] = choices["run"]["sheets"]
    return result


def measured(name: str, locale: str, sheet: str | None, budget: float) -> dict:
    """:func:`one` in a fresh interpreter, so that no scene's layouts or caches reach another's."""
    return in_fresh_interpreter(Path(__file__), name, locale, sheet, "--budget", str(budget))


def in_fresh_interpreter(script: Path, name: str, locale: str, sheet: str | None, *options: str) -> dict:
    """The row ``script --one name locale`` prints, run in a fresh interpreter, or the error it ends with."""
    command = [sys.executable, str(script.resolve()), "--one", name, locale, *options]
    if sheet:
        command += ["--sheet", sheet]
    done = subprocess.run(command, capture_output=True, text=True, check=False, cwd=ROOT)
    if done.returncode != 0:
        return {"scene": name, "locale": locale, "sheet": sheet or "scene's", "error": done.stderr.strip()[-400:]}
    return json.loads(done.stdout.splitlines()[-1])


def refused(row: dict, columns: int) -> str:
    """The table's line of a run refused: the error's last words, then ``columns`` empty cells."""
    said = row["error"].splitlines()[-1] if row["error"] else "?"
    return (f"| {row['scene']} | {row['locale']} | {row['sheet']} | refused: "
            f"{said.split(': ', 2)[-1].split(' (')[0][:100]} |" + " |" * columns)


def _sheets_cell(choice: dict) -> str:
    """A choice's sheets, marked † where the load diagrams stand before a force sheet."""
    return f"{choice['sheets']}{'' if choice['in_order'] else '†'}"


def table(rows: list[dict]) -> str:
    lines = [("| scene | locale | sheet | force sheets (ways each: cuts and rows apart) | run's choice | greedy/4 | "
              "greedy/8 | greedy/all | exhaustive, in order (tried of all) | run s (4 / 8 / all cuts) | choice's time "
              "of the run: run's, greedy/4, /8, /all, exhaustive |"),
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        if "error" in row:
            lines.append(refused(row, 7))
            continue
        runs = row["run_cpu_s"]
        timing = " / ".join(f"{runs[key]:.2f}" for key in ("4", str(MORE_CUTS), "all"))
        if "choices" not in row:
            lines.append(f"| {row['scene']} | {row['locale']} | {row['sheet']} | none | | | | | | {timing} | |")
            continue
        c = row["choices"]
        ex = c["exhaustive"]
        shares = ", ".join(f"{100 * c[key]['of_run']:.2g} %" for key in (*CHOICES, "exhaustive"))
        sheets = " | ".join(_sheets_cell(c[key]) for key in CHOICES)
        lines.append(f"| {row['scene']} | {row['locale']} | {row['sheet']} | {row['force_sheets']} "
                     f"({' '.join(map(str, row['ways']))}) | {sheets} | {ex['sheets']}, {ex['in_order_sheets']} "
                     f"({ex['tried']} of {ex['combinations']}) | {timing} | {shares} |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sheet", action="append", default=[], help="also measure on this sheet (A4, A3, ...)")
    parser.add_argument("--budget", type=float, default=BUDGET_S,
                        help="processor seconds the exhaustive search may take per scene")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time, each in an interpreter of its own")
    parser.add_argument("--one", nargs=2, metavar=("SCENE", "LOCALE"), help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.one:
        sheet = arguments.sheet[0] if arguments.sheet else None
        print(json.dumps(one(*arguments.one, sheet, arguments.budget), default=str))
        return
    names = [str(path.relative_to(ROOT)) for path in sorted((ROOT / "fixtures").glob("*.toml"))]
    names += [f"new:{kind}" for kind in STARTERS]
    runs = [(name, locale, sheet) for sheet in (None, *arguments.sheet) for name in names for locale in LOCALES]
    rows = []
    with ThreadPoolExecutor(arguments.jobs) as pool:
        for row in pool.map(lambda run: measured(*run, arguments.budget), runs):
            rows.append(row)
            print(json.dumps(row), flush=True)
    summarised(rows, arguments.budget)


def summarised(rows: list[dict], budget: float) -> None:
    """The rows, with what they add up to, written as bench/results/sheet_cuts.json and .md."""
    drawn = [row for row in rows if "choices" in row]
    chosen = [row for row in drawn if any(ways > 1 for ways in row["ways"])]
    refused = [row for row in rows if "error" in row]
    worse = {label: sum(row["choices"][label]["sheets"] > row["choices"]["exhaustive"]["sheets"] for row in drawn)
             for label in CHOICES}
    incomplete = [row for row in drawn if not row["choices"]["exhaustive"]["complete"]]
    # Runs whose choice leaves the load diagrams before a force sheet: of them, those where some combination keeps
    # them after all on as few sheets.
    out_of_order = [row for row in drawn if not row["choices"]["run"]["in_order"]]
    order_left = [row for row in out_of_order
                  if row["choices"]["exhaustive"]["in_order_sheets"] <= row["choices"]["run"]["sheets"]]
    most_ways = max((ways for row in drawn for ways in row["cuts"]), default=0)
    past = {most: sum(ways > most for row in drawn for ways in row["cuts"]) for most in (4, MORE_CUTS)}
    shares = {label: max((row["choices"][label]["of_run"] for row in drawn), default=0.0)
              for label in (*CHOICES, "exhaustive")}
    run_ratios = {key: statistics.median(row["run_cpu_s"][key] / row["run_cpu_s"]["4"] for row in drawn)
                  for key in (str(MORE_CUTS), "all")} if drawn else {}
    result = {"budget_s": budget, "rows": rows, "with_force_sheets": len(drawn), "with_a_choice": len(chosen),
              "refused": len(refused), "worse_than_exhaustive": worse, "exhaustive_incomplete": len(incomplete),
              "most_cuts_of_a_sheet": most_ways, "sheets_past": past, "most_share_of_run": shares,
              "median_run_ratio_to_4": run_ratios, "out_of_order": len(out_of_order),
              "in_order_at_the_same_count": len(order_left)}
    markdown = (
        "# The cuts of force sheets: the run's choice and the greedy one over 4 cuts against more cuts and every "
        "combination\n\n"
        f"{len(rows)} runs (every fixture and starter in en, ru, zh, on each sheet measured), {len(drawn)} with "
        f"force sheets, {len(chosen)} of them with a force sheet that may stand more than one way, {len(refused)} "
        f"refused (the scene's μl or a drawing no such sheet holds). A force sheet had at most **{most_ways}** cuts; "
        f"{past[4]} force sheets had more than 4, {past[MORE_CUTS]} more than {MORE_CUTS}. Sheets taken beyond "
        "the best that every combination of the cuts gives: "
        + ", ".join(f"{NAMES.get(label, label)} in **{count}** runs" for label, count in worse.items())
        + f"; the exhaustive search stopped at its budget ({budget:g} processor s) in {len(incomplete)} runs "
        "(its row says how many combinations it tried of how many). "
        f"The run's choice leaves the load diagrams before a force sheet (†) in {len(out_of_order)} runs; in "
        f"{len(order_left)} of them some combination keeps them after every force sheet on as many sheets (the "
        "choice refuses those that stand more force sheets with every drawing apart, a group away from its "
        "polygon, than the count needs).\n\n"
        "Processor time, the most any run's choice took as a share of the run with 4 cuts: "
        + ", ".join(f"{NAMES.get(label, label)} {100 * share:.2g} %" for label, share in shares.items())
        + "; the whole run with 8 and with every cut, median of its ratio to the run with 4: "
        + ", ".join(f"{key} {ratio:.3f}" for key, ratio in run_ratios.items()) + ".\n\n"
        + table(rows) + "\n\n"
        "Sheets: the force sheets' (with the load diagrams) as `render/packing.pack` lays them, the run's as it draws "
        "them (larger where the sheets have room); the exhaustive search's "
        "fewest, then its fewest with the load diagrams after every force sheet. Run s: the processor "
        "seconds of `run.run` with `force_rows.MOST_CUTS` 4, 8 and every cut; a choice's time: the processor time "
        "of choosing (and packing) alone, as a share of the run with 4.\n"
        "Regenerate with `python bench/sheet_cuts.py --sheet A3 --sheet A4 --budget 20`.\n")
    write_results("sheet_cuts", result, markdown)


if __name__ == "__main__":
    main()
