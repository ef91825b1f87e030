"""The scene file: TOML in, a frozen :class:`Scene` out, every key checked.

This module checks syntax, types and ranges, key by key, and rejects keys it
does not know.  Whether the names refer to each other correctly (the
structure of the mechanism) is checked by :mod:`graphplan.mechanism`.
"""

from __future__ import annotations

import codecs
import datetime
import difflib
import functools
import itertools
import json
import math
import os
import re
import tomllib
import unicodedata
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, BinaryIO

from .choices import LOCALES, OUTPUT_PIECES, SHEETS
from .errors import SceneError, as_written
from .groups import DRIVERS, GROUPS, Driver, Group, Guide
from .groups.base import read_guide
from .lookalikes import described, difference, full_width, lookalike_hint
from .lookalikes import plain as lookalike_plain
from .reader import (
    Table,
    check_choice,
    check_choices,
    check_int,
    check_number,
    check_str,
    check_xy,
    refuse_control_characters,
    required_purpose,
)
from .rounding import rounded_up
from .scales import LARGEST_PAPER_MM
from .scene_file import MAX_SCENE_BYTES, STDIN, bytes_at, stdin_bytes
from .table_keys import keys_of_other_tables
from .units import HEAVIEST_GRAVITY, gravity_unit

# The stages a scene's verbs run import the scene.  The rotor's and the vibration's readers are imported where a
# scene has their tables: a linkage's cold run never needs them, and they cost it 30 ms.
if TYPE_CHECKING:
    from .analysis import Analysis
    from .machine_dynamics import MachineDynamics
    from .motion import Motion
    from .notebook import Drawing as NotebookDrawing
    from .notebook import PositionPlans, RotorBalancing, VibrationResponse
    from .rotor_balancing import BalancingSpec
    from .run import Run
    from .vibration import VibrationSpec

# A run's cost grows in step with its positions, about 2 ms of CPU and 28 kB of memory each beside 6 s of its own
# (bench/positions_count.py): 20 000 run in about a minute.  100 000 took 14 minutes and 2.8 GB on a shared
# machine, with the console silent, which a student takes for a hang.
MAX_POSITIONS = 20_000
# A sheet of the ISO A series the drawings are not laid out on (A0, A5): told so, not guessed at as the nearest name.
_OTHER_A_SIZE = re.compile(r"[AaАа][0-9]+")
SENSES = ("ccw", "cw", "forward", "backward")
# Each sense's opposite: a link's other stroke.
OTHER_SENSE = {"ccw": "cw", "cw": "ccw", "forward": "backward", "backward": "forward"}
STROKES = ("working", "idle", "always")
# The most velocity plans of every position one scene draws: a course project draws 12, a fine one 24 or 36.
MOST_VELOCITY_PLANS = 48
# The tables that describe a mechanism: without [frame] and [driver] they have nothing to belong to.
# ([dynamics] may do without one: a flywheel sized from a load diagram alone.)
LINKAGE_KEYS = ("groups", "points", "links", "loads", "friction", "positions", "measured", "forces")
INERTIA_FORMS = ("couple", "displaced")


@dataclass(frozen=True)
class PointSpec:
    """A named point fixed on ``link``: ``at`` m from ``start`` toward ``toward``, then ``offset`` m to the left."""

    name: str
    where: str
    link: int
    start: str
    toward: str
    at: float
    offset: float


@dataclass(frozen=True)
class LinkSpec:
    number: int
    where: str
    mass: float
    centre: str | None
    inertia: float


@dataclass(frozen=True)
class LoadSpec:
    """An external force or moment; ``during`` is a stroke name or a (from, to) window of the working stroke.

    With a ``diagram`` (share of the working stroke, value) the load follows
    it piecewise-linearly over the window its shares span, and ``value`` is
    its largest magnitude.  A spring has no ``value`` (None): its force is its
    length's at each position (:func:`graphplan.loads.given_value` gives any
    load's there).  ``stroke`` names the link and sense whose strokes
    ``during`` and the diagram are of, where they are not the working link's
    (a second cylinder's piston, whose strokes come at other crank angles).
    """

    where: str
    kind: str
    link: int
    value: float | None
    resisting: bool
    during: str | tuple[float, float]
    point: str | None
    angle_deg: float | None
    diagram: tuple[tuple[float, float], ...] | None = None
    stroke: Working | None = None
    # A force along the line from this point to its own (a cylinder or a spring pinned there), in place of an angle:
    # the line turns as the mechanism moves.
    along: str | None = None
    # A spring along that line (N/m, m), in place of a value: its force is its length's, k·(L − L0) at each position,
    # so ``value`` is None for it, which no sum takes for a force of 0 N.
    stiffness: float | None = None
    free_length: float | None = None

    @property
    def spring(self) -> bool:
        """Whether the load is a spring, whose force k·(L − L0) its length sets, not a value."""
        return self.stiffness is not None

    @property
    def ends(self) -> frozenset[str] | None:
        """The two points of the spring or cylinder of a force ``along`` a line, None for another load.

        A cylinder between two moving links is two loads, one at each end along the other's point: the two have
        the same ends, and are one cylinder to draw.
        """
        return frozenset((self.along, self.point)) if self.along is not None and self.point is not None else None


@dataclass(frozen=True)
class FrictionSpec:
    """Friction in the pair at ``joint`` (between ``links``, when the joint has several pairs).

    ``f`` is the coefficient; a turning pair needs its journal ``radius`` (m),
    which makes the friction circle ρ = f·r; a sliding pair in a V-guide
    gives the groove's half-angle θ (radians), which makes f' = f / sin θ.
    """

    where: str
    joint: str
    links: tuple[int, int] | None
    f: float
    radius: float | None
    groove_half_angle: float | None


@dataclass(frozen=True)
class Working:
    link: int
    sense: str
    where: str


@dataclass(frozen=True)
class Positions:
    count: int
    start: str | float
    number_from: int
    working: Working | None
    plans: tuple[int, ...]
    # The positions whose velocity plans are drawn too, all at one μV (the course project's plans of every
    # position, from which the equivalent model is read): ``velocity_plans = "all"`` or a list of numbers.
    velocity_plans: tuple[int, ...] = ()
    # Whether the scene writes start, 0 included: a rocking crank's or a slider's positions refuse it written.
    start_given: bool = False


@dataclass(frozen=True)
class Drawing:
    length_scale: float | None
    velocity_pole: float | None
    acceleration_pole: float | None
    velocity_scale: float | None
    acceleration_scale: float | None
    drafting_precision: float
    sheet: str
    # μF of every force polygon (N/mm), as a hand drawing fixes it; None: chosen to fill the polygon's field.
    force_scale: float | None = None
    # Whether the scene names its sheet: only then are the sheets drawn without being asked for.
    sheet_given: bool = False
    # mm drawn for the driver's velocity pa on the velocity plans of every position (positions.velocity_plans);
    # None: the standard μV at which the largest of them fits its field.
    velocity_plans_pole: float | None = None


@dataclass(frozen=True)
class Project:
    """What only the student knows: who made the project, who checks it, what it is filed as.

    The sheets' title block and the note's head carry it; a field left out leaves its box blank.
    """

    author: str = ""
    checked_by: str = ""
    approved_by: str = ""
    organization: str = ""
    designation: str = ""
    # A TOML date (written the locale's way where it is printed) or the text to print as it stands.
    date: datetime.date | str = ""


def _on_a_scene(verb: Callable[..., Any]) -> Callable[..., Any]:
    """``verb``, a scene's method, refusing what is not a scene as the plain functions do (:func:`not_a_scene`):
    ``Scene.analyse("x.toml")`` was told that a string has no ``has_linkage``."""

    @functools.wraps(verb)
    def checked(self: Any, *args: Any, **kwargs: Any) -> Any:
        if not isinstance(self, Scene):
            raise not_a_scene(f"Scene.{verb.__name__}", self)
        return verb(self, *args, **kwargs)

    return checked


@dataclass(frozen=True)
class Scene:
    """Everything one scene file says, checked for syntax and range."""

    title: str
    locale: str
    gravity: float
    frame_link: int
    frame_points: Mapping[str, complex]
    frame_lines: Mapping[str, Guide]
    driver: Driver | None
    groups: tuple[Group, ...]
    points: tuple[PointSpec, ...]
    links: Mapping[int, LinkSpec]
    loads: tuple[LoadSpec, ...]
    friction: tuple[FrictionSpec, ...]
    positions: Positions
    drawing: Drawing
    # By position: each plan's (and the polygons') readings in mm by segment, and "balancing", a value (N·m or N).
    measured: Mapping[int, Mapping[str, Mapping[str, float] | float]]
    include: tuple[str, ...] | None
    source: str = "<scene>"
    # "couple": Fu at the centre and Mu; "displaced": one resultant Fu displaced by h = Mu/Fu.
    inertia: str = "couple"
    balancing: BalancingSpec | None = None
    vibration: VibrationSpec | None = None
    dynamics: Any = None  # flywheel.DynamicsSpec: the equivalent model, the flywheel, the equation of motion
    project: Project = Project()

    def __repr__(self) -> str:
        # The dataclass's own repr printed every table: 3 000 characters on a notebook's line.
        parts = [f"a mechanism at {self.positions.count} positions"] if self.has_linkage else []
        parts += [f"[{name}]" for name, part in (("dynamics", self.dynamics), ("balancing", self.balancing),
                                                 ("vibration", self.vibration)) if part is not None]
        return f"<Scene {self.title!r} from {self.source}: {', '.join(parts) or 'nothing to work out'}>"

    @property
    def guides(self) -> list[Guide]:
        """Every guide the scene writes: its frame lines, then the driver's and each group's, in the scene's order."""
        solvers = [solver for solver in (self.driver, *self.groups) if solver is not None]
        return [*self.frame_lines.values(), *(guide for solver in solvers for guide in solver.guides())]

    @property
    def own_words(self) -> tuple[str, ...]:
        """What a drawing quotes as written, never put into its language: the title and the loads' names (a link's
        second load F4.2 is no decimal number, to be written F4,2 in Russian)."""
        from .loads import external_names

        return (self.title, *external_names(self.loads))

    @property
    def has_linkage(self) -> bool:
        """Whether the scene describes a mechanism (a rotor, a vibrating machine or a load diagram alone does not)."""
        return self.driver is not None

    # The notebook's verbs.  They import the stages they run when called: a scene is read first of all.
    @_on_a_scene
    def solve(self, driver=None) -> Motion:
        """The analytic motion at the scene's positions, or at ``driver`` (crank angles, rad; slider, m)."""
        from . import solve

        return solve(self, driver)

    @_on_a_scene
    def analyse(self) -> Analysis:
        """The whole analysis of the scene's mechanism (:func:`graphplan.analysis.analyse`); what the scene seems to
        have mistyped (a speed in rpm, lengths in mm) is warned of with a ``UserWarning``, as the command line warns."""
        from .analysis import analyse
        from .notebook import warn_of_slips

        if not self.has_linkage:
            raise missing_part(self, "mechanism")
        return warn_of_slips(analyse(self))

    @_on_a_scene
    def machine_dynamics(self) -> MachineDynamics:
        """The scene's ``[dynamics]`` worked out as a run works it out: ``.model`` (Je, Me over the cycle),
        ``.flywheel`` (None without δ) and ``.motion`` (the equation of motion integrated; None without a motor)."""
        from .machine_dynamics import MachineDynamics

        if self.dynamics is None:
            raise missing_part(self, "dynamics")
        return MachineDynamics(self.analyse() if self.has_linkage else self)

    @_on_a_scene
    def plan(self, number: int) -> PositionPlans:
        """The plans of position ``number`` (:func:`graphplan.notebook.plan`); Jupyter shows its plan sheet."""
        from .notebook import plan

        if not self.has_linkage:
            raise missing_part(self, "mechanism")
        return plan(self, number)

    @_on_a_scene
    def balance(self) -> RotorBalancing:
        """The scene's ``[balancing]`` rotor balanced as a run balances it: ``.planes`` (each correction's m·r and
        angle), ``.results`` (``results.json``'s ``balancing``), ``.drawing`` (the polygons; Jupyter shows them)."""
        from .notebook import RotorBalancing

        if self.balancing is None:
            raise missing_part(self, "balancing")
        return RotorBalancing(self)

    @_on_a_scene
    def vibration_response(self) -> VibrationResponse:
        """The scene's ``[vibration]`` machine's steady vibration as a run works it out: ``.response`` (SI),
        ``.results`` (``results.json``'s ``vibration``), ``.magnification_plot``, ``.transmissibility_plot``."""
        from .notebook import VibrationResponse

        if self.vibration is None:
            raise missing_part(self, "vibration")
        return VibrationResponse(self)

    @_on_a_scene
    def results(self, *, only: Sequence[str] | None = None, locale: str | None = None,
                sheet: str | None = None) -> dict[str, Any]:
        """``results.json`` as :meth:`write` with the same ``only``, ``locale`` and ``sheet`` writes it, as a dict,
        no file written: the numbers of a scene with a mechanism or without one, or the refusal :meth:`write` gives
        (the drawings are laid out for it, so a run's time).  What the scene seems to have mistyped, and each outcome
        :meth:`write` warns of, is warned of with a ``UserWarning``."""
        from .notebook import warn_of, warn_of_slips
        from .run import PYTHON, results

        _refuse_letter_lists(only=only)
        return results(self, only, locale, sheet, options=PYTHON, analysed=warn_of_slips, warn=warn_of)

    @_on_a_scene
    def drawings(self, *, only: Sequence[str] | None = None, figures: bool = False, locale: str | None = None,
                 sheet: str | None = None) -> dict[str, NotebookDrawing]:
        """Every SVG file :meth:`write` with the same ``only``, ``figures``, ``locale`` and ``sheet`` writes, by its
        name (``diagrams.svg``, ``sheet_1.svg``, ``motion.svg``), each a drawing Jupyter shows and that saves as
        SVG, PNG or PDF, no file written; what the scene seems to have mistyped, and each outcome :meth:`write`
        warns of, warned of with a ``UserWarning``."""
        from .notebook import Drawing, warn_of, warn_of_slips
        from .report.plot_style import PLOT_DPI
        from .run import PYTHON, svg_files

        _refuse_letter_lists(only=only)
        _refuse_other_than_bool(figures)
        made = svg_files(self, only, bool(figures), locale, sheet, options=PYTHON, analysed=warn_of_slips,
                         warn=warn_of)
        return {name: Drawing(svg, png_dpi=PLOT_DPI if plot else None) for name, (svg, plot) in made.items()}

    @_on_a_scene
    def write(self, folder: str | Path, *, only: Sequence[str] | None = None, formats: Sequence[str] = ("svg",),
              figures: bool = False, locale: str | None = None, sheet: str | None = None) -> Run:
        """Write the scene's run to ``folder`` as ``graphplan run SCENE --out FOLDER`` writes it, the same files
        refused and warned of alike (:func:`graphplan.run.run`): ``only``, ``formats``, ``figures``, ``locale``
        and ``sheet`` are the command line's ``--only``, ``--format``, ``--figures``, ``--locale`` and ``--sheet``.
        The folder is written whole or not at all.  Returns the paths written (``.files``) and the lines the
        command line warns with (``.warnings``)."""
        from .run import PYTHON, run

        if not isinstance(folder, str | os.PathLike):  # pathlib's error named neither write nor its folder
            raise TypeError(f"write takes the folder to write, a path such as 'ratchet' (got {folder!r})")
        _refuse_letter_lists(only=only, formats=formats)
        _refuse_other_than_bool(figures)
        # A notebook has no shell to expand ~: the run went to a folder named ~ in the working folder.
        return run(self, Path(folder).expanduser(), only, formats, bool(figures), locale, sheet, options=PYTHON)


def _refuse_letter_lists(**lists: Any) -> None:
    """A TypeError for each of ``lists`` (``only``, ``formats``) given as one name, not a list of names."""
    for name, value in lists.items():
        if isinstance(value, str | bytes):  # taken letter by letter, "svg" would be refused as 's', 'v', 'g'
            shown = value if isinstance(value, str) else value.decode("utf-8", "replace")
            raise TypeError(f"{name} is a list of names: {name}=[{shown!r}], not {name}={value!r}")
        if not isinstance(value, Iterable) and not (name == "only" and value is None):
            example = {"only": "note", "formats": "png"}[name]
            raise TypeError(f"{name} is a list of names: {name}=[{example!r}] (got {value!r})")


def _refuse_other_than_bool(figures: Any) -> None:
    import numpy as np

    # A string is true: figures="no" drew the figures.
    if not isinstance(figures, bool | np.bool_):
        raise TypeError(f"figures is True or False (got {figures!r})")


# What each verb of a scene needs, and the verb that works it out, for the error that says what else to call.
_PARTS = {"mechanism": ("mechanism ([frame] and [driver])", "its mechanism", "analyse"),
          "dynamics": ("[dynamics] table", "its [dynamics]", "machine_dynamics"),
          "balancing": ("[balancing] table", "its [balancing]", "balance"),
          "vibration": ("[vibration] table", "its [vibration]", "vibration_response")}


def missing_part(scene: Scene, part: str) -> SceneError:
    """The error of a verb asked of ``scene`` without the ``part`` it works out (``mechanism``, ``dynamics``,
    ``balancing``, ``vibration``): what the scene lacks, and the verbs that work out what it has instead."""
    has = {"mechanism": scene.has_linkage, "dynamics": scene.dynamics is not None,
           "balancing": scene.balancing is not None, "vibration": scene.vibration is not None}
    instead = [f"for {what} call scene.{verb}()" for name, (_, what, verb) in _PARTS.items() if has[name]]
    lacking = f"the scene has no {_PARTS[part][0]}" + (f"; {', '.join(instead)}" if instead else "")
    if part == "mechanism":  # the key a mechanism begins with, as a scene file without it is told
        return SceneError("driver", f"is required but missing: {lacking}")
    return SceneError(part, lacking)


def not_a_scene(verb: str, value: Any) -> TypeError:
    """The error of ``verb`` given something other than a scene: the value shown where it is short (a mechanism's
    repr printed its whole scene, 3 000 characters); where it is a scene file's path, to read it first; where it has
    a scene, where that is."""
    shown = repr(value)
    if len(shown) > 100:
        name = type(value).__name__
        shown = f"{'an' if name[:1] in 'AEIOU' else 'a'} {name}"
    if isinstance(value, str | os.PathLike):  # a scene file's path, given for the scene read from it
        hint = f"; read it first: graphplan.load({os.fspath(value)!r})"
    elif isinstance(getattr(value, "scene", None), Scene):
        hint = f"; its scene is {type(value).__name__.lower()}.scene"
    else:
        hint = ""
    return TypeError(f"{verb} takes a scene, as graphplan.load(path) reads it (got {shown}){hint}")


def check_sheet(value: Any, where: str) -> str:
    """A sheet format of :data:`SHEETS`; another size of the A series is told which sizes there are (difflib would
    offer A4 for A0, a sheet sixteen times smaller)."""
    # A Cyrillic А1 is A1 mistyped, which check_choice tells so.
    if (isinstance(value, str) and _OTHER_A_SIZE.fullmatch(value.strip())
            and lookalike_plain(value.strip()).upper() not in SHEETS):
        nearest = "A1 is the largest" if int(value.strip()[1:]) < 1 else "A4 is the smallest"
        raise SceneError(where, f"is a paper size the sheets are not laid out on: {nearest} of A1, A2, A3, A4 (or none "
                                f"for no course sheets)", value)
    return check_choice(value, where, SHEETS)


def load(path: str | Path | Mapping[str, Any]) -> Scene:
    """Read and check the scene file at ``path``, or a scene given as its tables: the mapping ``tomllib`` reads
    of a scene file, changed as a parameter study changes it, is checked as the file would be.

    Raises
    ------
    SceneError
        naming the key path and what is wrong, for any problem of the file.
    """
    if not isinstance(path, str | bytes | bytearray | os.PathLike | Mapping):
        raise TypeError(f"load takes the path of a scene file, or the scene's tables as a mapping (got "
                        f"{type(path).__name__}); graphplan.load_text(text) reads a scene given as TOML text")
    if isinstance(path, Mapping):
        return _read_scene(Table(_as_read(path, ""), ""), "<scene>")
    if isinstance(path, str) and not path.strip():  # Path("") is the working folder, told as «.: cannot be read»
        raise SceneError("", f"load takes the path of a scene file, such as 'ratchet.toml' (got an empty path "
                             f"{path!r})")
    if isinstance(path, bytes | bytearray) or (isinstance(path, str) and ("\n" in path or len(path) > 4096)):
        # TOML text given for a path: its error would quote the whole scene as a file name.
        raise SceneError("", "load takes the path of a scene file; for a scene given as TOML text use "
                             "graphplan.load_text(text)")
    path = Path(os.fsdecode(path)).expanduser()  # a notebook has no shell to expand ~
    return loads(bytes_at(path), source=str(path))


def load_stdin(stream: BinaryIO | None = None) -> Scene:
    """Read and check a scene piped into standard input (the command line's ``-``), named ``<stdin>`` in its
    errors; ``stream`` stands in for ``sys.stdin``'s bytes (:func:`graphplan.scene_file.stdin_bytes`)."""
    return loads(stdin_bytes(stream), source=STDIN)


def _as_read(value: Any, where: str) -> Any:
    """``value`` as tomllib would have read it from a file: tuples and numpy arrays as lists, numpy numbers as
    Python's, so that the checks of a scene's keys take a scene built in Python as they take a file."""
    import numpy as np

    if isinstance(value, Mapping):
        for key in value:
            if not isinstance(key, str):
                raise SceneError(where, f"has the key {key!r}; a scene's keys are strings")
        return {key: _as_read(item, f"{where}.{key}" if where else key) for key, item in value.items()}
    if isinstance(value, np.ndarray):  # element by element: tolist() expands single precision as item() does
        value = value[()] if value.ndim == 0 else list(value)
    if isinstance(value, list | tuple):
        return [_as_read(item, f"{where}[{index}]") for index, item in enumerate(value)]
    if isinstance(value, np.floating) and value.dtype.itemsize < 8:
        # As its digits read: np.float32(0.26).item() is 0.25999999046325684, where a file's 0.26 is 0.26.
        return float(str(value))
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, str | int | float | datetime.date | datetime.time):
        return value
    raise SceneError(where, f"is a {type(value).__name__}, which a scene file cannot hold (a number, a string, a "
                            "list or a table)")


def loads(data: bytes | str, source: str = "<scene>") -> Scene:
    """Read and check a scene given as TOML text or bytes."""
    if not isinstance(data, str | bytes):
        hint = "graphplan.load(tables) reads a scene given as its tables" if isinstance(data, Mapping) else \
            "graphplan.load(path) reads a file"
        raise TypeError(f"a scene is given as its TOML text, a str (got {type(data).__name__}); {hint}")
    if isinstance(source, os.PathLike):
        source = os.fspath(source)
    if not isinstance(source, str):  # the title's default, Path(source).stem, raised pathlib's TypeError
        raise TypeError(f"source names the scene in its errors, a string such as 'ratchet.toml' (got {source!r})")
    size = len(data) if isinstance(data, bytes) else len(data.encode("utf-8", "surrogatepass"))
    if size > MAX_SCENE_BYTES:
        raise SceneError(source, f"is {size} bytes; a scene may have at most {MAX_SCENE_BYTES}")
    if isinstance(data, bytes):
        kind = _binary_kind(data)
        if kind:
            raise SceneError(source, f"is not a text file but {kind}: a scene is TOML text, written in a plain text "
                                     "editor (graphplan new KIND writes one to begin from)")
        if _utf16(data):
            raise SceneError(source, "is not UTF-8 text but UTF-16: save it as UTF-8")
        try:
            data = data.decode("utf-8-sig")  # an editor's byte-order mark is no reason to refuse a scene
        except UnicodeDecodeError as error:
            raise SceneError(source, f"is not UTF-8 text ({_place_of(error)}); save it as UTF-8") from None
    data = data.removeprefix("\ufeff")
    # Line ends of a classic Mac editor, a carriage return alone, which TOML refuses; no TOML text has a carriage
    # return outside a CR LF, so reading each as a line end changes no scene that TOML reads.
    data = re.sub(r"\r(?!\n)", "\n", data)
    try:
        document = tomllib.loads(data)
    except tomllib.TOMLDecodeError as error:
        hint = _other_format(data) or _toml_hint(data, str(error))
        if not hint and "\n" not in data.strip() and data.strip().lower().endswith(".toml"):
            hint = f"; {data.strip()!r} looks like a file's name: graphplan.load(path) reads a scene file"
        raise SceneError(source, f"is not valid TOML: {error}{hint}") from None
    except RecursionError:  # tomllib reads nested arrays and tables by recursion
        raise SceneError(source, "nests arrays or tables too deeply to be read") from None
    if not document:
        told = "is empty" if not data.strip() else "holds nothing but comments"
        raise SceneError(source, f"{told}: a scene has a mechanism's tables ([frame], [driver], [[groups]]) or a "
                                 "machine's ([dynamics], [balancing], [vibration]); graphplan new KIND writes one to "
                                 "begin from")
    return _read_scene(Table(document, ""), source)


# The first bytes of the files a student may give for the scene: a drawing saved as an image, the note from Word.
_SIGNATURES = ((b"\x89PNG", "a PNG image"), (b"\xff\xd8\xff", "a JPEG image"), (b"GIF8", "a GIF image"),
               (b"%PDF", "a PDF document"), (b"PK\x03\x04", "a zip archive (a Word .docx, .xlsx or .odt is one)"),
               (b"\xd0\xcf\x11\xe0", "an Office document (.doc, .xls)"), (b"{\\rtf", "an RTF document (WordPad's)"),
               (b"\x1f\x8b", "a gzip archive"), (b"\x7fELF", "a program"))


def _binary_kind(data: bytes) -> str:
    """What ``data`` is where it is not text: a known file's signature, or control bytes no text has."""
    for signature, kind in _SIGNATURES:
        if data.startswith(signature):
            return kind
    head = data[:4096]
    if _utf16(head):
        return ""
    controls = sum(head.count(bytes([code])) for code in (*range(9), 11, *range(14, 32)))
    # Any encoding of text, Latin-1 or a Cyrillic code page as well as UTF-8, has no control bytes but tab and the
    # line ends; a few strays may be slips in a text, which the decoder or the reader names where they stand.
    return "binary data" if controls > max(8, len(head) // 100) else ""


def _other_format(data: str) -> str:
    """A hint where the text TOML refused is another format a scene might be written in: JSON or YAML."""
    text = data.strip()
    how = "not TOML: a scene writes key = value, and a table as [name] on a line of its own"
    if text.startswith("{"):  # a TOML document cannot begin with a brace
        return f"; it looks like JSON, {how}"
    if text.startswith("["):
        try:
            json.loads(text)
        except ValueError:
            return ""
        return f"; it looks like JSON, {how}"
    first = next((line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")), "")
    if first.rstrip() == "---" or re.fullmatch(r"[A-Za-z_][\w-]*\s*:(\s.*)?", first.rstrip()):
        return f"; it looks like YAML (key: value), {how}"
    return ""


def guides_without_angle(scene: Scene) -> list[str]:
    """A line for each guide whose ``angle`` the scene left out: it then runs at 0° (along +x on the frame, along its
    link's reference line on a moving link), which a forgotten angle makes another mechanism of without a word."""
    told = []
    for guide in scene.guides:
        if guide.line is not None or guide.angle_given:
            continue
        along = "+x" if guide.link in (None, scene.frame_link) else f"link {guide.link}'s reference line"
        told.append(f"{guide.where}: no angle, so the guide is taken at 0°, along {along}: write angle = 0.0 if "
                    "that is meant")
    return told


def links_without_mass(scene: Scene) -> list[str]:
    """A line for each link given a centre of mass and a moment of inertia but no mass: no body has J > 0 and m = 0,
    so the mass was forgotten, and the link's weight and inertia force are left out of the forces without a word.
    A link with J alone (a crank's with its flywheel) or centred on a frame point is taken as meant."""
    told = []
    for number, link in sorted(scene.links.items()):
        if link.mass == 0 and link.inertia > 0 and link.centre is not None and link.centre not in scene.frame_points:
            told.append(f"{link.where}: inertia = {link.inertia:g} kg·m² about the centre {link.centre} but no mass: "
                        f"link {number}'s weight and inertia force Fu{number} = −m{number}·a{link.centre} are left out "
                        f"(only its moment Mu{number} = −J{number}·ε{number} acts); give its mass")
    return told


def _utf16(data: bytes) -> bool:
    """Whether ``data`` is UTF-16 text: a byte-order mark, or zero bytes beside the letters of a Latin text (a TOML
    file has no zero byte of its own)."""
    head = data[:200]
    return data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)) or 0 < len(head) <= 4 * head.count(0)


def _place_of(error: UnicodeDecodeError) -> str:
    """Where the first byte that is not UTF-8 stands, as an editor counts: line and column, and the byte."""
    before = error.object[:error.start]
    line_start = before.rfind(b"\n") + 1
    column = len(before[line_start:].decode("utf-8")) + 1
    line = before.count(b"\n") + 1
    return f"line {line}, column {column}: byte 0x{error.object[error.start]:02X}"


# Typographic quotes an editor or an input method puts for the straight one TOML takes.
_QUOTES = {"“": '"', "”": '"', "„": '"', "«": '"', "»": '"', "‘": "'", "’": "'", "「": '"', "」": '"'}
# Ideographic punctuation that Unicode does not fold to ASCII.
_IDEOGRAPHIC = {"、": ",", "。": ".", "　": " "}


def _ascii_counterpart(character: str) -> tuple[str, str] | None:
    """The ASCII character a full-width or typographic one stands for, and what to call the one typed: a Chinese
    input method types '，' for ',', '＝' for '=', '１２' for 12 and “ ” for quotes."""
    if character in _QUOTES:
        return _QUOTES[character], "a typographic quote (a word processor's or an input method's)"
    if character in _IDEOGRAPHIC:
        return _IDEOGRAPHIC[character], "a Chinese or Japanese input method's punctuation"
    plain = unicodedata.normalize("NFKC", character)
    if full_width(character) and len(plain) == 1 and plain.isascii() and plain.isprintable():
        return plain, "a full-width character (a Chinese or Japanese input method's)"
    return None


def _toml_hint(data: str, message: str) -> str:
    """A hint where the line TOML stumbled on has a number with a decimal comma (``pb = 35,5``, as a Russian
    drawing writes it), which TOML reads as a number followed by something else; a character a value cannot have
    (a degree sign, the typographic minus graphplan's own notes print, a non-breaking space copied from Word or a
    PDF, an input method's full-width forms); or a key with a letter a bare TOML key cannot have (a Cyrillic р
    for the Latin p, or a Russian word for the English key)."""
    place = re.search(r"at line (\d+), column (\d+)", message)
    lines = data.splitlines()
    if place is None or not 0 < int(place[1]) <= len(lines):
        return ""
    line, column = lines[int(place[1]) - 1], int(place[2])
    comma = _decimal_comma(line)
    if comma:
        return f"; a decimal comma? TOML numbers take a point: write {comma[1]}.{comma[2]}"
    letter = line[column - 1:column]
    if not line[column - 1:].split("#")[0].strip():  # at the line's end: what was left open, or a key given again
        return _end_of_line_hint(line, message)
    unit = _unit_hint(lines[:int(place[1])], column)
    if unit:
        return unit
    code = f"'{letter}' (U+{ord(letter):04X})"
    if letter in _DEGREE_SIGNS:
        written = (line[:column - 1] + line[column:]).split("#")[0].strip()
        return f"; {code} is a degree sign: an angle is a number, in degrees, so drop it: write {written}"
    if letter in _DASHES:
        key = _dashed_key(line, column)
        if key is not None:
            # A frame line's name as the notes print it (x–x): told to type a hyphen, the student renamed the line
            # and then had every guide that names it refused.
            start, end = key
            return (f"; {described(letter)} in the key {line[start:end]}: a bare TOML key takes ASCII letters, "
                    f"digits, '-' and '_' alone, so quote the name to keep it as typed: write "
                    f"{line[:start].lstrip()}\"{line[start:end]}\"{line[end:].rstrip()}")
        return (f"; {described(letter)} is a typographic sign (as the notes print a minus), which TOML does not "
                "read: type the ASCII '-'")
    if letter != " " and unicodedata.category(letter or "x") == "Zs" and letter not in _IDEOGRAPHIC:
        return (f"; {code} is a non-breaking space (copied from Word or a PDF): type an ordinary space, or delete "
                "it")
    plain = _ascii_counterpart(letter)
    if plain:
        return f"; {code} is {plain[1]}: TOML reads the ASCII '{plain[0]}' where one belongs"
    if letter and not letter.isascii() and message.startswith("Invalid value"):
        # A value in other letters typed without its quotes (title = Привет): no key, so no key's hint.
        typed = line[column - 1:].split("#")[0].rstrip()
        return f'; a text is written in quotes: write {line[:column - 1]}"{typed}"'
    if letter and not letter.isascii():
        return _key_hint(line, column, data)
    return ""


# Units typed after a number, by what one of them is in the scene's own: metres, kg, N, s, degrees; and the
# drawing's and the readings' millimetres in [drawing] and [measured].
_UNITS = {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "kg": 1.0, "g": 1e-3, "n": 1.0, "kn": 1e3, "s": 1.0, "deg": 1.0,
          "degrees": 1.0,
          # As a Russian or Chinese student writes them (the scene's locales): without these, 175 мм was told
          # "write length = 175", a length a thousand times too long.
          "м": 1.0, "мм": 1e-3, "см": 1e-2, "кг": 1.0, "г": 1e-3, "н": 1.0, "кн": 1e3, "с": 1.0, "град": 1.0,
          "米": 1.0, "毫米": 1e-3, "厘米": 1e-2, "千克": 1.0, "公斤": 1.0, "克": 1e-3, "牛": 1.0, "千牛": 1e3, "秒": 1.0,
          "度": 1.0}
_UNITS_ON_PAPER = {"mm": 1.0, "cm": 10.0, "m": 1e3, "мм": 1.0, "см": 10.0, "м": 1e3, "毫米": 1.0, "厘米": 10.0,
                   "米": 1e3}
_SPEED_KEYS = {"rpm": "rpm", "rev/min": "rpm", "об/мин": "rpm", "rad/s": "omega", "1/s": "omega", "рад/с": "omega"}


def _unit_hint(lines: list[str], column: int) -> str:
    """The hint for a unit typed after a number (length = 0.05 m, 190 mm, rpm = 1500 rpm): the number in the
    scene's unit, under the key that takes it, where the unit is one the scene has a key's unit for."""
    line = lines[-1]
    before = line[:column - 1]
    number = re.search(r"(?:^|[=,\[{])\s*([-+]?\d[\d_]*(?:\.\d[\d_]*)?(?:[eE][-+]?\d+)?)\s*$", before)
    typed = re.match(r"[^\s,}\]#]+", line[column - 1:])
    keys = re.findall(r"([\w-]+)\s*=", before)
    if number is None or typed is None or not keys or not (typed[0][0].isalpha() or typed[0][0] in "μµ"):
        return ""
    key, unit, value = keys[-1], typed[0], float(number[1].replace("_", ""))
    if re.fullmatch(r"[eE][-+]?", unit):  # a power of ten begun and not finished, not a unit
        return (f"; '{number[1]}{unit}' ends at its exponent's {unit[0]}, with no power of ten after it: TOML writes "
                f"the power's digits, {number[1]}e-3 for {value * 1e-3:g}; or drop the {unit[0]}")
    tables = [found[1] for found in (re.match(r"\s*\[+\s*([\w.-]+)", text) for text in lines) if found]
    on_paper = bool(tables) and tables[-1].split(".")[0] in ("drawing", "measured")
    told = (f"; '{unit}' after the number: TOML takes the number alone, in "
            + ("mm, as [drawing] and [measured] take lengths" if on_paper else "the scene's units (m, kg, N, s, "
               "degrees)"))
    if unit.casefold() in _SPEED_KEYS and key in ("rpm", "omega"):
        return f"; '{unit}' after the number: TOML takes the number alone: write {_SPEED_KEYS[unit.casefold()]} = " \
               f"{number[1]}"
    factor = (_UNITS_ON_PAPER if on_paper else _UNITS).get(unit.casefold())
    written = number[1] if factor is None else f"{value * factor:.12g}"
    in_a_list = before.rfind("[") > before.rfind("]") and before.rfind("[") > before.rfind("=")
    return f"{told}: write {written} in its place" if in_a_list else f"{told}: write {key} = {written}"


def _decimal_comma(line: str) -> re.Match[str] | None:
    """The first number written with a comma after an =, outside a [ ] list: a list such as [0,0] is valid TOML,
    so its comma is never what TOML stumbled on."""
    for comma in re.finditer(r"=\s*\{?[^=#]*?([-+]?\d+),(\d+)", line):
        before = line[:comma.start(1)]
        if before.count("[") <= before.count("]"):
            return comma
    return None


def _end_of_line_hint(line: str, message: str) -> str:
    """The hint for a line TOML found unfinished at its end (a string or a table's bracket left open) or a key
    given twice."""
    if message.startswith(("Cannot overwrite a value", "Cannot declare")):
        return "; a key or a table given twice: keep one"
    if "Illegal character '\\n'" in message and line.count('"') % 2 == 1:
        return '; the string opened on this line is not closed: end it with "'
    if message.startswith("Unclosed inline table"):
        return "; an inline table { … } ends on the line it starts: close it with }"
    return ""


_DEGREE_SIGNS = "°º˚"
_DASHES = "‐‑‒–—―−"


def _key_hint(line: str, column: int, data: str = "") -> str:
    """The hint for a bare key with a letter that is not ASCII: quotes, where the scene names it so in quotes
    elsewhere (a point О a Russian scheme names, as pivot = "О"); the Latin letter that looks the same (рb for pb),
    the English key a Russian word stands for (группы for groups), the number a numbered table takes."""
    start = column - 1
    while start > 0 and _in_key(line[start - 1]):
        start -= 1
    end = column - 1
    while end < len(line) and _in_key(line[end]):
        end += 1
    word = line[start:end]
    if word and f'"{word}"' in data:
        # Told to type the Latin letter, the student renamed the point here and had every "О" elsewhere refused.
        return (f"; a bare TOML key takes ASCII letters, digits, '-' and '_' alone, and the scene names {word!r} "
                f'in quotes elsewhere: quote it here too, write {line[:start].lstrip()}"{word}"{line[end:].rstrip()}')
    looks = lookalike_plain(word)
    if looks != word and looks.isascii():
        return f"; {difference(word, looks)}"
    if re.search(r"\[\s*(links|measured)\.\s*$", line[:start]):
        return f"; {line[:start].strip(' [').rstrip('.')} are numbered: write [{line[:start].strip(' [')}3]"
    english = next((key for stem, key in _RUSSIAN_KEYS.items() if word.lower().startswith(stem)), None)
    if english is not None:
        return f"; a key is the English word, not the Russian {word!r}: write {line[:start]}{english}{line[end:]}"
    if line.lstrip().startswith("["):
        return f"; a table's name is an English word, not {word!r}: the tables are {', '.join(_TABLES)}"
    return (f"; a key is an English word, not {word!r}: quote a name of your own in other letters "
            f'("{word}" = …)')


def _dashed_key(line: str, column: int) -> tuple[int, int] | None:
    """Where the name round the dash at ``column`` begins and ends when it stands in a key (``x–x = { … }``,
    ``[frame.lines.x–x]``); None where the dash is a value's sign (``omega = −17.0``, ``[0.0, −0.1]``)."""
    def in_name(character: str) -> bool:
        return character in _DASHES or _in_key(character)

    start = end = column - 1
    while start > 0 and in_name(line[start - 1]):
        start -= 1
    while end < len(line) and in_name(line[end]):
        end += 1
    before, after = line[:start].rstrip(), line[end:].lstrip()
    header = line.lstrip().startswith("[")
    if not any(character.isalpha() for character in line[start:end]) or (before and before[-1] not in "{,.["):
        return None
    if after.startswith(("=", ".")) or (header and after.startswith("]")):
        return start, end
    return None


def _in_key(character: str) -> bool:
    # A name's mark that is no letter (the prime of E′, a combining accent, an emoji) is part of the name to quote:
    # only a space, ASCII punctuation and an input method's wide or typographic punctuation end it.
    if character.isalnum() or character in "_-":
        return True
    return not (character.isascii() or character.isspace() or _ascii_counterpart(character)
                or character in _DASHES or character in _DEGREE_SIGNS)


# The tables of a scene, and the Russian words a student writes for them and for their commonest keys (by the
# stem, so that every case of the word is found).
_TABLES = ("scene", "project", "frame", "driver", "groups", "points", "links", "loads", "friction", "positions",
           "drawing", "measured", "output", "forces", "dynamics", "balancing", "vibration")
_RUSSIAN_KEYS = {"сцен": "scene", "проект": "project", "стойк": "frame", "кривошип": "driver", "привод": "driver",
                 "ведущ": "driver", "групп": "groups", "точк": "points", "звен": "links", "нагрузк": "loads",
                 "трени": "friction", "положени": "positions", "чертеж": "drawing", "чертёж": "drawing",
                 "замер": "measured", "измерен": "measured", "вывод": "output", "сил": "forces",
                 "динамик": "dynamics", "маховик": "dynamics", "балансировк": "balancing", "вибраци": "vibration",
                 "масс": "mass", "длин": "length", "угол": "angle", "угл": "angle"}


def _read_scene(top: Table, source: str) -> Scene:
    refuse_control_characters(top.data, "")
    scene = top.table("scene", None) or Table({}, "scene")
    # A file name of bytes that are not UTF-8 (os.fsdecode's surrogates) titles the scene as a file browser shows it:
    # a surrogate could be written in no drawing, note or results.json; nor can the title a tab or a line break.
    stem = Path(source).stem.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
    if source == STDIN:  # the sheets' title block and the note's head read as no one's file name: <stdin>
        stem = "stdin"
    stem = "".join(" " if unicodedata.category(character) == "Cc" else character for character in stem)
    title = scene.string("title", stem)
    locale = scene.choice("locale", LOCALES, "en")
    gravity = scene.number("gravity", 9.81, non_negative=True)
    _refuse_heavy_gravity(gravity, scene.data.get("gravity"))
    scene.done(elsewhere=keys_of_other_tables("scene"))
    project = _read_project(top.table("project", None))

    balancing = None
    if top.has("balancing"):
        from .rotor_balancing import read_balancing

        balancing = read_balancing(top.table("balancing"))
    linkage = top.has("frame") or top.has("driver")
    # With a linkage, [vibration] is read after the driver, whose speed it takes where it gives none.
    vibration = None
    if top.has("vibration") and not linkage:
        from .vibration import read_vibration

        vibration = read_vibration(top.table("vibration"))
    if not linkage and (balancing is not None or vibration is not None or top.has("dynamics")):
        # A rotor to balance, a machine on its springs, a flywheel from a load diagram: no linkage to read.
        for key in LINKAGE_KEYS:
            if top.has(key):
                raise SceneError(key, "describes a mechanism: a scene with one needs [frame] and [driver] too")
        dynamics = None
        if top.has("dynamics"):
            from .flywheel import read_dynamics

            dynamics = read_dynamics(top.table("dynamics"), linkage=False)
        drawing = _read_drawing(top.table("drawing", None) or Table({}, "drawing"))
        include = _read_output(top.table("output", None))
        top.done()
        return Scene(title=title, locale=locale, gravity=gravity, frame_link=1, frame_points=MappingProxyType({}),
                     frame_lines=MappingProxyType({}), driver=None, groups=(), points=(),
                     links=MappingProxyType({}), loads=(), friction=(),
                     positions=Positions(count=1, start=0.0, number_from=1, working=None, plans=()),
                     drawing=drawing, measured=MappingProxyType({}), include=include, source=source,
                     balancing=balancing, vibration=vibration, dynamics=dynamics, project=project)
    if not top.has("frame"):
        # No [frame] where a misspelt table name ([vibrations]) was meant as a scene without a linkage.
        top.misspelt(*(name for name in ("frame", "driver", "balancing", "vibration", "dynamics") if not top.has(name)))
    frame_link, frame_points, frame_lines = _read_frame(top.table("frame"))
    driver = _read_driver(top.table("driver"))
    if top.has("vibration"):
        from .vibration import read_vibration

        vibration = read_vibration(top.table("vibration"), driver_speed=_steady_crank_speed(driver))
    dynamics = None
    if top.has("dynamics"):
        # Imported here: the machine's dynamics are built on the analysis, which reads scenes.
        from .flywheel import read_dynamics

        dynamics = read_dynamics(top.table("dynamics"), once_over=None if driver.cyclic else f"driver.{driver.run_key}",
                                 driver=driver)
    groups = tuple(_read_group(where, item) for where, item in top.items("groups", default=[]) or [])
    points = _read_points(top.table("points", None))
    links = _read_links(top.table("links", None))
    loads_ = tuple(_read_load(where, item) for where, item in top.items("loads", default=[]) or [])
    friction = tuple(_read_friction(where, item) for where, item in top.items("friction", default=[]) or [])
    positions = _read_positions(top.table("positions", None) or Table({}, "positions"), driver)
    drawing = _read_drawing(top.table("drawing", None) or Table({}, "drawing"))
    _refuse_swing_below_drawing(driver, positions.count, drawing.drafting_precision, top.data["driver"].get("swing"))
    _refuse_on_frame(frame_link, links, loads_)
    measured = _read_measured(top.table("measured", None))
    include = _read_output(top.table("output", None))
    forces = top.table("forces", None) or Table({}, "forces")
    inertia = forces.choice("inertia", INERTIA_FORMS, "couple")
    forces.done()
    # The optional tables are looked for, never read, where absent: a misspelt one is named before done() likens it
    # to a table that was read ([vibrations] to positions).
    top.misspelt(*(name for name in ("balancing", "vibration", "dynamics") if not top.has(name)))
    top.done()
    return Scene(title=title, locale=locale, gravity=gravity, frame_link=frame_link,
                 frame_points=MappingProxyType(frame_points), frame_lines=MappingProxyType(frame_lines),
                 driver=driver, groups=groups, points=points, links=MappingProxyType(links), loads=loads_, friction=friction,
                 positions=positions, drawing=drawing, measured=MappingProxyType(measured), include=include,
                 source=source, inertia=inertia, balancing=balancing, vibration=vibration, dynamics=dynamics,
                 project=project)


def _read_frame(frame: Table | None) -> tuple[int, dict[str, complex], dict[str, Guide]]:
    assert frame is not None
    link = frame.integer("link", 1, minimum=1)
    points: dict[str, complex] = {}
    table = frame.table("points", None)
    if table is not None:
        for name in table.data:
            x, y = check_xy(table.raw(name), table.where(name))
            points[check_str(name, table.where(name))] = complex(x, y)
    lines: dict[str, Guide] = {}
    table = frame.table("lines", None)
    if table is not None:
        for name in table.data:
            check_str(name, table.where(name))
            if name in points:
                raise SceneError(table.where(name), f"{name} names a point of [frame] points already: a guide "
                                 "through it would read as the point; name the line apart (e.g. ram, guide)")
            guide = read_guide(table.raw(name), table.where(name))
            if guide.line is not None or not guide.on_frame:
                raise SceneError(table.where(name), "a frame line needs through and angle, on the frame")
            if isinstance(guide.through, str) and guide.through not in points:
                raise SceneError(f"{table.where(name)}.through", f"must be a point of [frame] points: {', '.join(points) or 'none'}",
                                 guide.through, hint=lookalike_hint(guide.through, points))
            lines[name] = guide
    frame.done(elsewhere=keys_of_other_tables("frame"))
    return link, points, lines


def _refuse_swing_below_drawing(driver: Driver, count: int, precision_mm: float, typed: object) -> None:
    """Refuse a rocking crank's swing too small for its positions to be drawn apart (`swing = [20, 20 + 1e-12]` drew
    its 7 positions as one line): at ``driver.swing``, with the smallest swing that draws them apart."""
    if driver.kind != "crank" or driver.cyclic:
        return
    first, last = driver.swing
    # A position's crank pin is drawn its length/μl from the pivot, and the whole mechanism, the crank with it, on
    # no paper longer than LARGEST_PAPER_MM (a μl that draws it longer is refused): so at most that far out.  Two
    # positions a step δ apart put their pins at most LARGEST_PAPER_MM·δ apart, and a drawing tells lines apart
    # only to its drafting precision: under that on the largest paper, no drawing tells the positions apart.
    least_step = precision_mm / LARGEST_PAPER_MM
    steps = count - 1
    if abs(last - first) / steps >= least_step:
        return
    least = rounded_up(math.degrees(least_step * steps))
    raise SceneError(f"{driver.where}.swing", f"spans {math.degrees(abs(last - first)):.3g}°, too little "
                     f"for its {count} positions (positions.count) to be drawn apart: a crank drawn as long as the "
                     f"largest paper ({LARGEST_PAPER_MM:g} mm) puts their pins "
                     f"{LARGEST_PAPER_MM * abs(last - first) / steps:.3g} mm apart, under the drafting "
                     f"precision of {precision_mm:g} mm (drawing.drafting_precision); give a swing of at least "
                     f"{least:g}°", typed)


def _refuse_on_frame(frame_link: int, links: dict[int, LinkSpec], loads_: tuple[LoadSpec, ...]) -> None:
    """The frame stands still: a mass or a load put on it takes no part in the analysis, and is a slip of
    the link's number."""
    spec = links.get(frame_link)
    if spec is not None and (spec.mass > 0 or spec.inertia > 0):
        raise SceneError(spec.where, f"link {frame_link} is the frame, which does not move: its mass and inertia take "
                         "no part; give them to a moving link")
    for load in loads_:
        if load.link == frame_link:
            raise SceneError(f"{load.where}.link", f"link {frame_link} is the frame, which does not move: a load on it "
                             "does no work and is taken by the frame itself", frame_link)


def _steady_crank_speed(driver: Driver) -> float | None:
    """|ω| (rad/s) of a crank turning round at a steady speed, the speed a machine's ``[vibration]`` turns at where it
    gives none; None for a slider, a rocking crank or one speeding up, which give no one speed of turning."""
    if driver.kind != "crank" or not driver.cyclic or driver.coordinate_acceleration != 0.0:
        return None
    return abs(driver.coordinate_speed)


def _read_driver(table: Table | None) -> Driver:
    assert table is not None
    kind = table.choice("kind", tuple(DRIVERS))
    link = table.integer("link", minimum=1)
    return DRIVERS[kind].read(table, link)


_COUNTS = {2: "two", 4: "four"}


def _read_group(where: str, item: object) -> Group:
    table = Table(item, where)
    _refuse_russian_kind(table)
    kind = table.choice("kind", tuple(GROUPS))
    cls = GROUPS[kind]
    pairs = table.items("links", length=cls.link_count)
    assert pairs is not None
    links = tuple(check_int(value, w) for w, value in pairs)
    for (w, _), number in zip(pairs, links):
        if number < 1:
            raise SceneError(w, "must be a link number >= 1", number)
    if len(set(links)) != len(links):
        raise SceneError(table.where("links"), f"must name {_COUNTS.get(cls.link_count, cls.link_count)} different links", list(links))
    joints = table.names("joints", len(cls.joint_roles))
    if len(set(joints)) != len(joints):
        raise SceneError(table.where("joints"), "must name different joints", list(joints))
    return cls.read(table, links, joints)


# A Russian textbook letters its pairs В (вращательная, turning) and П (поступательная, sliding), and the ru note
# titles a group "ВВВ (RRR)"; a Russian keyboard types Р for the R it sounds as.
_RUSSIAN_PAIRS = str.maketrans("ВПР", "RPR")


def _refuse_russian_kind(table: Table) -> None:
    """A group's kind in the Russian notation (ВВП, or РРР as a Russian keyboard types RRR), told the Latin one."""
    kind = table.data.get("kind")
    if not isinstance(kind, str) or kind in GROUPS:
        return
    latin = kind.strip().upper().translate(_RUSSIAN_PAIRS)
    if latin in GROUPS and not kind.strip().upper().isascii():
        raise SceneError(table.where("kind"), f"must be one of {', '.join(GROUPS)}; did you mean {latin!r}?", kind,
                         hint="; the Latin notation letters a turning pair (В) R and a sliding one (П) P")


def _read_points(table: Table | None) -> tuple[PointSpec, ...]:
    if table is None:
        return ()
    specs = []
    for name, entry in table.subtables():
        assert entry is not None
        specs.append(PointSpec(
            name=check_str(name, entry.path), where=entry.path,
            link=entry.integer("link", minimum=1),
            start=entry.string("from"),
            toward=entry.string("toward"),
            at=entry.number("at"),
            offset=entry.number("offset", 0.0),
        ))
        entry.done()
    return tuple(specs)


def _read_links(table: Table | None) -> dict[int, LinkSpec]:
    if table is None:
        return {}
    links = {}
    for key, entry in table.subtables():
        assert entry is not None
        number = _numbered(key, entry.path, "links are numbered: write [links.3]")
        if number < 1:
            raise SceneError(entry.path, "links are numbered: write [links.3]")
        if number in links:
            raise SceneError(entry.path, f"link {number} is given twice")
        links[number] = LinkSpec(
            number=number, where=entry.path,
            mass=entry.number("mass", 0.0, non_negative=True),
            centre=entry.string("centre", None),
            inertia=entry.number("inertia", 0.0, non_negative=True),
        )
        entry.done(elsewhere=keys_of_other_tables("links.N"))  # a centre given as center is named before it is missed
        if links[number].mass > 0 and links[number].centre is None:
            raise SceneError(f"{entry.path}.centre", "a link with a mass needs its centre of mass: a point fixed on it")
    return links


def _read_load(where: str, item: object) -> LoadSpec:
    table = Table(item, where)
    kind = table.choice("kind", ("moment", "force"))
    link = table.integer("link", minimum=1)
    stiffness = table.number("stiffness", None, positive=True)
    free_length = table.number("free_length", None, non_negative=True)
    spring = stiffness is not None or free_length is not None
    if spring:
        _refuse_beside_a_spring(table, kind)
    diagram = _read_load_diagram(table) if table.has("diagram") else None
    if spring:
        # Its force is its length's at each position, and it acts always: no value, window or stroke to give.
        value: float | None = None
        during: str | tuple[float, float] = "always"
    elif diagram is not None:
        if table.has("value") or table.has("during"):
            raise SceneError(table.where("diagram"), "a load diagram gives the values and the window itself: "
                                                      "leave out value and during")
        value = max(abs(v) for _, v in diagram)
        during = (diagram[0][0], diagram[-1][0])
    else:
        value = table.number("value")
        during = _read_during(table)
    resisting = table.boolean("resisting", False)
    if resisting and spring:
        raise SceneError(table.where("resisting"), "a spring's sense is its length's (it pushes its ends apart where "
                         "shorter than its free length and pulls them together where longer), not the motion's: "
                         "leave resisting out", resisting)
    if resisting and diagram is None and value < 0:
        # Its sense is taken from the motion at each position, so a sign would be dropped without a word.
        raise SceneError(table.where("value"), "a resisting load's value is its magnitude (resisting = true turns it "
                         f"against the motion): write {-value:g}", value)
    if resisting and diagram is not None and any(v < 0 for _, v in diagram):
        # A moment has no angle to give (one is refused: it acts on its whole link); its sign is its sense.
        signed = "its values counter-clockwise positive" if kind == "moment" else \
            "and the load's angle, its values signed along it"
        raise SceneError(table.where("diagram"), "a resisting load's diagram gives magnitudes (resisting = true turns "
                         "it against the motion), and a negative value's sign would be dropped: for a load that "
                         f"helps the motion over part of the stroke, give resisting = false {signed}",
                         [v for _, v in diagram])
    stroke_table = table.table("stroke", None)
    stroke = _read_working(stroke_table) if stroke_table is not None else None
    if stroke is not None and during == "always":
        raise SceneError(stroke.where, "names the stroke the load acts in, and the load acts always: give during or a "
                         "diagram, or leave stroke out")
    point = table.string("point", None)
    angle = table.number("angle", None)
    along = table.string("along", None)
    if spring and along is None:
        # A fixed angle gives no length: the spring's force is its length's, the distance to its other end.
        instead = ", in place of angle" if angle is not None else ""
        raise SceneError(table.where("along"), "is required but missing: a spring acts along the line between its "
                         "two ends, so name the point its other end is pinned at (along = \"D\")" + instead
                         + ", whose distance from point is its length L")
    if kind == "force":
        # Each missing key told at its own path: at loads[0] the student was left to find which of the two it was.
        # A direction is an angle or a point to act along, one of the two.
        needed = ("point",) if along is not None else ("point", "angle")
        table.misspelt(*(key for key in (*needed, "along") if not table.has(key)))
        for key in needed:
            if not table.has(key):
                raise SceneError(table.where(key), f"is required but missing{required_purpose(table.where(key))}")
        if along is not None and angle is not None:
            raise SceneError(table.where("along"), "a force's line is given once: along a point (a line that turns "
                             "with the mechanism) or at an angle (a fixed direction), not both", along)
        if along is not None and along == point:
            raise SceneError(table.where("along"), f"names the force's own point {point!r}, which makes no line: "
                             "name the other end of the line the force acts along (a cylinder's or spring's pin)",
                             along)
    if kind == "moment":
        # A couple acts alike wherever on its link it is put: a point or a direction would say otherwise.
        for key in ("point", "angle", "along"):
            if table.has(key):
                raise SceneError(table.where(key), "a moment acts on its whole link: leave point, angle and along "
                                 "out")
    table.done()
    return LoadSpec(where=where, kind=kind, link=link, value=value, resisting=resisting, during=during,
                    point=point, angle_deg=angle, diagram=diagram, stroke=stroke, along=along,
                    stiffness=stiffness, free_length=free_length)


def _refuse_beside_a_spring(table: Table, kind: str) -> None:
    """Refuse what a spring (``stiffness`` and ``free_length``) cannot take, each at its own key: a moment, a value
    beside its length's force, a window, diagram or stroke (it acts always), one of its two keys without the other."""
    given = next(key for key in ("stiffness", "free_length") if table.has(key))
    if kind == "moment":
        raise SceneError(table.where(given), "a spring is a force between two points: give kind = \"force\", its "
                         "point and along, or leave stiffness and free_length out of a moment")
    if table.has("value"):
        raise SceneError(table.where("value"), "a spring's force is k·(L − L0) at each position, from its stiffness "
                         "and free length: leave value out, or leave stiffness and free_length out for a force of "
                         "a set value", table.raw("value"))
    for key in ("during", "diagram", "stroke"):
        if table.has(key):
            raise SceneError(table.where(key), "a spring acts always, its force set by its length at each "
                             f"position: leave {key} out")
    for key, other in (("stiffness", "free_length"), ("free_length", "stiffness")):
        if not table.has(key):
            raise SceneError(table.where(key), f"is required but missing{required_purpose(table.where(key))} (a "
                             f"spring given its {other} needs its {key} too)")


# The ways on the drawing a student names a ram's stroke by (a press's ram moves down), and the angle of a guide
# that runs that way; in the scene's languages too.
_WAYS_ON_THE_DRAWING = {"right": 0, "up": 90, "left": 180, "down": -90,
                        "вправо": 0, "вверх": 90, "влево": 180, "вниз": -90,
                        "右": 0, "向右": 0, "上": 90, "向上": 90, "左": 180, "向左": 180, "下": -90, "向下": -90}


def _read_working(table: Table) -> Working:
    """A stroke: which link's motion, and its sense that is the working stroke."""
    typed = table.data.get("sense")
    way = _WAYS_ON_THE_DRAWING.get(typed.strip().lower()) if isinstance(typed, str) else None
    if way is not None:
        # Told only the four senses, a student took forward for the ram's working way down, on a guide at 90° that
        # runs up, and got the strokes the other way round without a word.
        raise SceneError(table.where("sense"), f"must be one of {', '.join(SENSES)}", typed,
                         hint=f"; a slider's sense is along its guide: forward the way the guide's angle points, "
                              f"backward against it, so {typed.strip()} is forward along a guide at angle = {way} "
                              f"and backward along one at angle = {way - 180 if way > 0 else way + 180} (a turning "
                              "link's sense is ccw or cw)")
    working = Working(link=table.integer("link", minimum=1), sense=table.choice("sense", SENSES), where=table.path)
    table.done()
    return working


def _read_during(table: Table) -> str | tuple[float, float]:
    during_raw = table.raw("during", "always")
    if not isinstance(during_raw, dict):
        return check_choice(during_raw, table.where("during"), STROKES)
    window = Table(during_raw, table.where("during"))
    start = window.number("from")
    end = window.number("to")
    window.done()
    if not 0.0 <= start < end <= 1.0:
        raise SceneError(window.path, "must be a window 0 <= from < to <= 1 of the working stroke", during_raw)
    return (start, end)


def _read_load_diagram(table: Table) -> tuple[tuple[float, float], ...]:
    """The useful-resistance diagram: [share of the working stroke, value] pairs, shares rising within 0..1."""
    where = table.where("diagram")
    points = tuple(check_xy(item, at) for at, item in table.items("diagram"))
    if len(points) < 2:
        raise SceneError(where, "must have at least two points [share of the working stroke, value]")
    shares = [share for share, _ in points]
    if not 0.0 <= shares[0] or not shares[-1] <= 1.0 or any(b <= a for a, b in itertools.pairwise(shares)):
        beyond = " (shares, not crank angles in degrees or the travel in metres or mm)" if shares[-1] > 1.0 else ""
        raise SceneError(where, f"shares of the working stroke must rise strictly within 0..1{beyond}: 0 where the "
                         "stroke starts, 1 where it ends", list(shares))
    if not any(value for _, value in points):
        raise SceneError(where, "must have a value other than zero")
    return points


# What people write for a friction coefficient's f: the Greek letter, its name, the word.
_COEFFICIENT_NAMES = frozenset({"μ", "mu", "coefficient", "friction_coefficient", "coefficient_of_friction",
                                "friction", "cof", "коэффициент", "коэффициент_трения", "摩擦系数"})


def _read_friction(where: str, item: object) -> FrictionSpec:
    table = Table(item, where)
    joint = table.string("joint")
    links = None
    if table.has("links"):
        links = tuple(check_int(item, at) for at, item in table.items("links", length=2))
        if links[0] == links[1] or min(links) < 1:
            raise SceneError(table.where("links"), "must be two different link numbers", list(links))
    f = table.number("f", None, non_negative=True)
    radius = table.number("radius", None, positive=True)
    half_angle = table.number("groove_half_angle", None, positive=True)
    if half_angle is not None and not half_angle <= 90.0:
        raise SceneError(table.where("groove_half_angle"), "must be at most 90 degrees: the angle between a flank and "
                         "the groove's plane of symmetry, 90 for a flat guide", half_angle)
    # A key typed for f is named before f is missed: "f is required" left `coefficient = 0.1` unmentioned.
    table.named_otherwise("f", _COEFFICIENT_NAMES, "the coefficient of friction")
    table.done()
    if f is None:
        raise SceneError(table.where("f"), "is required but missing: the coefficient of friction")
    return FrictionSpec(where=where, joint=joint, links=links, f=f, radius=radius,
                        groove_half_angle=None if half_angle is None else math.radians(half_angle))


def _read_positions(table: Table, driver: Driver) -> Positions:
    count = table.integer("count", 12, minimum=1)
    if count > MAX_POSITIONS:
        raise SceneError(table.where("count"), f"must be <= {MAX_POSITIONS}: a run takes about a minute for "
                         f"{MAX_POSITIONS}, and minutes and gigabytes beyond", count)
    if not driver.cyclic and count < 2:
        raise SceneError(table.where("count"), f"a {driver.kind} driver's positions run from one end of "
                         f"driver.{driver.run_key} to the other, which takes at least 2", count)
    start_raw = table.raw("start", 0.0)
    start: str | float
    if isinstance(start_raw, str):
        start = _start_word(start_raw, table.where("start"))
    else:
        start = check_number(start_raw, table.where("start"))
    if not driver.cyclic and table.has("start"):
        raise SceneError(table.where("start"),
                         f"a {driver.kind} driver's positions run over driver.{driver.run_key}: leave start out")
    number_from = table.integer("number_from", 1, minimum=0, maximum=1)
    working_table = table.table("working", None)
    working = _read_working(working_table) if working_table is not None else None
    if start == "extreme" and working is None:
        # Told at the key that is missing, with the one that asks for it.
        table.misspelt("working")
        raise SceneError(table.where("working"), 'is required by start = "extreme": working = { link, sense } names '
                         "the motion whose extreme the positions start at (or give start a crank angle in degrees)")
    plans = _position_numbers(table, "plans", number_from, count, once_each=True)
    every = table.raw("velocity_plans", None)
    if isinstance(every, str):
        if every != "all":
            raise SceneError(table.where("velocity_plans"), 'must be "all" or a list of position numbers', every)
        velocity_plans = list(range(number_from, number_from + count))
    else:
        velocity_plans = sorted(_position_numbers(table, "velocity_plans", number_from, count, once_each=True))
    if len(velocity_plans) > MOST_VELOCITY_PLANS:
        raise SceneError(table.where("velocity_plans"), f"draws {len(velocity_plans)} velocity plans: at most "
                         f"{MOST_VELOCITY_PLANS} make a readable drawing; list the positions to draw")
    table.done(elsewhere=keys_of_other_tables("positions"))
    return Positions(count=count, start=start, number_from=number_from, working=working, plans=tuple(plans),
                     velocity_plans=tuple(velocity_plans), start_given=table.has("start"))


def _start_word(text: str, where: str) -> str:
    """``positions.start`` given as a string, which only "extreme" may be: a crank angle is a number, and one
    quoted or written with its degree sign ("30°") is told so."""
    if text == "extreme":
        return text
    angle = text.strip().rstrip("°º˚").strip().replace(",", ".").replace("−", "-")
    try:
        example = f"start = {float(angle):g}"
    except ValueError:
        example = "start = 30.0"
    word = text.strip().lower()
    near = word in _EXTREME_WORDS or difflib.get_close_matches(word, ["extreme"], n=1, cutoff=0.5)
    hint = "; did you mean 'extreme'?" if near else ""
    raise SceneError(where, f'must be "extreme" or a crank angle in degrees, a number: {example}', text, hint=hint)


# The Russian for the extreme position a student writes for "extreme".
_EXTREME_WORDS = ("крайнее", "крайнее положение", "крайн")


def _position_numbers(table: Table, key: str, number_from: int, count: int, once_each: bool = False) -> list[int]:
    """The position numbers listed under ``key``, each checked to be one of the scene's.

    With ``once_each`` a number listed again is refused: each listed position gets outputs of its own (a plan
    sheet, a section of the note), so a repeat, most likely a slip for another number, would deliver them twice.
    """
    numbers = []
    for where, item in table.items(key, default=[]) or []:
        number = check_int(item, where)
        if not number_from <= number < number_from + count:
            raise SceneError(where, f"must be a position number from {number_from} to {number_from + count - 1}",
                             number)
        if once_each and number in numbers:
            raise SceneError(where, f"position {number} is already listed at {table.where(key)}[{numbers.index(number)}]",
                             number)
        numbers.append(number)
    return numbers


def _refuse_heavy_gravity(gravity: float, typed: object) -> None:
    """Refuse a g no planet has: Earth's in another unit (32.2 ft/s², 9810 mm/s²) would make every weight, and
    every reaction and balancing load with it, that many times too large, and the run would say nothing."""
    if not gravity > HEAVIEST_GRAVITY:
        return
    unit = gravity_unit(gravity)
    hint = (f"; {as_written(typed)} is Earth's g in {unit}: the scene's is in m/s², write gravity = 9.81" if unit
            else "; Earth's is 9.81, 0 switches weight off")
    raise SceneError("scene.gravity", f"must be at most {HEAVIEST_GRAVITY:g} m/s², more than any planet's (Jupiter's "
                     "is 24.8)", typed, hint=hint)


def _read_project(table: Table | None) -> Project:
    if table is None:
        return Project()
    project = Project(**{name: table.string(name, "") for name in ("author", "checked_by", "approved_by",
                                                                  "organization", "designation")},
                      date=table.date("date", ""))
    table.done(list_known=True)
    return project


def _read_drawing(table: Table) -> Drawing:
    drawing = Drawing(
        length_scale=table.number("length_scale", None, positive=True),
        velocity_pole=table.number("velocity_pole", None, positive=True),
        acceleration_pole=table.number("acceleration_pole", None, positive=True),
        velocity_scale=table.number("velocity_scale", None, positive=True),
        acceleration_scale=table.number("acceleration_scale", None, positive=True),
        drafting_precision=table.number("drafting_precision", 0.5, positive=True),
        sheet=table.take("sheet", "A1", check_sheet),
        force_scale=table.number("force_scale", None, positive=True),
        sheet_given=table.has("sheet"),
        velocity_plans_pole=table.number("velocity_plans_pole", None, positive=True),
    )
    for plan in ("velocity", "acceleration"):
        if table.has(f"{plan}_pole") and table.has(f"{plan}_scale"):
            raise SceneError(table.where(f"{plan}_scale"), f"give either {plan}_pole or {plan}_scale, not both")
    table.done(elsewhere=keys_of_other_tables("drawing"))
    return drawing


def _read_measured(table: Table | None) -> dict[int, Mapping[str, Mapping[str, float] | float]]:
    if table is None:
        return {}
    measured: dict[int, Mapping[str, Mapping[str, float] | float]] = {}
    for key, entry in table.subtables():
        assert entry is not None
        number = _numbered(key, entry.path, "must be a position number: write [measured.5]")
        if number in measured:
            raise SceneError(entry.path, f"position {number} is given twice")
        readings: dict[str, Mapping[str, float] | float] = {}
        for plan in ("velocity", "acceleration", "forces"):
            lengths = entry.table(plan, None)
            if lengths is None:
                continue
            if not lengths.data:
                raise SceneError(lengths.path, "has no readings: give the lengths measured off the plan "
                                               "(pb = 42.5, …), or leave the table out")
            readings[plan] = MappingProxyType({name: _reading_length(lengths, name, plan) for name in list(lengths.data)})
        # The balancing moment (a crank, N·m) or force (a slider, N) the student found by hand: a value, not a length,
        # its size alone (its sense is the force analysis's, as ω's is the plan's).
        balancing = entry.number("balancing", None)
        if balancing is not None and balancing < 0:
            # A student signs Mb as drawn (cw negative) or takes it off the lever with its sense: the size was meant.
            raise SceneError(entry.where("balancing"), f"must be >= 0: give its size, balancing = {-balancing:g}; "
                             "its sense is taken from the force analysis, as a plan reading's ω takes the plan's",
                             balancing)
        if balancing is not None:
            readings["balancing"] = balancing
        entry.done(list_known=True)
        # Read-only all the way down: scene.measured[5]["velocity"]["pb"] = 1.0 changed what plan(5) read.
        measured[number] = MappingProxyType(readings)
    return measured


def _reading_length(lengths: Table, name: str, drawing: str) -> float:
    """A segment's length read off a ``drawing`` (a plan, or the force polygons), mm: its size, as a ruler gives it."""
    length = lengths.number(name)
    if length < 0:
        # A vector read backwards, or signed as ω is: the sense is the construction's, the reading a length.
        sense = ("its sense is taken from the force analysis" if drawing == "forces" else
                 "its sense is taken from the construction, as the ω and ε it gives take the plan's")
        raise SceneError(lengths.where(name), f"must be >= 0: a reading is the segment's length, give {-length:g}; "
                         f"{sense}", length)
    return length


def _numbered(key: str, where: str, problem: str) -> int:
    """A table name that must be a number, such as the 3 of ``[links.3]``."""
    if not (key.isascii() and key.isdigit()):
        raise SceneError(where, problem)
    return int(key)


def _read_output(table: Table | None) -> tuple[str, ...] | None:
    if table is None:
        return None
    pieces = table.items("include", default=None)
    table.done(elsewhere=keys_of_other_tables("output"))
    if pieces is None:
        return None
    # A piece listed again is refused, as --only's is: most likely a slip for another piece.
    return tuple(check_choices([item for _, item in pieces], table.where("include"), OUTPUT_PIECES, "piece"))
