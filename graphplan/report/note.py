"""The explanatory note: the worked example a student hands in with the course project.

It is written in the scene's language (:mod:`graphplan.locale`) as a textbook
writes a worked example: the structural analysis (Chebyshev's formula with
its numbers, the groups, the structure formula), the initial data, then for
every plan position the velocity and the acceleration plan step by step (the
driver's velocity with its arithmetic, the scale factor, each group's vector
equation with the modulus and line of action of every term, the crossing of
the lines, the similarity proportions, every value read off with the
segment, the scale and the result), the tables of the plan against the
analytic solution, the error tables, and, where the scene has loads, the
force analysis (initial data of the loads, moment equations, force polygons,
reactions, the balancing load by the polygons and by Zhukovsky's lever).

Everything is read from the records of one :class:`~graphplan.analysis.Analysis`
(the plans' steps, the readings, the force plans and levers); what the note
computes itself (a normal component ω²·l, a similarity proportion, the
lever's Fb) it prints with its arithmetic, and checks against the record
before it does, falling back to the record's own value.  The force
analysis is written by :mod:`graphplan.report.force_note`, the machine's
dynamics, balancing and vibration by :mod:`graphplan.report.machine_note`.  The
tables of errors and of the force analysis are the ones ``errors.md`` and
``forces.md`` print (:mod:`graphplan.report.tables`,
:mod:`graphplan.report.forces`), with the locale's decimal mark.
"""

from __future__ import annotations

import cmath
import contextlib
import datetime
import functools
import itertools
import math
import re
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from .. import kinematic_diagrams
from ..analysis import SCENE_WIDE_WARNINGS, Analysis, PlanPosition, VelocityPosition
from ..check import Reading, epsilon_of_another, quantity_symbol
from ..errors import SceneError
from ..kinematics import at, cross
from ..length_units import FASTEST_CRANK_PIN_M_S, LONGEST_LINK_M, crank_pin_too_fast, length_slip
from ..locale import Count, strings
from ..plans import PLAN_FIELD_MM, LaidVector, LineMeaning, Plan, Similarity, Step, image_name
from ..render.drawings import dimensioned_travels, length_scale, plan_sheet_title
from ..render.plans import ZERO_MM, too_short_to_draw_mm
from ..scales import format_scale, standard_scale
from ..scene import Scene
from ..wording import driver_at, raised
from . import forces as force_report
from . import given_data
from .force_note import forces_section, reproducing, worked_product
from .machine_note import balancing_section, dynamics_section, vibration_section
from .markdown import literal, set_close, user_texts
from .symbols import CAPITALS
from .tables import (
    epsilons_of_others,
    error_table_lines,
    has_reactions,
    largest_errors,
    measured_bound,
    measured_velocity_plans,
    reactions_intro,
    slip_lines,
    undefined_errors,
    unit_of,
    velocity_plans_intro,
    velocity_plans_lines,
)

# Two numbers that agree to this share are the same number printed twice.
_SAME = 1e-6
# Suffixes of the components as the plans name them.
_NORMAL, _CORIOLIS, _TANGENTIAL, _RELATIVE = "ⁿ", "ᵏ", "^τ", "^r"
_ROMAN = {1: "I", 2: "II", 3: "III"}


def note_markdown(analysis: Analysis | None, dynamics=None, scene: Scene | None = None,
                  figures: Collection[str] = (), lever_scales: Mapping[str, float] | None = None,
                  shown_in_parts: Mapping[str, Sequence[str]] | None = None,
                  sheet_levers: Mapping[str, tuple[int, float]] | None = None,
                  tells_diagrams: bool | None = None, plans_shown: tuple[str, ...] = ("velocity", "acceleration")) -> str:
    """The explanatory note of ``analysis`` as Markdown, in the scene's language.

    ``dynamics`` (a :class:`graphplan.machine_dynamics.MachineDynamics`) adds the section on the
    machine's dynamics: the equivalent model, the flywheel and, with a motor, the motion; a scene
    with ``[balancing]`` or ``[vibration]`` has a section on its rotor or on its vibration too.  A
    scene without a linkage has no ``analysis``: its note is those sections alone, of ``scene``.
    ``figures`` names the drawings and plots written beside the note (``plan_2.svg``): each stands
    in the section it illustrates, numbered, its caption under it; ``lever_scales`` the μV each force sheet's
    lever is drawn at there where a small sheet draws it at its own (``forces_5.svg``: 0.01); ``shown_in_parts`` the
    headings of the diagrams a part of a figure holds (``dynamics-2.svg``), which its caption names; ``sheet_levers``
    the course sheet that draws each force sheet's lever and the μV there (``forces_5.svg``: sheet 12, 0.02), told
    after the lever's table where it is not the μV the note works it at.  ``tells_diagrams`` whether it has the
    kinematic diagrams' section (their method and scales, and the figure where ``figures`` has diagrams.svg); by
    default where a run of the scene draws them, so that the note is the one ``--only note`` writes.
    ``plans_shown`` the plans each plan sheet's figure holds (``--only velocity`` draws the velocity plan alone).
    """
    if tells_diagrams is None:
        from ..deliverables import tells_diagrams as told_by_run

        tells_diagrams = told_by_run(scene if analysis is None else analysis.scene, analysis)
    note = _Note(analysis, dynamics=dynamics, scene=scene, figures=frozenset(figures), tells_diagrams=tells_diagrams,
                 lever_scales=dict(lever_scales or {}), sheet_levers=dict(sheet_levers or {}),
                 shown_in_parts={name: tuple(shown) for name, shown in (shown_in_parts or {}).items()},
                 plans_shown=plans_shown)
    note.write()
    return raised("\n".join(note.lines).rstrip("\n") + "\n")


def _in_running_text(heading: str) -> str:
    """A heading as words within a sentence: its first letter small where it begins a word of small letters
    ("Works of ..." → "works of ..."), a symbol or a name kept ("ΔT(φ)", "Je", "JF")."""
    first = heading.split(" ", 1)[0]
    if len(first) > 1 and first[0].isupper() and first[1:].islower():
        return heading[0].lower() + heading[1:]
    return heading


def _turning_pairs(unit, joints: Sequence[str]) -> str:
    """The names of a unit's own turning pairs, in the order of its joints: the structure table's column of them.

    A pair counts once, with the unit that closes it: the crank's pin A is a pair of the group hung on it, not of
    I(1,2); and a joint that is no pin (an RPP's B, where the slot crosses the guide; a sliding leg's point on its
    guide) is no pair.  A unit whose pairs all slide (a driving slider) has none to name.
    """
    pins = {joint for joint, _, _ in unit.revolutes()}
    return ", ".join(joint for joint in dict.fromkeys(joints) if joint in pins) or "—"


def _equal_terms(clauses: Sequence[str]) -> dict[str, str]:
    """The terms a step's further clauses set equal, each to its like: ``aFF4ᵏ + aFF4^r = aE6E4ᵏ + aE6E4^r`` gives
    aFF4ᵏ = aE6E4ᵏ and aFF4^r = aE6E4^r."""
    equal: dict[str, str] = {}
    for clause in clauses:
        sides = [side.split(" + ") for side in clause.split(" = ")]
        if len(sides) == 2 and len(sides[0]) == len(sides[1]):
            equal.update(zip(*sides, strict=True))
    return equal


def _beyond_rounding(value: float, rates: Collection[float]) -> bool:
    """Whether an ω or ε is a value rather than the plan's rounding: more than ROUNDING of the largest of its plan."""
    return abs(value) > force_report.ROUNDING * max((abs(rate) for rate in rates), default=0.0)


def note_html(analysis: Analysis | None, dynamics=None, markdown: str | None = None, scene: Scene | None = None) -> str:
    """The explanatory note as a standalone HTML page (from its ``markdown`` when already written)."""
    from .html import to_html

    scene = analysis.scene if analysis is not None else scene
    assert scene is not None, "a note is of an analysis or of a scene"
    title = strings(scene.locale)["note_title"].format(title=scene.title)
    markdown = markdown if markdown is not None else note_markdown(analysis, dynamics, scene)
    return to_html(markdown, title, scene.locale, symbols=True, author=scene.project.author,
                   verbatim=user_texts(scene))


@dataclass(frozen=True)
class _Term:
    """One term of a vector equation as the note tabulates it."""

    name: str
    modulus: str
    segment: str
    direction: str


@dataclass
class _Note:
    analysis: Analysis | None
    lines: list[str] = field(default_factory=list)
    tables: int = 0
    dynamics: object = None
    scene: Scene | None = None
    figures: frozenset[str] = frozenset()
    figures_shown: int = 0
    tells_diagrams: bool = False
    # μV of each force sheet's lever where the figure beside the note draws it at its own (``forces_5.svg``).
    lever_scales: Mapping[str, float] = field(default_factory=dict)
    # The course sheet that draws each force sheet's lever, and its μV there (``forces_5.svg``: sheet 12, 0.02).
    sheet_levers: Mapping[str, tuple[int, float]] = field(default_factory=dict)
    # The headings of the diagrams each part of a figure shows (``dynamics-2.svg``), named in its caption.
    shown_in_parts: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    # The plans a plan sheet's figure holds: both, or the one a run asked for alone.
    plans_shown: tuple[str, ...] = ("velocity", "acceleration")
    # The symbols a sentence has said what they are (A4, lCA4), each defined once, where it is first used.
    defined: set[str] = field(default_factory=set)
    # What the sections found, as they wrote it, for the conclusions to sum up in the same numbers.
    found: dict[str, object] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.analysis is not None:
            self.scene = self.analysis.scene
            self.mechanism = self.analysis.mechanism
            self.frame = self.analysis.scene.frame_link
        assert self.scene is not None, "a note is of an analysis or of a scene"
        self.text = strings(self.scene.locale)
        self.mark = self.text["decimal_mark"]

    # Formatting in the note's language.

    def t(self, key: str, **values: object) -> str:
        return self.text[key].format(**values)

    def n(self, value: float, digits: int = 5) -> str:
        return force_report.number(float(value), digits, self.mark)

    def mm(self, value: float) -> str:
        """A length on a drawing, to a hundredth of a millimetre."""
        return f"{value:.2f}".replace(".", self.mark)

    def reading_factors(self, millimetres: float, scale: float, result: str, length: float | None = None) -> tuple[str, ...]:
        """A plan's length and its scale (and the link's length an ω or ε is divided by) as a reading writes them:
        the scale and the link's length as the note states them, the plan's length to a hundredth of a millimetre as
        drawn, and digits more where the printed arithmetic would not give the printed ``result`` (61.27·0.0062832 =
        0.38497, not the 0.38498 found: 61.273·0.0062832); most need a digit or two, one just on a rounding boundary
        more (41.26696·0.05 = 2.0633, 41.267·0.05 = 2.0634)."""
        # The length first, then the scale too: a scale chosen from a pole's length (2.975/150 = 0.0198333) is
        # rounded in its sentence, and no digits of the length make up for it (46.5409·0.019833 = 0.92305, not 0.92306).
        tries = [(f"{millimetres:.{decimals}f}".replace(".", self.mark), self.n(scale, digits),
                  *([self.n(length, digits)] if length is not None else []))
                 for digits in (5, 6, 7) for decimals in range(2, 7)]
        # A power of ten, in the result or in a factor (a named point typed a billion metres out): no digits of the
        # length make it read back, and none are added.
        if "·10" in result or any("·10" in text for text in tries[0]):
            return tries[0]
        # Read as the reader reads it: to half a unit of the result's last printed digit (1.36 for 1.35995).
        target = float(result.replace(self.mark, "."))
        decimals_printed = len(result.split(self.mark)[1]) if self.mark in result else 0
        for written in tries:
            read = [float(text.replace(self.mark, ".")) for text in written]
            worked = read[0] * read[1] / (read[2] if length is not None else 1.0)
            if abs(worked - target) <= 0.5 * 10.0 ** -decimals_printed * (1 + 1e-9):
                return written
        return tries[0]

    def on_plan(self, millimetres: float) -> str:
        """A vector's length on its plan, and where the plan leaves it out as too short to draw, that it is not
        drawn: the reader measuring the plan finds no such segment on it."""
        written = self.mm(millimetres)
        if too_short_to_draw_mm(millimetres):
            written += self.text["semicolon"] + self.not_drawn()
        return written

    def not_drawn(self, segment: str = "") -> str:
        """The words that say a segment is left out of its plan as too short to draw; ``segment`` names it where
        the sentence has another subject (``VB = pb·μV = …``: pb is not drawn, not VB's value)."""
        words = self.t("note_segment_short", least=self.n(ZERO_MM))
        return f"{segment} {words}" if segment else words

    def drawn_mm(self, millimetres: float, written: str | None = None) -> str:
        """A plan's length in a sentence, with its unit (``written``: the number as the sentence gives it), and
        where the plan leaves that segment out as too short to draw, that it is not drawn, in brackets: the same
        words as the equation tables', which the reader finds on the plan's caption too."""
        text = f"{self.mm(millimetres) if written is None else written} {self.text['millimetre']}"
        return text + self.short_mark(millimetres)

    def short_mark(self, millimetres: float, segment: str = "") -> str:
        """`` (not drawn: shorter than 0.25 mm)`` after a plan's length the plan leaves out, else nothing."""
        return self.t("bracketed", words=self.not_drawn(segment)) if too_short_to_draw_mm(millimetres) else ""

    def product(self, *factors: str) -> str:
        """Factors joined by the locale's sign of multiplication, a negative one after the first in brackets."""
        return self.text["times"].join([factors[0], *map(self.enclosed, factors[1:])]) if factors else ""

    @staticmethod
    def enclosed(number: str) -> str:
        """A negative number in brackets, to stand after a sign: −2.8 − (−2.8), not −2.8 − −2.8."""
        return f"({number})" if number.startswith("−") else number

    def sense(self, value: float) -> str:
        return self.text["sense_ccw"] if value > 0 else self.text["sense_cw"]

    def with_sense(self, value: float) -> str:
        """", clockwise" after a turning quantity; nothing after one written 0 (rounding's 1e-17 has no sense)."""
        return self.text["comma"] + self.sense(value) if self.n(value) != "0" else ""

    def para(self, *lines: str) -> None:
        definitions = self.definitions(lines)
        if definitions:
            self.para(definitions)
        if self.scene.locale == "zh":
            lines = tuple(map(set_close, lines))
        self.lines += [*lines, ""]

    @functools.cached_property
    def coincident_names(self) -> dict[str, tuple[str, int]]:
        """The points the plans' equations name after a link under another link's pin or on a guide (A3, A4, E1),
        each with that pin and the link: name → (pin, link).  A textbook says once what such a point is."""
        if self.analysis is None:
            return {}
        names = {name: (pin, link) for group in self.mechanism.groups
                 for name, pin, _, link in group.coincident_points()}
        for pp in self.analysis.plans:
            places = _places(pp)
            for plan in (pp.velocity, pp.acceleration):
                for step in plan.steps:
                    for name in _guide_points(step.equation):
                        match = re.fullmatch(r"(.+?)(\d+)", name)
                        if name not in places and match and match.group(1) in places:
                            names[name] = (match.group(1), int(match.group(2)))
        return names

    def definitions(self, lines: Sequence[str]) -> str:
        """The sentences that say what a coincident point (A4) or a length to one (lCA4) is, for each that ``lines``
        name and no earlier paragraph has defined: a symbol is defined where it is first used."""
        if not self.coincident_names:
            return ""
        text = "\n".join(lines)
        # The points in the order of their names (A3 before A4, as their links), the lengths to them after.
        found: list[tuple[int, str, str]] = []
        for name, (pin, link) in self.coincident_names.items():
            if name in self.defined:
                continue
            at = re.search(rf"{re.escape(name)}(?!\d)", text)
            if at is None:
                continue
            key = "note_coincident_frame_point" if link == self.frame else "note_coincident_point"
            found.append((0, name, self.t(key, name=name, point=pin, link=link)))
            self.defined.add(name)
        for name in self.coincident_names:
            for match in re.finditer(rf"l([{CAPITALS}][a-z]?\d*?)({re.escape(name)})(?!\d)|"
                                     rf"l({re.escape(name)})([{CAPITALS}][a-z]?\d*)(?![\d{CAPITALS}])", text):
                start, end = (match.group(1), match.group(2)) if match.group(1) else (match.group(3), match.group(4))
                length = match.group(0)
                if length in self.defined:
                    continue
                found.append((1, length, self.t("note_length_to_coincident", length=length, start=start,
                                                    end=end)))
                self.defined.add(length)
        return " ".join(sentence for *_, sentence in sorted(found))

    def reactions_named(self) -> str:
        """What Rij and its components are, the first time the note names a reaction (the error tables' or the
        force analysis'); nothing after."""
        if "Rij" in self.defined:
            return ""
        self.defined.add("Rij")
        return self.text["note_reactions_named"]

    def heading(self, level: int, title: str, number: object = None) -> None:
        """``number`` the section's ("3.1"), written the locale's way: GOST 2.105 and GB/T 7713 put no point after it."""
        if number is not None:
            title = self.t("heading_numbered", number=number, title=title)
        self.lines += ["#" * level + " " + title, ""]

    def numbered_table(self, caption: str, lead: str | None = "table_lead") -> None:
        """The next table's number, the sentence that refers to it (the locale's ``lead``) and its caption.

        GOST 2.105 and 7.32 want every table and figure referred to in the text before it: the reference is
        written here and in :meth:`figure`, with the number the caption takes, so that the two never differ.
        ``lead`` None: the paragraph before already refers to it, by :meth:`next_table`."""
        self.tables += 1
        if lead is not None:
            self.para(self.t(lead, number=self.tables))
        self.para(self.t("table_caption", number=self.tables, caption=caption))

    @property
    def next_table(self) -> int:
        """The number the next captioned table takes, for a sentence that refers to it from its own paragraph."""
        return self.tables + 1

    def table(self, caption: str | None, header: Sequence[str], rows: Sequence[Sequence[str]],
              align: str | None = None, lead: str | None = "table_lead") -> None:
        """``lead``: the locale's sentence that refers to a captioned table by its number (None: one written
        before, with :attr:`next_table`)."""
        if caption is not None:
            self.numbered_table(caption, lead)
        align = align or "l" * len(header)
        self.lines.append("| " + " | ".join(header) + " |")
        self.lines.append("|" + "".join("---:|" if a == "r" else "---|" for a in align))
        self.lines += ["| " + " | ".join(row) + " |" for row in rows]
        self.lines.append("")

    def figure(self, file: str, caption: str, lead: str = "figure_lead") -> None:
        """The drawing ``file`` when the run writes it beside the note, numbered, its caption under it (as GOST
        2.105 sets a figure's); a picture alone in its paragraph, which the HTML, LaTeX and Word notes place.
        A drawing too tall for a page (a force sheet) is shown in the parts the run cut it into for the note
        (``forces_3-1.svg``, ...), each under the figure's number and caption with its part.  Before it, the
        locale's ``lead`` refers to it by its number."""
        if file not in self.figures:
            return
        self.figures_shown += 1
        self.para(self.t(lead, number=self.figures_shown))
        stem = file.removesuffix(".svg")
        parts = list(itertools.takewhile(lambda part: part in self.figures,
                                         (f"{stem}-{k}.svg" for k in itertools.count(1))))
        shown = [(file, caption)] if not parts else [
            (part, self.part_caption(caption, part, k, len(parts))) for k, part in enumerate(parts, start=1)]
        for picture, words in shown:
            # A bracket of the note's own words must not close it; the title's come escaped (``literal``).
            alternative = re.sub(r"(?<!\\)([\[\]])", r"\\\1", words)
            self.para(f"![{alternative}]({picture})")
            self.para(self.t("figure_caption", number=self.figures_shown, caption=words))

    def part_caption(self, caption: str, part: str, number: int, count: int) -> str:
        """The caption of the ``number``-th of ``count`` parts of a figure, naming the diagrams the part ``part``
        shows where the run says which (their headings, set in the caption's lower case: "Figure 6. Dynamics ...
        (part 2 of 3): energy–mass diagram ΔT(Je); reduced moment of inertia Je(φ)")."""
        shows = self.shown_in_parts.get(part, ())
        if not shows:
            return self.t("figure_part", caption=caption, part=number, count=count)
        return self.t("figure_part_named", caption=caption, part=number, count=count,
                      shows=self.text["semicolon"].join(_in_running_text(heading) for heading in shows))

    def captioned(self, caption: str, table_lines: list[str]) -> None:
        """A table another report wrote, with the note's numbered caption; a part it goes on in after the first
        (the velocity plans, six positions a part) under the locale's "Table 7 (continued)"."""
        self.numbered_table(caption)
        blocks = [list(block) for blank, block in itertools.groupby(table_lines, key=lambda line: not line.strip())
                  if not blank]
        for k, block in enumerate(blocks):
            # GOST 7.32 names the table once, over its first part, and writes «Продолжение таблицы 7» over
            # every other: a part under no caption read as a table of its own with no number.
            if k and block[0].startswith("|"):
                self.para(self.t("table_continued", number=self.tables))
            self.para(*block)

    # The note.

    def write(self) -> None:
        self.heading(1, self.t("note_title", title=literal(self.scene.title)))
        self.project()
        section = self.linkage() if self.analysis is not None else 0
        if self.dynamics is not None:
            section += 1
            dynamics_section(self, section, self.dynamics)
        if self.scene.balancing is not None:
            from ..rotor_balancing import balance

            section += 1
            balancing_section(self, section, balance(self.scene.balancing))
        if self.scene.vibration is not None:
            from ..vibration import steady_state

            section += 1
            vibration_section(self, section, self.scene.vibration, steady_state(self.scene.vibration))
        self.conclusions(section + 1)

    def conclusions(self, section: int) -> None:
        """The note's last section, as a course project's ends: what the sections before found, each in the words
        and numbers its section wrote (``found``), only those the note has."""
        found = self.found
        items = []
        if "structure" in found:
            items.append(self.t("note_conclusion_structure", **found["structure"]))
        if "ratio" in found:
            items.append(self.t("note_conclusion_ratio", ratio=found["ratio"]))
        if "errors" in found:
            for key, largest in zip(("note_conclusion_velocity_errors", "note_conclusion_acceleration_errors"),
                                    found["errors"], strict=True):
                if largest:
                    items.append(self.t(key, errors=self.text["comma"].join(self.largest_error(*error)
                                                                                 for error in largest)))
        for balancing in found.get("balancing", []):
            key = "note_conclusion_balancing" if "lever" in balancing else "note_conclusion_balancing_polygons"
            items.append(self.t(key, **balancing))
        if "efficiency" in found:
            items.append(self.t("note_conclusion_efficiency", efficiency=found["efficiency"]))
        if "flywheel" in found:
            flywheel = found["flywheel"]
            items.append(self.t("note_conclusion_flywheel" if flywheel["needed"] else "note_conclusion_no_flywheel",
                                delta=flywheel["delta"], inertia=flywheel["inertia"]))
        if not items:
            return
        self.heading(2, self.t("note_conclusion"), section)
        self.para(self.t("note_conclusion_lead"))
        # One sentence down the list, as GOST 2.105 writes a list's items: each after the first lower case, each
        # ended by a semicolon, the last by a full stop.
        ends = [self.text["semicolon"].rstrip()] * (len(items) - 1) + [self.text["full_stop"]]
        self.para(*(f"- {item}{end}" for item, end in zip(items, ends, strict=True)))

    def largest_error(self, source: str, percent: str, quantity: str, position: int) -> str:
        """``drafting 0.631 % (VE, position 3)``; no quantity named where the error rounds to 0.000, as its table
        (:func:`~graphplan.report.tables.largest_errors` names none)."""
        name = self.text[f"source_{source}"]
        if not quantity:
            return self.t("note_conclusion_error", source=name, percent=percent)
        return self.t("note_conclusion_error_of", source=name, percent=percent, quantity=quantity, number=position)

    def project(self) -> None:
        """Under the title, what the scene's ``[project]`` gives: the designation, who made and checked it, where,
        when; each on its own line (a Markdown hard break)."""
        project = self.scene.project
        lines = []
        for name in ("designation", "author", "checked_by", "approved_by", "organization", "date"):
            value = getattr(project, name)
            if isinstance(value, datetime.date):
                value = self.t("date_format", date=value)
            else:
                value = literal(value)
            if value:
                lines.append(self.t(f"note_project_{name}", value=value))
        if lines:
            self.para(*(line + "\\" for line in lines[:-1]), lines[-1])

    def linkage(self) -> int:
        """The sections on the linkage: its structure, data, plans, errors and forces; the last one's number."""
        section = 1
        self.structure(section)
        section += 1
        self.initial_data(section)
        self.figure("positions.svg", self.text["positions_title"])
        plans = self.analysis.plans
        working = self.analysis.scene.positions.working
        diagrams = self.t("kd_title", link=working.link, point="") if working is not None else None
        if plans or self.analysis.velocity_plans:
            section += 1
            self.heading(2, self.t("note_kinematics"), section)
            if plans:
                numbers = self.text["enumeration"].join(str(p.number) for p in plans)
                self.para(self.t("note_kinematics_intro", positions=numbers, count=Count(len(plans))))
            for number, plan in enumerate(plans, 1):
                self.kinematics(f"{section}.{number}", plan)
            subsection = len(plans)
            if self.analysis.velocity_plans:
                subsection += 1
                self.heading(3, self.t("velocity_plans_heading"), f"{section}.{subsection}")
                intro = velocity_plans_intro(self.analysis, self.mark)
                if not plans:
                    # No plan sheet, so no section on the plans' accuracy follows to say what δ and its columns are.
                    intro += " " + self.errors_intro()
                undefined = undefined_errors(self.analysis, self.analysis.velocity_plans)
                self.para(intro + (f" {undefined}" if undefined else ""))
                self.captioned(self.t("velocity_plans_heading"), velocity_plans_lines(self.analysis, self.mark))
                for position in measured_velocity_plans(self.analysis):
                    self.captioned(self.t("velocity_plan_errors", number=position.number),
                                   error_table_lines(self.analysis, position, self.mark))
                    self.slips(position)
                self.figure("velocity_plans.svg", self.text["velocity_plans_heading"])
            if diagrams is not None and self.tells_diagrams:
                subsection += 1
                self.heading(3, diagrams, f"{section}.{subsection}")
                self.diagrams_method()
                self.figure("diagrams.svg", diagrams)
        elif diagrams is not None:   # no plans: the diagrams follow the plan of positions they are read off
            self.figure("diagrams.svg", diagrams)
        if plans:
            section += 1
            self.errors(section)
        if any(plan.forces is not None for plan in plans) or self.analysis.equilibrium is not None:
            section += 1
            forces_section(self, section)
        return section

    def diagrams_method(self) -> None:
        """How the kinematic diagrams are built (the chord method), the scales diagrams.svg draws them at and how
        far its derivatives come from the analytic ones, each line as the drawing writes it: the figure stood alone,
        with no word on the method, its μ or its pole distances."""
        from ..render.diagrams import scales_and_differences
        from ..render.primitives import decimal_marked

        scales, differences = scales_and_differences(kinematic_diagrams.of_analysis(self.analysis), self.text)
        self.para(self.t("note_kd_method"))
        # A paragraph each: a line broken by hand reads run together in the LaTeX note.  The drawing parts two
        # formulas with a Latin semicolon in every language; the note with its language's (the Chinese "；").
        for line in (*scales, *differences):
            self.para(decimal_marked(line, self.mark).replace(";  ", self.text["semicolon"]))

    def structure(self, section: int) -> None:
        mechanism = self.mechanism
        n, p5, w = mechanism.degrees_of_freedom
        self.heading(2, self.t("note_structure"), section)
        self.para(self.t("note_links_and_pairs", n=n, p5=p5, p4=0))
        formula = self.t("dof_formula")
        numbers = f"3{self.text['times']}{n} − 2{self.text['times']}{p5} − 0 = {w}"
        self.para(self.t("note_dof", formula=f"{formula} = {numbers}"))
        driver = mechanism.driver
        # A crank that swings (a hand lever) is a rocker, as the textbooks name a link that does not turn round.
        kind = "rocker" if driver.kind == "crank" and not driver.cyclic else driver.kind
        rows = [[f"I({self.frame},{driver.link})", self.t("note_group_driver"), f"{self.frame}, {driver.link}",
                 _turning_pairs(driver, driver.known_joints() + driver.new_joints()), self.t(f"driver_{kind}")]]
        for group in mechanism.groups:
            rows.append([group.label, self.t("note_class_order", klass=_ROMAN[group.klass], order=group.order),
                         ", ".join(str(link) for link in group.links), _turning_pairs(group, group.joints),
                         self.kind_name(group.kind)])
        header = [self.t("column_group"), self.t("column_class_order"), self.t("column_links"),
                  self.t("column_joints"), self.t("column_kind")]
        self.table(self.t("note_groups_caption"), header, rows, lead="note_groups_lead")
        klass = _ROMAN[max((group.klass for group in mechanism.groups), default=1)]
        self.para(self.t("note_structure_formula", formula=mechanism.structure, klass=klass))
        self.found["structure"] = {"formula": mechanism.structure, "klass": klass, "w": w}

    def kind_name(self, kind: str) -> str:
        """RRR as the locale letters a group (ВВВ in Russian); the Latin letters alongside when they differ."""
        if f"kind_{kind}" in self.text:  # a kind not named by its pairs (the triad)
            return self.text[f"kind_{kind}"]
        letters = "".join(self.text["pair_turning"] if c == "R" else self.text["pair_sliding"] for c in kind)
        return letters if letters == kind else f"{letters} ({kind})"

    def initial_data(self, section: int) -> None:
        scene, driver = self.analysis.scene, self.mechanism.driver
        self.heading(2, self.t("note_initial_data"), section)
        rows = [[label, f"{self.n(value)} {self.text['unit_m']}"] for label, value in self.lengths()]
        rows.extend(self.frame_rows())
        rows.extend(self.moving_slide_rows())
        if driver.kind == "crank":
            omega = f"{self.n(abs(driver.omega))} {self.text['unit_rad_per_s']}{self.with_sense(driver.omega)}"
            if driver.rpm is not None:
                # The speed as the scene gave it, and ω from it, as a note on paper writes them: the reader checks
                # the conversion against the assignment, which gives n.
                n = self.n(abs(driver.rpm))
                rows.append([f"n{driver.link}", f"{n} {self.text['unit_rpm']}"])
                omega = f"πn{driver.link}/30 = π{self.text['times']}{n}/30 = {omega}"
            rows.append([f"ω{driver.link}", omega])
            epsilon = f"{self.n(abs(driver.epsilon))} {self.text['unit_rad_per_s2']}{self.with_sense(driver.epsilon)}"
            rows.append([f"ε{driver.link}", epsilon])
            if not driver.cyclic:  # a rocking crank: the angles its positions run between
                rows.append([f"φ{driver.link}", " … ".join(f"{self.n(math.degrees(end))}°" for end in driver.travel)])
        else:
            rows.append([f"V{driver.joint}", f"{self.n(driver.velocity)} {self.text['unit_m_per_s']}"])
            rows.append([f"a{driver.joint}", f"{self.n(driver.acceleration)} {self.text['unit_m_per_s2']}"])
        # The μl the drawings are drawn at, the scene's or the one chosen for its sheets; left out where no
        # sheet holds them at any μl (the drawings, not the note, say so).
        with contextlib.suppress(SceneError):
            scale = format_scale(length_scale(self.analysis)).replace(".", self.mark)
            rows.append(["μl", f"{scale} {self.text['unit_length_scale']}"])
        self.table(self.t("note_initial_data_caption"), [self.t("column_quantity"), self.t("column_value")], rows)
        turns = self.analysis.positions.stroke_turns(driver.sense)
        if turns is not None:
            working, idle = turns
            strokes = self.t("note_strokes", link=scene.positions.working.link, working=self.n(math.degrees(working)),
                             idle=self.n(math.degrees(idle)), ratio=self.n(working / idle, 4))
            # The textbook's θ: how far the crank's two extremes are off a straight line, whatever the linkage (the
            # rod's angle between its extremes in a four-bar or slider-crank, the swing ψ of a slotted lever).
            quicker_working = working < idle
            formula = "(180° − θ)/(180° + θ)" if quicker_working else "(180° + θ)/(180° − θ)"
            # θ is half the difference of the two φ written beside it, so it is written to their decimal places
            # (φw = 187.7°, θ = 7.7°): to five digits of its own it read 7.7047°, finer than the angles it comes from.
            larger_deg = math.degrees(max(working, idle))
            decimals = max(0, 4 - math.floor(math.log10(float(self.n(larger_deg).replace(self.mark, ".")))))
            theta_deg = round(math.degrees(abs(working - idle)) / 2.0, decimals)
            theta = self.t("note_strokes_theta", theta=self.n(theta_deg), formula=formula,
                           ratio=self.n(working / idle, 4))
            # K ≥ 1 where the working stroke is the slower one, as a machine that works in one stroke is laid out.
            quicker = f" {self.t('note_strokes_quicker')}" if working / idle < 1.0 - 1e-6 else ""
            # The stroke H or swing ψ the plan of positions dimensions, which the note handed in alone would lack.
            travels = [self.travel_words(travel) for travel in dimensioned_travels(self.analysis, self.text)]
            travel = f" {self.t('note_strokes_travel', travels=', '.join(travels))}" if travels else ""
            self.para(f"{strokes} {theta}{quicker}{travel}")
            self.found["ratio"] = self.n(working / idle, 4)
            self.extra_reversals()
        elif self.analysis.positions.working_link_turns:
            self.para(self.t("note_turns_round", link=scene.positions.working.link,
                             turns=Count(abs(self.analysis.positions.working_link_turns))))
        self.given_data()
        self.scene_warnings()

    def given_data(self) -> None:
        """The rest of the assignment, which a course project's note states whole under its initial data: the
        links' masses and moments of inertia, then the loads, friction and the dynamics' data, each table only where
        the scene gives any of it."""
        masses = given_data.mass_rows(self)
        if masses:
            self.table(self.t("note_data_masses_caption"), given_data.mass_header(self), masses, "rrlr",
                       lead="note_data_masses_table_lead")
        rows = given_data.data_rows(self)
        if rows:
            self.table(given_data.data_caption(self), given_data.data_header(self), rows, "lll",
                       lead="note_data_table_lead")

    def travel_words(self, travel) -> str:
        """``the rocker's swing ψ = 67.6°``, ``the stroke H = 0.3 m``: a travel the plan of positions dimensions, named
        by its kind, as the textbook names a rocker's swing (угол размаха коромысла, 摇杆摆角) apart from a slider's
        stroke (ход, 行程), and a slotted lever's, a link a block slides in, apart from a rocker's."""
        value = travel.text.replace(".", self.mark)
        if not travel.swing:
            return self.t("note_travel_stroke", value=value)
        slotted = any(slide.guide == travel.link for slide in self.analysis.motion.slides)
        return self.t("note_travel_swing_slotted" if slotted else "note_travel_swing", value=value)

    def extra_reversals(self) -> None:
        """Where the working link turns back more than twice a turn, the two extremes the strokes paragraph names are
        a choice the run warned of: the note handed in must say so, or it reads as a link that swings once."""
        if not any(warning.code == "extra-reversals" for warning in self.analysis.warnings):
            return
        reversals = sorted(math.degrees(value) % 360.0 for value in self.analysis.positions.reversals)
        angles = self.text["enumeration"].join(f"{value:.2f}°".replace(".", self.mark) for value in reversals)
        self.para(self.t("note_warning_extra_reversals", link=self.analysis.scene.positions.working.link,
                         count=Count(len(reversals)), angles=angles))

    def scene_warnings(self) -> None:
        """What the run warned of about the scene as a whole (its lengths in millimetres, a working sense its link
        never takes) and the positions near a singular one or passing one, said under the data it is about: the
        console's line is gone by the time the note is handed in, and a note of 550-m links must not read as if
        nothing were amiss."""
        codes = sorted({warning.code for warning in self.analysis.warnings if warning.code in SCENE_WIDE_WARNINGS})
        working = self.analysis.scene.positions.working
        if codes:
            self.para(" ".join(self.lengths_in_mm() if code == "lengths-in-mm" else self.t(
                "note_warning_" + code.replace("-", "_"), link=working.link if working else "") for code in codes))
        # Near a singular position the plans, and a hand drawing of them, magnify every slip: a note that hands in
        # their values must say where, as the console did.
        numbers = self.analysis.positions.numbers
        singular = sorted({int(numbers[warning.position]) for warning in self.analysis.warnings
                           if warning.code == "ill-conditioned"})
        if singular:
            self.para(self.t("note_warning_ill_conditioned", count=Count(len(singular)),
                             positions=self.text["enumeration"].join(map(str, singular))))
        # Between two positions the real mechanism may change its assembly where the solution keeps the first's.
        toggles = sorted({warning.position for warning in self.analysis.warnings if warning.code == "toggle-between"})
        if toggles:
            pairs = (f"{numbers[after]}–{numbers[(after + 1) % len(numbers)]}" for after in toggles)
            self.para(self.t("note_warning_toggle_between", pairs=self.text["enumeration"].join(pairs)))

    def lengths_in_mm(self) -> str:
        """The caution of the ``lengths-in-mm`` warning: dimensions larger than any machine's, or the one length a
        named point far off its link gives away, with what was likely meant (a crank a thousandth of itself is no
        millimetres, and a point 6 m off a 0.05 m crank no dimension over 20 m), said in the note's own terms (lOA,
        point S2), not the scene's keys, which its reader does not have."""
        larger = self.t("note_warning_lengths_in_mm", longest=self.n(LONGEST_LINK_M),
                        fastest=self.n(FASTEST_CRANK_PIN_M_S))
        slip = length_slip(self.analysis.motion)
        if slip is None or slip.far_off is None or isinstance(slip.value, tuple):
            return larger
        far = slip.far_off
        times = self.n(round(far.times)) if far.times >= 10 else self.n(far.times, 2)
        if slip.shorter:
            told = self.t("note_warning_length_a_thousandth", length="l" + far.joints.replace("–", ""),
                          value=self.n(slip.value), meant=self.n(slip.value * 1000), times=times)
        else:
            told = self.t("note_warning_point_far_off", point=far.point, start=far.start, reach=self.n(far.reach),
                          meant=self.n(far.reach_meant), times=times)
        return f"{told} {larger}" if crank_pin_too_fast(self.mechanism) else told

    def frame_rows(self) -> list[list[str]]:
        """The frame's dimensions: how far apart its points are (lOC), and where each of its named lines runs:
        how far from the driver's pivot (from the frame's first point for a slider driver), at what angle."""
        scene, metre = self.analysis.scene, self.text["unit_m"]
        points = scene.frame_points
        driver = self.mechanism.driver
        origin = driver.pivot if driver.kind == "crank" else next(iter(points), None)
        # The pivot first, as the lengths read from it: lOC, not lCO.
        names = sorted(points, key=lambda name: name != origin)
        rows = [[f"l{first}{second}", f"{self.n(abs(points[second] - points[first]))} {metre}"]
                for first, second in itertools.combinations(names, 2)]
        if origin is None:  # a frame of lines alone: nothing to measure them from
            return rows
        pivot = points[origin]
        lines = []  # (label, a point of the line, its direction, its angle in degrees as written)
        for name, line in scene.frame_lines.items():
            through = points[line.through] if isinstance(line.through, str) else complex(*line.through)
            lines.append((name, through, cmath.exp(1j * line.angle), math.degrees(line.angle)))
        # A slide on a guide of the frame that no named line gives: the line its joint runs along.
        motion = self.analysis.motion
        size = max((abs(complex(np.ravel(point.r)[0]) - pivot) for point in motion.points.values()), default=1.0)
        for slide in motion.slides:
            if slide.guide != scene.frame_link or slide.joint not in motion.points:
                continue
            along, at = complex(np.ravel(slide.u)[0]), complex(np.ravel(motion.points[slide.joint].r)[0])
            if any(abs(cross(along, direction)) < _SAME and abs(cross(direction, at - through)) <= _SAME * size
                   for _, through, direction, _ in lines):
                continue
            angle = 90.0 - (90.0 - math.degrees(cmath.phase(along))) % 180.0  # the line's, within (−90°, 90°]
            lines.append((self.t("note_guide_of", joint=slide.joint), at, along, angle))
        for label, through, direction, angle in lines:
            distance = abs(cross(direction, pivot - through))
            rows.append([label, self.t("note_frame_line", distance=f"{self.n(distance)} {metre}", point=origin,
                                       angle=self.n(angle))])
        return rows

    def moving_slide_rows(self) -> list[list[str]]:
        """The lines that slides run along on moving links: an RPR's slide where it misses the lever's pivot (how
        far, on which side), a guide a group puts on a moving link (through which point, at what angle to the
        link's line; a PRP's joint beside it, how far and on which side), and an RPP's slot (its angle to the
        guide)."""
        metre, rows = self.text["unit_m"], []
        for group in self.mechanism.groups:
            if group.kind == "RPR" and group.offset != 0.0:
                block, pivot = group.joints
                # The scene's offset is to the left of the slide's direction, which runs from the pivot's side
                # toward the block: standing at the pivot and facing the block, the slide passes on that side.
                side = "note_slide_offset_left" if group.offset > 0 else "note_slide_offset_right"
                rows.append([self.t("note_slide_line", link=group.links[1]),
                             self.t(side, distance=f"{self.n(abs(group.offset))} {metre}", pivot=pivot, joint=block)])
            joints: dict[int, str] = {}  # the joint that slides on each link, the group's first on it
            for _, carrier, joint in group.sliding_pairs(self.mechanism):
                joints.setdefault(carrier, joint)
            for index, guide in enumerate(group.guides()):
                if guide.link is None or guide.link == self.frame or guide.link not in joints:
                    continue
                line = self.link_line(guide.link)
                rows.append([self.t("note_guide_of", joint=joints[guide.link]),
                             self.t("note_guide_on_moving_link", point=guide.through,
                                    angle=self.n(math.degrees(guide.angle)),
                                    line=line or self.t("note_line_of_link", link=guide.link))])
                # A PRP's joint may run beside its guide (on the frame, the joint's own line is a row of the frame's).
                offset = group.offsets[index] if group.kind == "PRP" else 0.0
                if offset != 0.0:
                    side = "note_slide_beside_guide_left" if offset > 0 else "note_slide_beside_guide_right"
                    rows.append([self.t("note_slide_line", link=group.links[index]),
                                 self.t(side, distance=f"{self.n(abs(offset))} {metre}", joint=joints[guide.link])])
            if group.kind == "RPP":  # the slot's angle to the guide, which the Scotch yoke's 90° hides
                rows.append([self.t("note_slot_of", link=group.links[1]),
                             self.t("note_slot_at_angle", angle=self.n(math.degrees(group.angle)),
                                    joint=group.joints[1])])
        return rows

    def link_line(self, link: int) -> str | None:
        """The link's reference line, which a guide on it is set at an angle to, named by two of its points
        (``OA``: the crank's pivot and pin); None where no second point lies on it (a slider's, along its guide)."""
        motion = self.analysis.motion
        reference = motion.links[link]

        def at(name: str) -> complex:
            return complex(np.ravel(motion.points[name].r)[0])

        origin, along = at(reference.origin), complex(np.ravel(reference.u)[0])
        ahead = []  # (how far, name) of the link's points on its line, on the side the line points to
        for name in self.mechanism.fixed_on.get(link, ()):
            arm = at(name) - origin if name in motion.points else 0j
            if (arm / along).real > 0 and abs(cross(along, arm)) <= _SAME * abs(arm):
                ahead.append((abs(arm), name))
        return f"{reference.origin}{max(ahead)[1]}" if ahead else None

    def lengths(self) -> list[tuple[str, float]]:
        """The constant distances between the points of each link that the construction uses (lOA, lAB, lAS3, ...);
        a point off the line it is placed from (a coupler point M, a third joint D of a rocker) from both ends of
        that line, the two sides that fix it and that its similarity proportions read."""
        motion, found, seen = self.analysis.motion, [], set()

        def add(first: str, second: str) -> None:
            if first == second or frozenset((first, second)) in seen:
                return
            if first not in motion.points or second not in motion.points:
                return
            distance = np.abs(np.asarray(motion.points[second].r) - np.asarray(motion.points[first].r))
            distance = distance[np.isfinite(distance)]
            if distance.size and not distance.any():
                return  # a point placed on another (a centre of mass at its link's pivot): no length to give
            if distance.size and float(np.ptp(distance)) <= _SAME * max(float(distance.max()), 1e-300):
                seen.add(frozenset((first, second)))
                found.append((f"l{first}{second}", float(distance[0])))

        for unit in self.mechanism.units:
            for names in unit.solver.fixed_points().values():
                for first, second in itertools.combinations(names, 2):
                    add(first, second)
            for spec in unit.points:
                add(spec.start, spec.name)
                if spec.offset != 0.0:
                    add(spec.toward, spec.name)
        return found

    # Kinematics of one position.

    def kinematics(self, section: str, plan: PlanPosition) -> None:
        positions = self.analysis.positions
        value = float(positions.values[plan.index])
        where = driver_at(self.mechanism, self.text, value, self.n)
        stroke = ""
        if positions.strokes is not None:
            stroke = self.text["comma"] + self.text[f"{positions.strokes[plan.index]}_stroke"]
        self.heading(3, f"{self.t('position_heading', number=plan.number)}{self.text['colon']}{where}{stroke}", section)
        self.plan_section(plan, plan.velocity)
        self.plan_section(plan, plan.acceleration)
        for kind in ("velocity", "acceleration"):
            self.values_table(plan, kind)
        self.figure(f"plan_{plan.number}.svg", plan_sheet_title(self.text, self.plans_shown, plan.number))

    def plan_section(self, pp: PlanPosition, plan: Plan) -> None:
        kind = plan.kind
        self.heading(4, self.text[f"{kind}_plan_title"])
        blocks = self.blocks(plan)
        for index, steps in blocks:
            unit = self.mechanism.units[index]
            if index == 0:
                self.driver_step(pp, plan)
                self.scale(pp, plan)
            else:
                group = unit.solver
                self.para(f"**{self.t('note_group_heading', group=group.label, kind=self.kind_name(group.kind))}**")
                self.assur_point(plan, steps)
                for step in steps:
                    if step.similarity is None and step.fixes:
                        self.group_step(pp, plan, step)
            similar = [self.similarity(pp, plan, step.similarity) for step in steps if step.similarity is not None]
            if similar:
                self.para(self.t("note_similarity"), *(f"- {line}" for line in similar))
            # Vectors read off points found by similarity (a triad's VBA for ω3) come after those points.
            for step in steps:
                if index != 0 and step.similarity is None and not step.fixes:
                    self.group_step(pp, plan, step)
        self.readings(pp, plan)

    def assur_point(self, plan: Plan, steps: list[Step]) -> None:
        """Why a triad's plan starts at Assur's special point, which its first step fixes."""
        special = {image_name(name) for name in plan.auxiliary}
        # A guide link's point under a slider's pin may be put on the plan first, by similarity.
        first = next((step for step in steps if step.fixes and step.similarity is None), None)
        if plan.kind != "velocity" or first is None or first.fixes[-1] not in special:
            return
        point = next(name for name in plan.auxiliary if image_name(name) == first.fixes[-1])
        # Both lines through the pole (the legs' outer joints, or the guides' points under the pins, fixed): Σ
        # stands still, the instant centre of its link.
        still = " " + self.t("note_assur_instant_centre", point=point, link=point[1:]) \
            if all(line.through == "p" for line in first.lines) else ""
        if all(line.along.kind == "perpendicular" for line in first.lines):
            lines = ["".join(line.along.points) for line in first.lines]
            self.para(self.t("note_assur_point", point=point, link=point[1:], first=lines[0], second=lines[1]) + still)
            return
        # A sliding leg's line is its guide, which names the slider's pin: Σ is on the guide's normal there.
        names, motions = [], []
        for line in first.lines:
            if line.along.kind == "perpendicular":
                outer, inner = line.along.points
                names.append(self.t("note_assur_leg_line", line=f"{outer}{inner}"))
                motions.append(self.t("note_assur_leg_motion", line=f"{outer}{inner}", outer=outer))
            elif line.along.kind == "slot":
                names.append(self.t("note_assur_slot_line", pin=line.along.points[0], link=line.along.link))
                motions.append(self.t("note_assur_slot_motion", pin=line.along.points[0]))
            else:
                names.append(self.t("note_assur_normal_line", pin=line.along.points[0]))
                motions.append(self.t("note_assur_normal_motion", pin=line.along.points[0]))
        self.para(self.t("note_assur_point_sliding", point=point, link=point[1:], first=names[0], second=names[1],
                         first_motion=motions[0], second_motion=motions[1]) + still)

    def blocks(self, plan: Plan) -> list[tuple[int, list[Step]]]:
        """The plan's steps by the unit of the structure (driver, groups) that drew them, in order.

        A unit's steps end with the one that fixes its new joints; the named
        points a unit places by similarity come right after it, and a guide
        link's point placed by similarity belongs to the group that needs it.
        """
        units = self.mechanism.units
        named = {plan.images[spec.name]: k for k, unit in enumerate(units) for spec in unit.points
                 if spec.name in plan.images}
        fixed: set[str] = set()
        ends = [len(plan.steps) - 1] * len(units)
        pending = list(range(len(units)))
        for i, step in enumerate(plan.steps):
            fixed.update(step.fixes)
            for k in list(pending):
                letters = {plan.images.get(joint) for joint in units[k].solver.new_joints()}
                if None not in letters and letters <= fixed:
                    ends[k] = i
                    pending.remove(k)
        found: dict[int, list[Step]] = {k: [] for k in range(len(units))}
        for i, step in enumerate(plan.steps):
            if step.similarity is not None and step.similarity.letter in named:
                found[named[step.similarity.letter]].append(step)
                continue
            owner = next((k for k in range(len(units)) if ends[k] >= i), len(units) - 1)
            found[owner].append(step)
        return [(k, found[k]) for k in range(len(units))]

    def letter(self, plan: Plan, letter: str) -> str:
        """A plan letter as the note writes it: the pole of an acceleration plan is the locale's (π)."""
        if letter == "p" and plan.kind == "acceleration":
            return self.text["acceleration_pole"]
        return letter

    def segment(self, plan: Plan, start: str, end: str) -> str:
        return self.letter(plan, start) + self.letter(plan, end)

    def length_mm(self, plan: Plan, start: str, end: str) -> float:
        return abs(plan.mm(end) - plan.mm(start))

    def driver_step(self, pp: PlanPosition, plan: Plan) -> None:
        driver = self.mechanism.driver
        joint = driver.joint
        value = abs(plan.value(joint))
        velocity = plan.kind == "velocity"
        unit = self.text["unit_m_per_s" if velocity else "unit_m_per_s2"]
        if driver.kind == "slider":
            symbol = "ṡ" if velocity else "s̈"
            key = "note_slider_velocity" if velocity else "note_slider_acceleration"
            rate = driver.velocity if velocity else driver.acceleration
            vector = f"{'V' if velocity else 'a'}{joint}"
            if rate >= 0:
                self.para(self.t(key, equation=f"{vector} = {symbol} = {self.n(value)} {unit}"))
                return
            # Moving (or speeding up) backward: the rate keeps its sign, the vector's modulus is its size.
            self.para(self.t(f"{key}_against", rate=f"{symbol} = {self.n(rate)} {unit}",
                             equation=f"{vector} = |{symbol}| = {self.n(value)} {unit}"))
            return
        length = f"l{driver.pivot}{joint}"
        omega, epsilon, arm = abs(driver.omega), driver.epsilon, driver.length
        if velocity:
            written = self.n(value)
            equation = (f"V{joint} = ω{driver.link}·{length} = {worked_product(self, [omega, arm], written)} = "
                        f"{written} {unit}")
            self.para(self.t("note_crank_velocity", equation=equation, joint=joint, pivot=driver.pivot,
                             link=driver.link, sense=self.sense(driver.omega)))
            return
        centripetal = self.n(omega * omega * arm)
        # ω² times the arm as printed gives the result as printed: 6.28319²·0.1 = 3.9478, where 6.2832² gave 3.9479.
        written_omega, written_arm = reproducing(self, [omega, arm], [5, 5], centripetal, 5,
                                                 lambda omega, arm: omega * omega * arm)
        normal = f"a{joint}ⁿ = ω{driver.link}²·{length} = {written_omega}²{self.text['times']}{written_arm} = " \
                 f"{centripetal} {unit}"
        if epsilon == 0:
            self.para(self.t("note_crank_acceleration", equation=f"a{joint} = {normal}", joint=joint,
                             pivot=driver.pivot, link=driver.link))
            return
        written = self.n(abs(epsilon) * arm)
        tangential = (f"a{joint}^τ = ε{driver.link}·{length} = {worked_product(self, [abs(epsilon), arm], written)} = "
                      f"{written} {unit}")
        total = f"a{joint} = √((a{joint}ⁿ)² + (a{joint}^τ)²) = {self.n(value)} {unit}"
        self.para(self.t("note_crank_acceleration_tangential", normal=normal, tangential=tangential, total=total,
                         joint=joint, pivot=driver.pivot, link=driver.link, sense=self.sense(epsilon)))

    def scale(self, pp: PlanPosition, plan: Plan) -> None:
        """The scale factor of the plan with the arithmetic that chose it (as :func:`graphplan.plans` does)."""
        drawing = self.analysis.scene.drawing
        velocity = plan.kind == "velocity"
        symbol = "μV" if velocity else "μa"
        unit = self.text["unit_velocity_scale" if velocity else "unit_acceleration_scale"]
        joint = self.mechanism.driver.joint
        quantity = f"{'V' if velocity else 'a'}{joint}"
        letter = plan.images[joint]
        segment = self.segment(plan, "p", letter)
        given = drawing.velocity_scale if velocity else drawing.acceleration_scale
        pole = drawing.velocity_pole if velocity else drawing.acceleration_pole
        value = abs(plan.value(joint))
        scale = self.n(plan.scale)
        if given is not None and math.isclose(given, plan.scale, rel_tol=_SAME):
            self.para(self.t("note_scale_given", symbol=symbol, scale=scale, unit=unit,
                             equation=f"{segment} = {quantity}/{symbol} = {self.n(value)}/{scale} = "
                                      f"{self.drawn_mm(value / plan.scale)}"))
        elif pole is not None and value > 0 and math.isclose(value / pole, plan.scale, rel_tol=_SAME):
            self.para(self.t("note_scale_pole", segment=segment, pole=self.drawn_mm(pole, self.n(pole)),
                             quantity=quantity, unit=unit, millimetre=self.text["millimetre"],
                             equation=f"{symbol} = {quantity}/{segment} = {self.n(value)}/{self.n(pole)} = {scale}"))
        else:
            extent = max(abs(a - b) for a in plan.points.values() for b in plan.points.values())
            least = max(extent, 1e-300) / PLAN_FIELD_MM
            if math.isclose(standard_scale(least), plan.scale, rel_tol=_SAME):
                self.para(self.t("note_scale_standard", symbol=symbol, extent=self.n(extent), field=self.n(PLAN_FIELD_MM),
                                 least=self.n(least), scale=scale, unit=unit,
                                 quantity_unit=self.text["unit_m_per_s" if velocity else "unit_m_per_s2"]))
            else:
                self.para(f"{symbol} = {scale} {unit}{self.text['full_stop']}")
            if value > 0:
                self.para(f"{segment} = {quantity}/{symbol} = {self.n(value)}/{scale} = "
                          f"{self.drawn_mm(value / plan.scale)}{self.text['full_stop']}")

    # A group's vector equation.

    def group_step(self, pp: PlanPosition, plan: Plan, step: Step) -> None:
        clauses = step.equation.split(", ")
        sides = [side.split(" + ") for side in clauses[0].split(" = ")]
        shown = self.equation(" = ".join(" + ".join(side) for side in sides))
        explanation = "" if step.translating is None else self.t("note_translates", link=step.translating)
        extra = "".join(f", {self.equation(clause)}" for clause in clauses[1:])
        if len(sides) < 3 and all(len(side) == 1 for side in sides):
            self.para(f"{shown}{extra}" + (f" — {explanation}" if explanation else "") + self.text["full_stop"])
            return
        # Numbered and captioned as every other table of the note, a reference to it before it (GOST 2.105).
        self.para(self.t("note_vector_equation", equation=shown + extra) + (f" ({explanation})" if explanation else "")
                  + self.text["full_stop"] + " " + self.t("note_equation_table_lead", number=self.next_table))
        terms = self.terms(pp, plan, step, sides, _equal_terms(clauses[1:]))
        header = [self.t("column_vector"), self.t("column_modulus"), self.t("column_on_plan"),
                  self.t("column_direction")]
        caption = self.t("note_equation_table", vector=self.equation(sides[0][0]), number=pp.number)
        self.table(caption, header, [[term.name, term.modulus, term.segment, term.direction] for term in terms],
                   lead=None)
        if step.lines and step.fixes:
            lines = self.text["semicolon"].join(self.t("note_line_through", line=self.line(line.along),
                                     point=self.letter(plan, line.through)) for line in step.lines)
            angle = f"{self.n(step.crossing_deg, 4)}" if step.crossing_deg is not None else "—"
            self.para(self.t("note_lines_cross", lines=lines, point=self.letter(plan, step.fixes[-1]), angle=angle))

    def equation(self, text: str) -> str:
        """An equation of the record with velocities written V, as the textbooks print them."""
        return re.sub(rf"(?<![A-Za-z])v(?=[{CAPITALS}])", "V", text)

    def line(self, along: LineMeaning) -> str:
        """A line of action (⊥ AB, ∥ guide) in the note's language; points and frame lines keep their names."""
        if along.kind == "guide":
            return "∥ " + (self.text["note_guide"] if along.link is None else self.t("note_guide_on_link", link=along.link))
        if along.kind == "slot":
            return "∥ " + self.text["note_slot"]
        if along.kind == "slide":
            return "∥ " + self.t("note_slide_of_link", link=along.link)
        return along.text

    def resolve(self, plan: Plan, point: str) -> str | None:
        """The plan letter of a point an equation names: a mechanism point, a guide link's point (B4), or a
        link's point over a joint (A3 is the block's point A); the frame's points are at the pole."""
        if point in plan.images:
            return plan.images[point]
        if image_name(point) in plan.points:
            return image_name(point)
        match = re.fullmatch(r"(.+?)(\d+)", point)
        if match:
            base, link = match.group(1), int(match.group(2))
            if link == self.frame:
                return "p"
            if base in plan.images:
                return plan.images[base]
        return None

    def terms(self, pp: PlanPosition, plan: Plan, step: Step, sides: list[list[str]],
              equal: Mapping[str, str] | None = None) -> list[_Term]:
        """Each term of each side with its modulus, its segment on the plan and its line of action.

        A side is walked as it is laid off: from the image of its first
        (known) term, each component from the end of the one before, the last
        ending at the point the step fixes. A term ``equal`` names is known as the term it equals, found before
        (:meth:`copied`).
        """
        by_meaning = {vector.meaning: vector for vector in step.vectors}
        result = self.resolve(plan, _body(sides[0][0])[1])
        terms: list[_Term] = []
        listed: set[str] = set()
        for number, side in enumerate(sides[1:]):
            current = self.resolve(plan, _body(side[0])[1])
            if side[0] not in listed:
                terms.append(self.known_term(plan, side[0], current))
                listed.add(side[0])
            for position, name in enumerate(side[1:], 1):
                vector = by_meaning.get(name)
                last = position == len(side) - 1
                if vector is not None:
                    start, end = vector.start, vector.end
                else:
                    start, end = current, (result if last else None)
                current = end
                if name in listed:
                    continue
                listed.add(name)
                if equal and name in equal:
                    terms.append(self.copied(pp, plan, name, equal[name], vector))
                    continue
                terms.append(self.component(pp, plan, step, name, start, end, vector, number))
        return terms

    def copied(self, pp: PlanPosition, plan: Plan, name: str, same: str, laid: LaidVector | None) -> _Term:
        """A term the step copies from one found before, not one it solves for: link b of an RPP on a turning guide
        slides on it without turning relative to it, so every point of b moves alike relative to the guide's link
        (aFF4ᵏ + aFF4^r = aE6E4ᵏ + aE6E4^r, each part equal to its like). Its modulus is that term's, its Coriolis
        part 2·ω·V of the same relative velocity; its segment is its own where the step lays it (f4f)."""
        shown = self.equation(name)
        found = next(((vector, step) for step in plan.steps for vector in step.vectors if vector.meaning == same), None)
        if found is None:
            return _Term(shown, "?", "—", "—")
        source, source_step = found
        value = abs(plan.points[source.end] - plan.points[source.start])
        segment = "—" if laid is None else f"{self.segment(plan, laid.start, laid.end)} = " \
            f"{self.on_plan(abs(plan.points[laid.end] - plan.points[laid.start]) / plan.scale)}"
        if name.endswith(_CORIOLIS):
            modulus, direction = self.coriolis(pp, name, value)
            return _Term(shown, modulus, segment, direction)
        unit = self.text["unit_m_per_s" if plan.kind == "velocity" else "unit_m_per_s2"]
        along = [line.along for line in source_step.lines if line.through == source.start]
        return _Term(shown, f"{self.equation(same)} = {self.n(value)} {unit}", segment,
                     self.line(along[0]) if along else "—")

    def known_term(self, plan: Plan, name: str, letter: str | None) -> _Term:
        shown = self.equation(name)
        if letter is None:
            return _Term(shown, "—", "—", "—")
        unit = self.text["unit_m_per_s" if plan.kind == "velocity" else "unit_m_per_s2"]
        if letter == "p":
            return _Term(shown, "0", self.letter(plan, "p"), self.text["note_at_pole"])
        value = abs(plan.points[letter])
        segment = f"{self.segment(plan, 'p', letter)} = {self.on_plan(value / plan.scale)}"
        return _Term(shown, f"{self.n(value)} {unit}", segment, self.text["note_known"])

    def component(self, pp: PlanPosition, plan: Plan, step: Step, name: str, start: str | None, end: str | None,
                  vector: LaidVector | None, side: int) -> _Term:
        shown = self.equation(name)
        segment = self.segment(plan, start, end) if start and end else "—"
        if name.endswith((_NORMAL, _CORIOLIS)) and vector is not None:
            value = abs(plan.points[vector.end] - plan.points[vector.start])
            segment += f" = {self.on_plan(value / plan.scale)}"
            if name.endswith(_NORMAL):
                modulus, direction = self.normal(pp, plan, name, value)
            else:
                modulus, direction = self.coriolis(pp, name, value)
            return _Term(shown, modulus, segment, direction)
        if start and end and not step.fixes:
            # A step that fixes nothing reads a relative vector off points already found (a triad's ω and ε, the
            # sliding of a triad's slider found by similarity).
            return self.read_off(pp, plan, step, name, (start, end), segment)
        through = [line for line in step.lines if line.through == start]
        if len(through) > 1 and side < len(step.lines) and step.lines[side].through == start:
            through = [step.lines[side]]
        direction = self.line(through[0].along) if through else "—"
        return _Term(shown, "?", segment, direction)

    def read_off(self, pp: PlanPosition, plan: Plan, step: Step, name: str, ends: tuple[str, str], segment: str) -> _Term:
        """VBA or aBA^τ read off the plan: its segment's length, its modulus, square to AB; or a slider's VDD1 along
        the line of its guide the step gives."""
        start, end = ends
        value = abs(plan.points[end] - plan.points[start])
        modulus = f"{self.n(value)} {self.text['unit_m_per_s' if plan.kind == 'velocity' else 'unit_m_per_s2']}"
        along = [line.along for line in step.lines if line.through == start]
        if along:
            direction = self.line(along[0])
        else:
            pair = self.split(name[1:].removesuffix(_TANGENTIAL), pp)
            direction = self.line(LineMeaning("perpendicular", (pair[1], pair[0]))) if pair is not None else "—"
        return _Term(self.equation(name), modulus, f"{segment} = {self.on_plan(value / plan.scale)}", direction)

    def normal(self, pp: PlanPosition, plan: Plan, name: str, value: float) -> tuple[str, str]:
        """aBAⁿ = ω3²·lAB, directed from B to A."""
        unit = self.text["unit_m_per_s2"]
        pair = self.split(name[1:-1], pp)
        if pair is None:
            return f"{self.n(value)} {unit}", "—"
        moving, centre = pair
        direction = self.t("note_normal_direction", line=f"{centre}{moving}", start=moving, end=centre)
        length = abs(self.position(pp, moving) - self.position(pp, centre))
        link = self.link_of(pp, moving, centre)
        omega = pp.velocity.rates.get(link) if link is not None else None
        if omega is None or length == 0 or not math.isclose(omega * omega * length, value, rel_tol=_SAME,
                                                             abs_tol=_SAME * value + 1e-300):
            return f"{self.n(value)} {unit}", direction
        written = self.n(value)
        written_omega, written_length = reproducing(self, [abs(omega), length], [5, 5], written, 5,
                                                    lambda omega, length: omega * omega * length)
        modulus = (f"ω{link}²·l{centre}{moving} = {written_omega}²{self.text['times']}{written_length} = "
                   f"{written} {unit}")
        return modulus, direction

    def coriolis(self, pp: PlanPosition, name: str, value: float) -> tuple[str, str]:
        """aA4A3ᵏ = 2·ω3·VA4A3, the relative velocity turned by 90° in the sense of ω."""
        unit = self.text["unit_m_per_s2"]
        body = name[1:-1]
        relative = None
        for step in pp.velocity.steps:
            for vector in step.vectors:
                if vector.meaning == "v" + body:
                    relative = abs(pp.velocity.points[vector.end] - pp.velocity.points[vector.start])
        if relative is None:
            return f"{self.n(value)} {unit}", "—"
        # The link the name ends with (A4A3: the block 3), else one it names (E8E: the slotted link 8), else any.
        candidates = [int(number) for number in reversed(re.findall(r"\d+", body))] + sorted(pp.velocity.rates)
        link = next((k for k in candidates if k in pp.velocity.rates
                     and math.isclose(2 * abs(pp.velocity.rates[k]) * relative, value, rel_tol=_SAME)), None)
        if link is None:
            return f"{self.n(value)} {unit}", "—"
        omega = pp.velocity.rates[link]
        # A block turns with the link it slides on: its ω is that link's, which the note has worked out.
        worked = [int(reading.quantity[5:]) for reading in pp.readings if reading.quantity.startswith("omega")]
        twin = next((k for k in worked if k != link and math.isclose(pp.velocity.rates[k], omega, rel_tol=_SAME)), None)
        same = "" if twin is None or link in worked else f" (ω{link} = ω{twin})"
        written = self.n(value)
        modulus = (f"2·ω{link}·V{body}{same} = {worked_product(self, [2.0, abs(omega), relative], written)} = "
                   f"{written} {unit}")
        return modulus, self.t("note_coriolis_direction", relative=f"V{body}", link=link,
                               sense=self.sense(omega))

    def split(self, text: str, pp: PlanPosition) -> tuple[str, str] | None:
        """``"BA"`` → ``("B", "A")``: two point names whose positions are known, longest names first."""
        names = sorted(set(_places(pp)) | {m for m in _guide_points(text)}, key=len, reverse=True)
        for first in names:
            if text.startswith(first) and len(text) > len(first):
                rest = text[len(first):]
                if self.position(pp, rest) is not None and self.position(pp, first) is not None:
                    return first, rest
        return None

    def position(self, pp: PlanPosition, name: str) -> complex | None:
        """Where a point is at the instant; a link's point over a joint (A3, B4) is where that joint is."""
        places = _places(pp)
        if name in places:
            return places[name]
        match = re.fullmatch(r"(.+?)(\d+)", name)
        if match and match.group(1) in places:
            return places[match.group(1)]
        return None

    def link_of(self, pp: PlanPosition, first: str, second: str) -> int | None:
        """The link that carries both points on the velocity plan (its members)."""
        a, b = self.position(pp, first), self.position(pp, second)
        for link, members in sorted(pp.velocity.members.items()):
            if link == self.frame:
                continue
            where = [position for position, _ in members]
            if a in where and b in where:
                return link
        return None

    # The similarity theorem.

    def similarity(self, pp: PlanPosition, plan: Plan, similar: Similarity) -> str:
        """``as3 = ab·lAS3/lAB = …`` for a point on the line of two known images, and the second side of the
        triangle for a point off it; the two similar figures when it cannot be read that way."""
        letter = similar.letter
        if not similar.basis:
            return (self.turning_with(pp, plan, similar)
                    or self.t("note_turns_with", point=letter, link=similar.link, other=similar.turns_with))
        fallback = letter + self.text["colon"] + similar.figures
        (la, lb), (na, nb), target = similar.basis, similar.basis_points, similar.point
        pa, pb, where = self.position(pp, na), self.position(pp, nb), self.position(pp, target)
        if pa is None or pb is None or where is None:
            return fallback
        if similar.link in self.mechanism.translating:
            return self.t("note_translating_image", point=self.letter(plan, letter), link=similar.link,
                          other=self.letter(plan, la))
        span = abs(pb - pa)
        if span == 0:
            return fallback
        base_mm = self.length_mm(plan, la, lb)
        sides = [(la, na, abs(where - pa))]
        off_line = abs(((where - pa) * (pb - pa).conjugate()).imag) > 1e-9 * span * span
        if off_line:
            sides.append((lb, nb, abs(where - pb)))
        parts = []
        for start, name, length in sides:
            value = base_mm * length / span
            if not math.isclose(value, self.length_mm(plan, start, letter), rel_tol=_SAME, abs_tol=1e-9):
                return fallback
            parts.append(f"{self.segment(plan, start, letter)} = {self.segment(plan, la, lb)}·l{name}{target}/l{na}{nb}"
                         f" = {self.mm(base_mm)}{self.text['times']}{self.n(length)}/{self.n(span)} = "
                         f"{self.drawn_mm(value)}")
        line = self.letter(plan, letter) + self.text["colon"] + self.text["semicolon"].join(parts)
        if not off_line and ((where - pa) * (pb - pa).conjugate()).real < 0:
            # Laid off from the first image toward the second, the length alone would put the image on the wrong
            # side: a Whitworth lever's tail D behind its pivot C, whose d lies beyond p from a4.
            line += self.text["semicolon"] + self.t("note_similar_beyond", point=self.letter(plan, letter),
                                                    line=self.segment(plan, lb, la), start=self.letter(plan, la),
                                                    target=target, link_line=f"{nb}{na}", start_point=na)
        if off_line:
            line += self.text["semicolon"] + self.t("note_similar_triangle", plan=self.segment(plan, la, lb) + self.letter(plan, letter),
                                  link=f"{na}{nb}{target}")
        return line

    def turning_with(self, pp: PlanPosition, plan: Plan, similar: Similarity) -> str | None:
        """A point of a link that turns with another (a point of an RPR's block on the lever) laid off as a student
        lays it: from its link's one image, ``ae = pa4·lAE/lCA4`` turned from AE as pa4 is from CA4; None where
        the plan's members do not give that."""
        other = similar.turns_with
        target = self.position(pp, similar.point)
        own = [(where, mark) for where, mark in plan.members.get(similar.link, ()) if mark != similar.letter]
        pairs = [(first, second) for k, first in enumerate(plan.members.get(other, ()))
                 for second in plan.members.get(other, ())[k + 1:] if first[0] != second[0]]
        if other is None or target is None or not own or not pairs:
            return None
        (start, start_mark) = own[0]
        (pa, la), (pb, lb) = max(pairs, key=lambda pair: abs(pair[1][0] - pair[0][0]))
        name = {mark: self.name_of(pp, plan, mark, where) for where, mark in ((start, start_mark), (pa, la), (pb, lb))}
        span, reach = abs(pb - pa), abs(target - start)
        value = self.length_mm(plan, la, lb) * reach / span
        if reach == 0 or not math.isclose(value, self.length_mm(plan, start_mark, similar.letter), rel_tol=_SAME):
            return None
        own_line, other_line = f"{name[start_mark]}{similar.point}", f"{name[la]}{name[lb]}"
        laid = (f"{self.segment(plan, start_mark, similar.letter)} = {self.segment(plan, la, lb)}·l{own_line}/"
                f"l{other_line} = {self.mm(self.length_mm(plan, la, lb))}{self.text['times']}{self.n(reach)}/"
                f"{self.n(span)} = {self.drawn_mm(value)}")
        return self.t("note_turns_with_laid", point=self.letter(plan, similar.letter), link=similar.link,
                      other=other, laid=laid, own=own_line, other_segment=self.segment(plan, la, lb),
                      others=other_line)

    def name_of(self, pp: PlanPosition, plan: Plan, mark: str, where: complex) -> str:
        """The mechanism's name of the point at ``where`` whose image is ``mark`` (``A4`` for ``a4``)."""
        return next((name for name, image in plan.images.items()
                     if image == mark and self.position(pp, name) == where), mark.upper())

    # Values read off the plan.

    def readings(self, pp: PlanPosition, plan: Plan) -> None:
        chosen = [reading for reading in pp.readings if reading.plan == plan.kind]
        if not chosen:
            return
        lines = [f"- {self.reading(pp, plan, reading)}" for reading in chosen]
        if plan.kind == "acceleration":
            lines += [f"- {self.epsilon_of_another(pp, link, other)}"
                      for link, other in sorted(epsilon_of_another(pp.plans, pp.readings).items())]
        self.para(self.t("note_read_off"), *lines)
        key = "note_omega_sense" if plan.kind == "velocity" else "note_epsilon_sense"
        if any(reading.quantity.startswith(("omega", "epsilon")) for reading in chosen):
            self.para(self.text[key])

    def reading(self, pp: PlanPosition, plan: Plan, reading: Reading) -> str:
        symbol = "μV" if plan.kind == "velocity" else "μa"
        segment = self.segment(plan, *reading.segment)
        millimetres = reading.millimetres(pp.plans)
        value = reading.value(pp.plans)
        if reading.quantity.startswith(("omega", "epsilon")):
            link = int(re.sub(r"\D", "", reading.quantity))
            angular = reading.quantity.startswith("omega")
            unit = self.text["unit_rad_per_s" if angular else "unit_rad_per_s2"]
            name, length = self.angular_names(pp, plan, reading, link)
            through = f"{name}/{length} = " if name else ""
            result = self.n(abs(value))
            drawn, scale, arm = self.reading_factors(millimetres, plan.scale, result, reading.length)
            text = (f"{quantity_symbol(reading.quantity)} = {through}{segment}·{symbol}/{length} = "
                    f"{drawn}{self.text['times']}{scale}/{arm} = "
                    f"{result} {unit}{self.with_sense(value)}{self.short_mark(millimetres, segment)}")
            if not angular:
                # Accelerated or decelerated only where both ω and ε are more than the plans' rounding: an ε of
                # 1e-16 where it is nought (a lever passing its greatest ω) is written 0 and has no sense. Every ε
                # of a plan may be such a residue (a uniform crank): ε is measured against ω² as well.
                omegas = pp.velocity.rates.values()
                omega = pp.velocity.rates.get(link, 0.0)
                if _beyond_rounding(value, [*plan.rates.values(), *(w * w for w in omegas)]) and \
                        _beyond_rounding(omega, omegas):
                    key = "note_accelerated" if omega * value > 0 else "note_decelerated"
                    text += self.text["semicolon"] + self.t(key, link=link)
            return text
        unit = self.text["unit_m_per_s" if plan.kind == "velocity" else "unit_m_per_s2"]
        result = self.n(abs(value))
        drawn, scale = self.reading_factors(millimetres, plan.scale, result)
        return (f"{reading.quantity} = {segment}·{symbol} = {drawn}{self.text['times']}{scale} = "
                f"{result} {unit}{self.short_mark(millimetres, segment)}")

    def epsilon_of_another(self, pp: PlanPosition, link: int, other: int) -> str:
        """``ε3 = ε4 = …``: link ``link`` turns with link ``other``, whose tangential component is the only one the
        plan lays off for either, so a student takes ε3 for the inertia loads from ε4's reading."""
        value = next(reading for reading in pp.readings if reading.quantity == f"epsilon{other}").value(pp.plans)
        return self.t("note_epsilon_of_another", link=link, other=other,
                      value=f"{self.n(abs(value))} {self.text['unit_rad_per_s2']}", sense=self.with_sense(value))

    def angular_names(self, pp: PlanPosition, plan: Plan, reading: Reading, link: int) -> tuple[str, str]:
        """The relative vector and the length an ω or ε is read from: (VBA, lAB), (aBA^τ, lAB)."""
        length = "l"
        if plan.kind == "velocity":
            same = [r for r in pp.readings if r.plan == plan.kind and set(r.segment) == set(reading.segment)
                    and not r.quantity.startswith(("omega", "epsilon"))]
            same.sort(key=lambda r: r.points is None)
            chosen = same[0] if same else None
            if chosen is not None and chosen.points is not None:
                moving, centre = chosen.points
                length = f"l{centre}{moving}"
            else:
                # No velocity of the pair read off (a triad's ab): the segment's ends still name the length.
                names = [self.name_on(pp, plan, link, letter) for letter in reading.segment]
                if None not in names:
                    length = f"l{names[0]}{names[1]}"
            return (chosen.quantity if chosen is not None else ""), length
        for step in plan.steps:
            for vector in step.vectors:
                if (vector.start, vector.end) == reading.segment and vector.meaning.endswith(_TANGENTIAL):
                    pair = self.split(vector.meaning[1:-len(_TANGENTIAL)], pp)
                    if pair is not None:
                        length = f"l{pair[1]}{pair[0]}"
                    return vector.meaning, length
        return "", length

    def name_on(self, pp: PlanPosition, plan: Plan, link: int, letter: str) -> str | None:
        """The mechanism's name of ``link``'s point whose image is ``letter``."""
        for position, member in plan.members.get(link, ()):
            if member != letter:
                continue
            for name, where in _places(pp).items():
                image = plan.images.get(name, image_name(name) if name in plan.auxiliary else None)
                if where == position and image == letter:
                    return name
                if where == position and letter == f"{image_name(name)}{link}":
                    # The link's own point under a joint of another link (E6 under the block's pin E), as the
                    # vector equations name it.
                    return f"{name}{link}"
        return None

    def values_table(self, pp: PlanPosition, kind: str) -> None:
        """The plan's values beside the analytic solution, as constructed."""
        plan = pp.plans[kind]
        exact = {row.quantity: row.analytic for row in pp.errors if row.source == "construction"}
        others = epsilon_of_another(pp.plans, pp.readings) if kind == "acceleration" else {}
        rows = []
        for reading in pp.readings:
            if reading.plan != kind:
                continue
            cells = [self.segment(plan, *reading.segment), self.on_plan(reading.millimetres(pp.plans)),
                     self.n(reading.value(pp.plans))]
            rows.append([quantity_symbol(reading.quantity), *cells,
                         self.n(exact[reading.quantity]) if reading.quantity in exact else "—",
                         unit_of(reading.quantity, self.text)])
            # A link that turns with this one (an RPR's rod) has its ω row on the velocity plan; its ε is this
            # reading, written as such under it, beside its own exact value, so that the table lists every link's ε.
            for link in sorted(link for link, other in others.items() if f"epsilon{other}" == reading.quantity):
                epsilon = float(at(self.analysis.motion.link(link).epsilon, pp.index))
                rows.append([f"{quantity_symbol(f'epsilon{link}')} = {rows[-1][0]}", *cells, self.n(epsilon),
                             unit_of(reading.quantity, self.text)])
        if not rows:
            return
        length = f"{self.t('column_length')}{self.text['comma']}{self.text['millimetre']}"
        header = [self.t("column_quantity"), self.t("column_segment"), length, self.t("column_by_plan"),
                  self.t("column_analytic"), self.t("column_unit")]
        caption = self.t(f"note_{kind}_table", number=pp.number)
        self.para(self.t(f"note_{kind}_table_formula"))
        self.table(caption, header, rows, "llrrrl")

    # The errors of the plans.

    def slips(self, position: VelocityPosition) -> None:
        """Under a position's error table, its hand readings far off the construction, if any."""
        slipped = slip_lines(self.analysis, position, self.mark, in_note=True)
        if slipped:
            self.para(*slipped)

    def errors_intro(self) -> str:
        """What δ and the error tables' columns are; the measured column only where a table has it, else the
        reader looks for a column the intro names and finds none."""
        intro = self.t("note_errors_intro", formula=self.text["errors_formula"],
                       precision=self.n(self.analysis.scene.drawing.drafting_precision))
        positions = (*self.analysis.plans, *self.analysis.velocity_plans)
        if any(row.source == "measured" for position in positions for row in position.errors):
            intro += " " + self.t("note_errors_measured")
        bound = measured_bound(self.analysis, self.mark)
        return f"{intro} {bound}" if bound else intro

    def errors(self, section: int) -> None:
        self.heading(2, self.t("note_errors"), section)
        intro = self.errors_intro()
        undefined = undefined_errors(self.analysis, self.analysis.plans)
        intro += f" {undefined}" if undefined else ""
        others = epsilons_of_others(self.analysis)
        intro += f" {others}" if others else ""
        if has_reactions(self.analysis):
            intro += f" {reactions_intro(self.analysis, in_note=True)} {self.reactions_named()}".rstrip()
        self.para(intro)
        for plan in self.analysis.plans:
            self.captioned(self.t("note_errors_table", number=plan.number),
                           error_table_lines(self.analysis, plan, self.mark))
            self.slips(plan)
        self.found["errors"] = (largest_errors(self.analysis, False, self.mark),
                                largest_errors(self.analysis, True, self.mark))

def _body(term: str) -> tuple[str, str]:
    """``"vBA"`` → ``("v", "BA")``; the component's suffix is dropped."""
    for suffix in (_NORMAL, _CORIOLIS, _TANGENTIAL, _RELATIVE):
        term = term.removesuffix(suffix)
    return term[:1], term[1:]


def _places(pp: PlanPosition) -> dict[str, complex]:
    """The scene's points at the instant and the plans' auxiliary points (Assur's Σ6), by name."""
    return {**pp.positions, **pp.velocity.auxiliary}


def _guide_points(text: str) -> set[str]:
    """Names like ``B4`` (a link's point over a joint) that occur in ``text``."""
    return set(re.findall(rf"[{CAPITALS}][a-z]?\d+", text))


__all__ = ["note_html", "note_markdown"]
