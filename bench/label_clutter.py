"""How cluttered the placed labels are: on drawn lines, over other shapes, on each other, and on leaders.

    python bench/label_clutter.py                      the placer as it is
    python bench/label_clutter.py --baseline 4783397   and the placer of that commit beside it, in the same run

Every fixture is run in English and Russian (``--sheet none``: the drawings, not the sheets that repeat them), in
this process, with :func:`graphplan.render.labels.place_labels` wrapped so that every call's anchors, obstacles
and placement are kept. For each placement:

* on a line: labels whose box (as drawn, not spaced) meets a drawn line, an arrow, a circle's outline (not a
  point's dot), a filled block's outline or another label's leader (its own leader starts at its own point and ends at its box, and is not counted);
* obstacle hits: (label, obstacle) pairs whose shapes meet, any obstacle (lines, dots, arrowheads, texts);
* overlapping: pairs of labels whose boxes meet (the placer keeps them apart: must stay 0);

A placement that a drawing makes only to letter again with fewer of its anchors (:func:`superseded`) is not drawn
and not counted; its time is.
* leaders and their mean length (mm); the CPU time spent placing (s: the machine is shared, its wall time noisy).

The machine is shared and noisy, so with ``--baseline`` both placers run fixture by fixture alternately and the
figures that matter are the ratios of the one run. Results go to bench/results/label_clutter.md.
"""

from __future__ import annotations

import argparse
import importlib.util
import inspect
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import shapely

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from graphplan import cli
from graphplan.render import (
    balancing,
    diagrams,
    dynamics,
    force_lever,
    force_marks,
    force_polygons,
    labels,
    plans,
    positions,
)

# The modules that letter with the placer (the diagrams place their numbers themselves since 0794f7b); the force
# sheet's drawings letter through force_marks, and its polygons and lever measure their labels against their lines.
CALLERS = (*(module for module in (balancing, diagrams, dynamics, plans, positions) if hasattr(module, "place_labels")),
           force_marks, force_polygons, force_lever,
           # labels itself: the plan of positions and the plan sheets' mechanism letter through its
           # place_breaking_thin_lines, which asks its own placer.
           labels)
LOCALES = ("en", "ru")


@dataclass
class Clutter:
    labels: int = 0
    on_line: int = 0
    obstacle_hits: int = 0
    overlapping: int = 0
    leaders: int = 0
    leader_length: float = 0.0
    seconds: float = 0.0

    def add(self, other: Clutter) -> None:
        for name in self.__dataclass_fields__:
            setattr(self, name, getattr(self, name) + getattr(other, name))

    @property
    def mean_leader(self) -> float:
        return self.leader_length / self.leaders if self.leaders else 0.0


@dataclass
class Recorder:
    place: object
    calls: list = field(default_factory=list)

    def __call__(self, anchors, obstacles, *args, **kwargs):
        start = time.process_time()
        placement = self.place(anchors, obstacles, *args, **kwargs)
        self.calls.append((list(anchors), list(obstacles), placement, time.process_time() - start))
        return placement


# The obstacles drawn as lines, by id while their call lasts: what a label can lie on.
LINES: dict[int, tuple] = {}
# A circle smaller than this (radius, mm) is a point's dot or a pin, not a line a label lies on.
DOT_RADIUS = 1.5


# The labels module's own, kept: wrapped in it too, the recorder would call itself.
_OBSTACLES_OF = labels.obstacles_of


def recording_obstacles_of(items):
    """:func:`labels.obstacles_of`, noting which of its shapes are drawn lines: a polyline, an arrow (its shaft and
    head), a filled block's or a circle's outline; not a text's box, a point's dot, nor a spot a caller adds."""
    shapes = []
    for item in items:
        own = _OBSTACLES_OF([item])
        for shape in own:
            if isinstance(item, labels.Text) or (isinstance(item, labels.Circle) and item.radius < DOT_RADIUS):
                continue
            # The shape kept beside its line: an id is only unique while its object lives.
            LINES[id(shape)] = (shape, shape.boundary if shape.geom_type == "Polygon" else shape)
        shapes += own
    return shapes


def clutter_of(anchors, obstacles, placement, seconds: float) -> Clutter:
    result = Clutter(seconds=seconds)
    boxes = np.array([labels.text_box(text) for text in placement.texts], dtype=object)
    result.labels = len(boxes)
    if not len(boxes):
        return result
    leaders = [shapely.LineString(leader.points) for leader in placement.leaders]
    result.leaders = len(leaders)
    result.leader_length = float(sum(leader.length for leader in leaders))
    # Which leader is whose: a leader starts next to its own anchor's point.
    leader_owner = []
    for leader in leaders:
        start = np.array(leader.coords[0])
        leader_owner.append(int(np.argmin([np.hypot(*(start - anchor.at)) for anchor in anchors])))
    lines = [LINES[id(shape)][1] for shape in obstacles if id(shape) in LINES and LINES[id(shape)][0] is shape]
    line_tree = shapely.STRtree(lines) if lines else None
    leader_tree = shapely.STRtree(leaders) if leaders else None
    for index, label in enumerate(boxes):
        on = line_tree is not None and len(line_tree.query(label, predicate="intersects")) > 0
        if not on and leader_tree is not None:
            on = any(leader_owner[hit] != index for hit in leader_tree.query(label, predicate="intersects"))
        result.on_line += bool(on)
    if obstacles:
        hit, _ = shapely.STRtree(obstacles).query(boxes, predicate="intersects")
        result.obstacle_hits = len(hit)
    one, other = shapely.STRtree(boxes).query(boxes, predicate="intersects")
    result.overlapping = int((one < other).sum())
    return result


def superseded(call, following) -> bool:
    """Whether a placement was made only to be placed again, and never drawn: the next call letters some of its
    anchors (in their order), all at the same points, and no others (a lever's arms whose names crowd the pole are
    given under it, and the rest lettered again without them)."""
    if not following:
        return False
    anchors, later = call[0], following[0][0]
    if not 0 < len(later) < len(anchors):
        return False
    remaining = iter(anchors)
    return all(any(anchor == earlier for earlier in remaining) for anchor in later)


def baseline_labels(commit: str):
    """The labels module as it was at ``commit``, loaded beside the current one (its relative imports resolved
    in graphplan.render)."""
    source = subprocess.run(["git", "show", f"{commit}:graphplan/render/labels.py"], cwd=ROOT, check=True,
                            capture_output=True, text=True).stdout
    path = Path(tempfile.mkdtemp()) / "labels_baseline.py"
    path.write_text(source, encoding="utf-8")
    spec = importlib.util.spec_from_file_location("graphplan.render._labels_baseline", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def accepting(place):
    """``place`` asked only with the keywords it takes: an older placer, measured beside the current one, is not
    given one the callers pass it since (the force drawings' ``shafts``), and places as it did then."""
    taken = set(inspect.signature(place).parameters)

    def placing(anchors, obstacles, *args, **kwargs):
        return place(anchors, obstacles, *args, **{name: value for name, value in kwargs.items() if name in taken})

    return placing


def discarding(recorder: Recorder, discarded: set[int]):
    """:func:`labels._each_in_its_own_direction`, noting the placements it asks of one label and then leaves undrawn:
    a label it tries elsewhere, alone, and keeps where it stood when the new spot is no clearer."""
    own = labels._each_in_its_own_direction

    def each_in_its_own_direction(placement, *args, **kwargs):
        start = len(recorder.calls)
        kept = own(placement, *args, **kwargs)
        discarded.update(start + number for number, (_, _, tried, _) in enumerate(recorder.calls[start:])
                         if not set(tried.texts) <= set(kept.texts))
        return kept

    return each_in_its_own_direction


def run_fixture(scene: Path, locale: str, place, out: Path) -> Clutter:
    recorder = Recorder(place)
    discarded: set[int] = set()
    wrapped = {"place_labels": recorder, "obstacles_of": recording_obstacles_of,
               "_each_in_its_own_direction": discarding(recorder, discarded)}
    originals = {(caller, name): getattr(caller, name) for caller in CALLERS for name in wrapped
                 if hasattr(caller, name)}
    try:
        for caller, name in originals:
            setattr(caller, name, wrapped[name])
        code = cli.main(["run", str(scene), "--out", str(out), "--locale", locale, "--sheet", "none"])
    finally:
        for (caller, name), original in originals.items():
            setattr(caller, name, original)
    if code:
        raise SystemExit(f"{scene.name} ({locale}): graphplan run exited with {code}")
    total = Clutter()
    for number, call in enumerate(recorder.calls):
        if number in discarded or superseded(call, recorder.calls[number + 1:number + 2]):
            continue
        total.add(clutter_of(*call))
    total.seconds = sum(call[3] for call in recorder.calls)
    LINES.clear()
    return total


COLUMNS = ("labels", "on a line", "obstacle hits", "overlapping", "leaders", "mean leader (mm)", "placing (s)")


def row(name: str, clutter: Clutter) -> str:
    values = (clutter.labels, clutter.on_line, clutter.obstacle_hits, clutter.overlapping, clutter.leaders,
              f"{clutter.mean_leader:.2f}", f"{clutter.seconds:.2f}")
    return f"| {name} | " + " | ".join(str(value) for value in values) + " |"


def table(title: str, rows: dict[str, Clutter]) -> list[str]:
    total = Clutter()
    for clutter in rows.values():
        total.add(clutter)
    return [f"### {title}", "", "| run | " + " | ".join(COLUMNS) + " |", "|---" * (len(COLUMNS) + 1) + "|",
            *(row(name, clutter) for name, clutter in rows.items()), row("**all**", total), ""], total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", help="a commit whose placer to measure beside the current one")
    parser.add_argument("--fixtures", nargs="*", help="fixture file names (default: all)")
    args = parser.parse_args()
    scenes = sorted((ROOT / "fixtures").glob("*.toml"))
    if args.fixtures:
        scenes = [scene for scene in scenes if scene.name in args.fixtures or scene.stem in args.fixtures]
    placers = {"current": labels.place_labels}
    if args.baseline:
        placers = {f"baseline {args.baseline}": accepting(baseline_labels(args.baseline).place_labels), **placers}
    results: dict[str, dict[str, Clutter]] = {name: {} for name in placers}
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            for locale in LOCALES:
                for name, place in placers.items():
                    results[name][f"{scene.stem} ({locale})"] = run_fixture(scene, locale, place, Path(scratch) / "o")
                    print(row(f"{name}: {scene.stem} ({locale})", results[name][f"{scene.stem} ({locale})"]),
                          file=sys.stderr)
    lines = ["# Label clutter", "", "`python bench/label_clutter.py" + (f" --baseline {args.baseline}`" if
             args.baseline else "`"), "", "Every fixture, en and ru, `--sheet none`; the columns as the script's",
             "docstring defines them. Placing time is the CPU time of all calls of `place_labels`.", ""]
    totals = {}
    for name, rows in results.items():
        section, totals[name] = table(name, rows)
        lines += section
    if len(totals) == 2:
        old, new = totals.values()
        lines += ["### ratios (current / baseline, same run)", ""]
        for label, before, after in (("on a line", old.on_line, new.on_line),
                                     ("obstacle hits", old.obstacle_hits, new.obstacle_hits),
                                     ("overlapping", old.overlapping, new.overlapping),
                                     ("leaders", old.leaders, new.leaders),
                                     ("mean leader", old.mean_leader, new.mean_leader),
                                     ("placing time", old.seconds, new.seconds)):
            ratio = f"{after / before:.3f}" if before else "–"
            lines.append(f"- {label}: {before:.4g} → {after:.4g} ({ratio})")
        lines.append("")
    (HERE / "results").mkdir(exist_ok=True)
    (HERE / "results" / "label_clutter.md").write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
