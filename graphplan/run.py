"""One run of a scene: its pieces chosen, its files made, its output folder written whole or not at all.

The command line's ``graphplan run`` and the notebook's ``scene.write(folder)`` both go through :func:`run`, so
that they write the same files, warn of the same outcomes and refuse the same things; each names its own options
(``--only`` or ``only``) in what it says.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .errors import GraphplanError, SceneError
from .reader import check_choice, check_choices
from .scene import LOCALES, Scene, check_sheet

if TYPE_CHECKING:
    from .analysis import Analysis


@dataclass(frozen=True)
class Options:
    """How a caller names the run's options, for the errors and warnings that name them."""

    only: str
    formats: str
    figures: str
    sheet: str
    locale: str
    # Who is to be given another folder where the one given cannot be written.
    out: str


COMMAND_LINE = Options(only="--only", formats="--format", figures="--figures", sheet="--sheet", locale="--locale",
                       out="--out")
PYTHON = Options(only="only", formats="formats", figures="figures", sheet="sheet", locale="locale",
                 out="scene.write()")


@dataclass(frozen=True)
class Run:
    """What a run wrote and what it warned of.

    ``scene`` is the scene as run (in the locale and on the sheet asked for), ``analysis`` its mechanism's analysis
    (None without a linkage), ``files`` the paths written, ``warnings`` each line the command line prints after
    ``warning:``: the positions near a toggle, then the outcomes (a machine that stalls, a speed near resonance).
    """

    scene: Scene = dataclasses.field(repr=False)
    analysis: Analysis | None = dataclasses.field(repr=False)
    folder: Path
    files: tuple[Path, ...]
    warnings: tuple[str, ...]

    def __repr__(self) -> str:
        told = "".join(f"\nwarning: {line}" for line in self.warnings)
        return f"<Run of {self.scene.title!r}: {len(self.files)} files in {self.folder}>{told}"


def as_asked(scene: Scene, locale: str | None = None, sheet: str | None = None,
             options: Options = COMMAND_LINE) -> Scene:
    """``scene`` in another ``locale`` and on another ``sheet``, as if it named them: the sheets are then drawn
    unasked."""
    if locale is not None:
        scene = dataclasses.replace(scene, locale=check_choice(locale, options.locale, LOCALES))
    if sheet is not None:
        scene = dataclasses.replace(scene, drawing=dataclasses.replace(
            scene.drawing, sheet=check_sheet(sheet, options.sheet), sheet_given=True))
    return scene


def run(scene: Scene, folder: Path, only: Iterable[str] | None = None, formats: Iterable[str] = ("svg",),
        figures: bool = False, locale: str | None = None, sheet: str | None = None,
        options: Options = COMMAND_LINE, say: Callable[[str], None] | None = None) -> Run:
    """Analyse ``scene``, make the files of the pieces ``only`` names (else those the scene asks for or has data
    for; ``figures`` adds the report figures) in ``formats``, and write them as ``folder``, which is replaced only
    once they are all made (:func:`graphplan.output.write_folder`).  ``say`` is told of each stage as it begins.

    Raises
    ------
    SceneError
        for a piece, format, locale or sheet the scene cannot give, naming the option as ``options`` spells it.
    OutputError
        for a folder the run cannot write, or one holding a file of the user's named as one of the run's.
    """
    with _sheet_named_as_given(sheet, options):
        return _run(as_asked(scene, locale, sheet, options), folder, only, formats, figures, options,
                    _sheet_key(sheet, options), say)


def results(scene: Scene, only: Iterable[str] | None = None, locale: str | None = None, sheet: str | None = None,
            options: Options = PYTHON, analysed: Callable[[Analysis], object] | None = None,
            warn: Callable[[str], None] | None = None) -> dict[str, Any]:
    """``results.json`` as :func:`run` with the same ``only``, ``locale`` and ``sheet`` writes it, nothing written:
    the same pieces chosen and the same refusals (the drawings are laid out for them); ``analysed`` is given the
    mechanism's analysis once made, ``warn`` each outcome the run warns of (a machine that stalls)."""
    from .deliverables import results_document

    with _sheet_named_as_given(sheet, options):
        scene, analysis, pieces = _asked(scene, only, False, locale, sheet, options, analysed)
        with _noting_warnings(analysis):
            return results_document(scene, analysis, pieces, warn)


def svg_files(scene: Scene, only: Iterable[str] | None = None, figures: bool = False, locale: str | None = None,
              sheet: str | None = None, options: Options = PYTHON,
              analysed: Callable[[Analysis], object] | None = None,
              warn: Callable[[str], None] | None = None) -> dict[str, tuple[str, bool]]:
    """Every SVG file :func:`run` with the same ``only``, ``figures``, ``locale`` and ``sheet`` writes, by name, and
    whether it is a plot (:func:`graphplan.deliverables.svg_files`), nothing written; the pieces chosen and refused as
    the run chooses and refuses them, ``analysed`` given the mechanism's analysis once made, ``warn`` each outcome
    the run warns of."""
    from .deliverables import svg_files as made

    with _sheet_named_as_given(sheet, options):
        scene, analysis, pieces = _asked(scene, only, figures, locale, sheet, options, analysed)
        with _noting_warnings(analysis):
            return made(scene, analysis, pieces, warn)


@contextmanager
def _noting_warnings(analysis: Analysis | None) -> Iterator[None]:
    """A refusal noting the analysis's warnings (:func:`note_warnings`), as a run's does."""
    try:
        yield
    except GraphplanError as error:
        note_warnings(error, analysis)
        raise


def _asked(scene: Scene, only: Iterable[str] | None, figures: bool, locale: str | None, sheet: str | None,
           options: Options, analysed: Callable[[Analysis], object] | None
           ) -> tuple[Scene, Analysis | None, tuple[str, ...]]:
    """The scene as asked for, its analysis (None without a linkage, given to ``analysed``) and the pieces chosen."""
    from .analysis import analyse

    scene = as_asked(scene, locale, sheet, options)
    only = _checked_pieces(only, options)
    analysis = analyse(scene) if scene.has_linkage else None
    if analysis is not None and analysed is not None:
        analysed(analysis)
    return scene, analysis, _pieces(scene, analysis, only, figures, options, _sheet_key(sheet, options))


def _sheet_key(sheet: str | None, options: Options) -> str:
    """The key a warning of the sheet names: the caller's option where the caller gives a sheet, which then stands
    in the scene's place."""
    return options.sheet if sheet is not None else "drawing.sheet"


@contextmanager
def _sheet_named_as_given(sheet: str | None, options: Options) -> Iterator[None]:
    """A refusal of the scene's sheet renamed for the ``sheet`` the caller gave in its place."""
    try:
        yield
    except SceneError as error:
        if sheet is not None and error.where == "drawing.sheet":
            # The way out the drawings offer, the scene's key sheet = "none", spelt as the option that was given in
            # its place: the user who typed --sheet A4 was told to write a key the scene need not have.
            no_sheet = f"{options.sheet} none" if options.sheet.startswith("-") else f'{options.sheet}="none"'
            renamed = SceneError(f"{options.sheet} (in place of drawing.sheet)",
                                 error.problem.replace('sheet = "none"', no_sheet), error.value, hint=error.hint)
            for note in getattr(error, "__notes__", ()):
                renamed.add_note(note)
            raise renamed from None
        raise


def _checked_pieces(only: Iterable[str] | None, options: Options) -> list[str] | None:
    """``only`` as a list of pieces, each checked: a piece mistyped is told at once, not once the mechanism is
    analysed (what the scene has data for is known only then)."""
    from .deliverables import PIECES

    if only is None:
        return None
    only = list(only)  # a generator is read once
    # The command line refuses an empty list as it parses it; scene.write(only=[]) wrote results.json alone.
    if not only:
        raise SceneError(options.only, "names nothing: give one or more pieces")
    if "results" in only:
        # Asked for by users who want the numbers alone: it is no piece, and was refused as a misspelt one.
        raise SceneError(f"{options.only}[{only.index('results')}]", "results.json is written by every run, "
                         "beside the pieces named: name those, or positions alone for the least beside it",
                         "results")
    return check_choices(only, options.only, PIECES, "piece")


def _run(scene: Scene, folder: Path, only: Iterable[str] | None, formats: Iterable[str], figures: bool,
         options: Options, sheet_key: str, say: Callable[[str], None] | None) -> Run:
    from .analysis import analyse
    from .deliverables import check_formats
    from .output import check_folder

    tell = say if say is not None else (lambda stage: None)
    only = _checked_pieces(only, options)
    formats = list(formats)  # a generator is read once
    # The command line refuses an empty list as it parses it; formats=[] wrote the SVG alone without a word.
    if not formats:
        raise SceneError(options.formats, "names nothing: give one or more formats")
    formats = check_formats(formats, options.formats)
    # A folder the run could never write is told at once, not once the analysis and the drawings are done.
    check_folder(folder, options.out)
    tell("analysing the mechanism" if scene.has_linkage else "analysing the machine")
    analysis = analyse(scene) if scene.has_linkage else None
    with _noting_warnings(analysis):
        return _deliver(scene, analysis, folder, only, formats, figures, options, sheet_key, tell)


def note_warnings(error: GraphplanError, analysis: Analysis | None) -> None:
    """Add the analysis's warnings to a refusal as notes: the warnings come only with a finished run, and a refused
    one would hide the cause they may name (lengths in millimetres behind a drawing no sheet holds)."""
    for line in position_warnings(analysis):
        error.add_note(f"warning: {line}")


def _deliver(scene: Scene, analysis: Analysis | None, folder: Path, only: Iterable[str] | None,
             formats: tuple[str, ...], figures: bool, options: Options, sheet_key: str,
             tell: Callable[[str], None]) -> Run:
    """The run's pieces drawn and written, once the scene is analysed."""
    from .deliverables import files, missing
    from .output import write_folder

    pieces = _pieces(scene, analysis, only, figures, options, sheet_key)
    outcomes: list[str] = []
    # The analysis as the files tell it: the course sheets drawn may say more of the hand readings.
    checked: list[Analysis] = []
    found = files(scene, analysis, pieces, formats, warn=outcomes.append, say=tell, checked=checked.append)
    analysis = checked[-1] if checked else analysis
    # A sheet asked for that the scene has nothing to draw on (a vibration alone) is said, not dropped.
    if scene.drawing.sheet_given and scene.drawing.sheet != "none" and "sheets" not in pieces \
            and (reason := missing(scene, analysis, "sheets")) is not None:
        alone = ("; without a mechanism only a [balancing] and a [dynamics] of load diagrams are drawn on sheets"
                 if analysis is None else "")
        outcomes.append(f"{sheet_key}: no sheet is drawn: 'sheets' {reason}{alone}")
    # A format none of the pieces comes in (docx with no note, dxf of the accuracy's plots) is said, not dropped.
    outcomes += [f"{options.formats} {kind}: nothing this run writes comes as {kind} (the pieces it writes: "
                 f"{', '.join(pieces)})" for kind in formats if kind != "svg"
                 and not any(name.endswith(f".{kind}") for name in found)]
    tell("writing the folder")
    written = write_folder(folder, found, options.out)
    return Run(scene, analysis, Path(folder), tuple(written), tuple(position_warnings(analysis) + outcomes))


def _pieces(scene: Scene, analysis: Analysis | None, only: Iterable[str] | None, figures: bool, options: Options,
            sheet_key: str) -> tuple[str, ...]:
    """The pieces a run delivers: ``only`` (else those the scene asks for or has data for) and the figures if asked."""
    from .deliverables import chosen, missing

    asked = list(only) if only is not None else None
    if figures:
        if (reason := missing(scene, analysis, "figures")) is not None:
            raise SceneError(options.figures, f"'figures' {reason}")
        asked = [*(asked if asked is not None else chosen(scene, analysis)), "figures"]
    return chosen(scene, analysis, asked, options.only, sheet_key)


def position_warnings(analysis: Analysis | None) -> list[str]:
    """The analysis's warnings, each a line as the command line prints it: a position's with its number.

    A warning told alike at several positions (the friction locking twelve of them) is one line naming them all,
    where the first of them stands: results.json keeps one a position."""
    from .analysis import SCENE_WIDE_WARNINGS

    if analysis is None:
        return []
    lines: list[str | tuple[str, str]] = []
    where: dict[tuple[str, str], list[int]] = {}
    for warning in analysis.warnings:
        if warning.code in SCENE_WIDE_WARNINGS:
            lines.append(warning.detail)
            continue
        told = (warning.code, warning.detail)
        if told not in where:
            where[told] = []
            lines.append(told)
        where[told].append(int(analysis.positions.numbers[warning.position]))
    return [line if isinstance(line, str) else f"{_positions(where[line])}: {line[1]}" for line in lines]


def _positions(numbers: list[int]) -> str:
    """``position 3``, or ``positions 1–5, 7–11`` with runs of three or more numbers in a row joined."""
    if len(numbers) == 1:
        return f"position {numbers[0]}"
    runs: list[list[int]] = []
    for number in numbers:
        if runs and number == runs[-1][-1] + 1:
            runs[-1].append(number)
        else:
            runs.append([number])
    written = [f"{run[0]}–{run[-1]}" if len(run) > 2 else ", ".join(map(str, run)) for run in runs]
    return "positions " + ", ".join(written)


__all__ = ["COMMAND_LINE", "PYTHON", "Options", "Run", "as_asked", "note_warnings", "position_warnings", "run"]
