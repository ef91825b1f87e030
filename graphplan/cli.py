"""The command line: ``graphplan run SCENE``, ``graphplan check SCENE``.

Every :class:`~graphplan.errors.GraphplanError` becomes one line on stderr
and exit status 2, never a traceback.
"""

from __future__ import annotations

import argparse
import atexit
import contextlib
import difflib
import gc
import math
import os
import re
import shlex
import signal
import sys
import threading
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from .errors import GraphplanError, SceneError

if TYPE_CHECKING:
    from .analysis import Analysis
    from .machine_dynamics import MachineDynamics
    from .scene import Scene

# The same for every command, so that a script can tell a refusal from an interruption.
EXIT_STATUS = """
exit status:
  0    done (check: the scene is ok, with its warnings or without)
  2    refused, in a line on stderr: the command line (under its usage), the scene or the output folder;
       nothing is written
  130  interrupted by Ctrl-C (143 killed, 129 the terminal closed, 141 the reader of its output gone); the
       output folder is left as it was
"""

EXAMPLES = """\
examples:
  graphplan run fixtures/ratchet_crank_rocker.toml              writes output/ratchet_crank_rocker/
  graphplan run fixtures/ratchet_crank_rocker.toml --out report --locale ru
  graphplan run fixtures/ratchet_crank_rocker.toml --only velocity,acceleration --format svg,png
  graphplan run fixtures/ratchet_crank_rocker.toml --only sheets,note --format pdf,dxf    sheets to CAD, note to PDF
  graphplan run fixtures/ratchet_crank_rocker.toml --only note --format docx              the note for Word
  graphplan run fixtures/ratchet_crank_rocker.toml --sheet A2   the course-project sheets on A2
  graphplan check fixtures/ratchet_crank_rocker.toml            validates and prints the structure formula
  graphplan run - --only velocity < fixtures/ratchet_crank_rocker.toml    a scene piped in: writes output/stdin/
  graphplan new crank-rocker                                    writes a commented starter scene crank-rocker.toml
  graphplan new shaper --locale ru                              a starter whose sheets and note are in Russian
"""


# A scene piped in has no file name to name its output folder after.
STDIN_FOLDER = "stdin"


def _piped(command: str) -> str:
    return f" (graphplan {command} - < scene.toml; a file named - is ./-)"


def _listed(text: str) -> list[str]:
    items = [item.strip() for item in text.split(",") if item.strip()]
    if not items:
        # An empty list would quietly mean "the default" for --format and "nothing but results.json" for --only.
        raise argparse.ArgumentTypeError("names nothing: give one or more, comma-separated")
    # "svg;png" or "svg png" was told as one unknown name, with a did-you-mean of its first word.
    if any(re.search(r"[\s;|+]", item) for item in items):
        commas = ",".join(word for item in items for word in re.split(r"[\s;|+]+", item) if word)
        raise argparse.ArgumentTypeError(f"separate the names with commas: {commas} (got {text!r})")
    return items


def _sheet(text: str) -> str:
    """A sheet format as drawing.sheet takes it, with the same did-you-mean (a Cyrillic а1 for A1)."""
    from .scene import check_sheet

    try:
        return check_sheet(text, "--sheet")
    except SceneError as error:
        raise argparse.ArgumentTypeError(str(error).removeprefix("--sheet: ")) from None


def _given_path(text: str) -> str:
    """A path typed on the command line: an empty one (a shell variable left unset) was taken for ".", the folder
    the command runs in."""
    if not text:
        raise argparse.ArgumentTypeError("is empty: give a path")
    return text


def _locale(text: str) -> str:
    """A locale as scene.locale takes it, with the same did-you-mean (RU, russian, cn)."""
    from .reader import check_choice
    from .scene import LOCALES

    try:
        return check_choice(text, "--locale", LOCALES)
    except SceneError as error:
        raise argparse.ArgumentTypeError(str(error).removeprefix("--locale: ")) from None


class _Parser(argparse.ArgumentParser):
    """argparse's parser, which names the command or kind meant beside one mistyped (rn for run, shapr for
    shaper): argparse's own only lists them all."""

    def _check_value(self, action: argparse.Action, value: object) -> None:
        if action.choices is not None and value not in action.choices:
            from .reader import suggestion

            choices = ", ".join(map(repr, action.choices))
            raise argparse.ArgumentError(
                action, f"invalid choice: {value!r} (choose from {choices}){suggestion(str(value), list(action.choices))}")


def _unknown_told(parser: argparse.ArgumentParser, unknown: list[str], arguments: argparse.Namespace) -> str:
    """argparse's "unrecognized arguments", with the option meant beside the first mistyped (--onyl, -o), or the
    list a name left outside with a space was meant to be in (--only velocity acceleration)."""
    from .deliverables import FORMATS, PIECES

    told = f"unrecognized arguments: {' '.join(unknown)}"
    for option, dest, names in (("--only", "only", PIECES), ("--format", "formats", FORMATS)):
        given, left_out = getattr(arguments, dest, None), [word for word in unknown if word in names]
        if given and left_out:
            return f"{told}; the names {option} takes are comma-separated: {option} {','.join(given + left_out)}"
    options = [name for action in parser._actions for name in action.option_strings if name.startswith("--")]
    for word in unknown:
        if not word.startswith("-") or word == "-":
            continue
        typed = word.split("=", 1)[0]
        # A single letter, as other programs shorten their options (-o for --out), where one option begins with it.
        initial = [name for name in options if len(typed) == 2 and name[2:3] == typed[1:]]
        if len(initial) == 1:
            return f"{told}; did you mean {initial[0]}?"
        # The dashes every option shares would make --bogus as near --out as --outt is.
        close = difflib.get_close_matches(typed.lstrip("-"), [name[2:] for name in options], n=1, cutoff=0.7)
        if close:
            return f"{told}; did you mean --{close[0]}?"
    return told


def _parser() -> argparse.ArgumentParser:
    from .choices import LOCALES, SHEETS
    from .deliverables import FORMATS, PIECES
    from .starters import KINDS

    parser = _Parser(
        prog="graphplan",
        description="The plan method of the theory of machines, from one scene file.",
        epilog=EXAMPLES + EXIT_STATUS, formatter_class=argparse.RawDescriptionHelpFormatter)
    # Not required here: argparse's "the following arguments are required: COMMAND" named none of them.
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    run = commands.add_parser("run", help="analyse a scene and write results.json, the drawings and the tables",
                              epilog=EXAMPLES + EXIT_STATUS, formatter_class=argparse.RawDescriptionHelpFormatter)
    # A string: a Path reads ./- as -, which names standard input, not the file ./- names.
    run.add_argument("scene", type=_given_path,
                     help=f"the scene file (TOML), or - to read it from standard input{_piped('run')}")
    run.add_argument("--out", type=lambda text: Path(_given_path(text)), default=None,
                     help=f"output folder (default: output/<the scene file's name without .toml>, {Path('output', STDIN_FOLDER)} for -)")
    run.add_argument("--locale", type=_locale, default=None, metavar="{" + ",".join(LOCALES) + "}",
                     help="the language of the drawings and the text (default: the scene's [scene] locale)")
    run.add_argument("--sheet", type=_sheet, default=None, metavar="{" + ",".join(SHEETS) + "}",
                     help="the sheet format of the course-project sheets, which it then draws unless --only or the "
                          "scene's [output] include leaves out 'sheets' (default: the scene's [drawing] sheet)")
    # Each given again adds to the list ("--format svg --format png" is svg,png): the last alone was taken,
    # and the pieces or formats named before it were dropped without a word.
    run.add_argument("--only", type=_listed, action="extend", default=None, metavar="PIECES",
                     help=f"deliver only these pieces, comma-separated or the option repeated: {', '.join(PIECES)} "
                          "(default: the scene's [output] include, else every piece the scene has data for)")
    run.add_argument("--format", type=_listed, action="extend", default=None, metavar="FORMATS", dest="formats",
                     help=f"formats of the drawings and the note, comma-separated or the option repeated: "
                          f"{', '.join(FORMATS)} (SVG always; pdf also typesets the note as note.pdf; docx writes the "
                          "note for Word)")
    run.add_argument("--figures", action="store_true",
                     help="also draw the report figures with matplotlib (the same as adding 'figures' to --only)")
    check = commands.add_parser("check", help="validate a scene and print its structure formula", epilog=EXIT_STATUS,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    check.add_argument("scene", type=_given_path,
                       help=f"the scene file (TOML), or - to read it from standard input{_piped('check')}")
    new = commands.add_parser("new", help="write a commented starter scene for a kind of mechanism or machine",
                              epilog=EXIT_STATUS, formatter_class=argparse.RawDescriptionHelpFormatter)
    new.add_argument("kind", choices=KINDS, help="the kind of mechanism, or a flywheel or rotor without one")
    # A string, not a Path: a Path drops the trailing slash that says "a folder" of one not made yet.
    new.add_argument("--out", type=_given_path, default=None,
                     help="the scene file to write, or a folder to write KIND.toml in (default: KIND.toml here)")
    new.add_argument("--locale", type=_locale, default="en", metavar="{" + ",".join(LOCALES) + "}",
                     help="the language of its drawings and note (scene.locale; its comments stay English)")
    for command in (run, check, new):
        command.set_defaults(command_parser=command)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    if argv is None:  # the command line's own process, which ends when the command does
        atexit.register(_nothing_collected_at_exit)
    _print_what_the_console_cannot_show_escaped()
    parser = _parser()
    arguments, unknown = parser.parse_known_args(argv)
    if arguments.command is None:
        parser.error("give a command: run, check or new (graphplan --help tells what each does)")
    if unknown:
        # argparse hands a command's unknown options up to the top parser, whose usage lists no options at all.
        arguments.command_parser.error(_unknown_told(arguments.command_parser, unknown, arguments))
    try:
        with _terminated_as_interrupted(), _few_full_collections(restored=argv is not None):
            if arguments.command == "check":
                return _check(arguments.scene)
            if arguments.command == "new":
                return _new(arguments.kind, arguments.out, arguments.locale)
            return _run(arguments)
    except GraphplanError as error:
        # The scene's warnings that may name the refusal's cause (lengths in millimetres behind a drawing no sheet
        # holds) come before it, as the refusing stage noted them.
        for note in getattr(error, "__notes__", ()):
            print(note, file=sys.stderr)
        print(f"graphplan: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        # The output folder is written whole or not at all, so an interrupted run has nothing to clean up.
        print("graphplan: interrupted", file=sys.stderr)
        return 130
    except _Terminated as ended:
        with contextlib.suppress(OSError):  # a terminal closed takes stderr with it
            print(f"graphplan: {ended.told}", file=sys.stderr)
        return 128 + ended.number
    except BrokenPipeError:
        # The reader of the output went away (| head -1): nothing is left to tell it. Python would print the error
        # again as it flushes stdout on the way out, so stdout goes nowhere from here.
        with contextlib.suppress(OSError, ValueError, AttributeError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + getattr(signal, "SIGPIPE", 13)


def _print_what_the_console_cannot_show_escaped() -> None:
    """A console that cannot print a character (Windows' code page, PYTHONIOENCODING=ascii) shows it as an escape
    (the structure's →, a Cyrillic file name): it stopped the command with a UnicodeEncodeError."""
    for stream in (sys.stdout, sys.stderr):
        if getattr(stream, "errors", None) == "strict" and hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")


class _Terminated(BaseException):
    """SIGTERM (``timeout``, a job killed) or SIGHUP (the terminal closed) as an exception: Python's default ends
    the process at once, leaving the output folder's half-written staging folder behind; raised, it unwinds through
    the writers' clean-up."""

    def __init__(self, number: int) -> None:
        super().__init__(number)
        self.number = number
        self.told = "the terminal was closed" if number == getattr(signal, "SIGHUP", None) else "terminated"


# A command's objects live until it ends: the modules it imports, the scene, the analysis and the drawings. The
# collector's full passes walk them all and free next to nothing (three passes were a tenth of a cold run's time);
# with the oldest generation's threshold raised, only a run that makes millions of objects pays for one.  The young
# generation is let grow to more objects than the default 700 too: the middle one, collected every tenth young pass,
# then held few of a run's many short-lived arrays and geometries (its passes fell from 0.025 s to 0.006 s).  The
# middle generation is collected every hundredth young pass, not every tenth: what outlives a young pass mostly lives
# till the run ends (the analysis, the drawings, their memos), and each middle pass walked all of it once more only to
# move it on to the oldest generation (the bundled scene's two took some 0.05 s); a run that makes ten times as many
# objects still walks each once, later.  A young pass walks what the command has made since the last one, and most of
# that lives till the command ends: at 20 000 the bundled scene's fourteen young passes (0.04 to 0.05 s of its cold
# run) walked its objects only to move them on and freed some twenty thousand; at 500 000 it makes none, and keeps
# some 10 MB more of what they would have freed.
YOUNG_COLLECTION_AT = 500_000
MIDDLE_COLLECTION_EVERY = 100
FULL_COLLECTION_EVERY = 100


def _nothing_collected_at_exit() -> None:
    """Every object kept out of the collector's passes as the interpreter ends.

    Those passes walk everything a command made (the modules, the analysis,
    the drawings and their memos) to free memory that the process hands back
    whole a moment later: a seventh of a cold run of the bundled scene
    (0.15 s of about 1.3).  Run at exit, once every file is written and
    closed; what is not in a cycle is still freed as the modules are.
    """
    gc.freeze()


@contextlib.contextmanager
def _few_full_collections(restored: bool = True) -> Iterator[None]:
    """The command run with the collector's full passes made rare, and the thresholds as they were afterwards where
    ``restored`` (a test calls :func:`main` in its own process).  The command line's own process, which ends with the
    command, keeps them: the default's young threshold, restored, set off a pass at the next allocation over every
    object the command had made since the last one, to free nothing the process does not give back a moment later."""
    before = gc.get_threshold()
    gc.set_threshold(YOUNG_COLLECTION_AT, MIDDLE_COLLECTION_EVERY, FULL_COLLECTION_EVERY)
    try:
        yield
    finally:
        if restored:
            gc.set_threshold(*before)


@contextlib.contextmanager
def _terminated_as_interrupted() -> Iterator[None]:
    if threading.current_thread() is not threading.main_thread():  # only the main thread may handle signals
        yield
        return

    def terminate(number: int, frame: object) -> None:
        raise _Terminated(number)

    numbers = [signal.SIGTERM] + ([signal.SIGHUP] if hasattr(signal, "SIGHUP") else [])
    previous = {number: signal.signal(number, terminate) for number in numbers}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


def _load(given: str, command: str) -> Scene:
    """The scene at the path ``given``, or piped into standard input for ``-`` (a file of that name is ``./-``).

    The reader's advice to pipe a scene in names ``run``; for another ``command`` it is retold with that command,
    which is the one the user typed.
    """
    from .errors import SceneError
    from .scene import load, load_stdin
    from .scene_file import pipe_in

    try:
        return load_stdin() if given == "-" else load(Path(given))
    except SceneError as error:
        if command == "run" or pipe_in() not in error.problem:
            raise
        raise SceneError(error.where, error.problem.replace(pipe_in(), pipe_in(command)), error.value,
                         hint=error.hint) from None


def _check(given: str) -> int:
    from .analysis import analyse
    from .deliverables import chosen, refuse_as_run_would
    from .run import note_warnings
    from .scene import STDIN

    scene = _load(given, "check")
    shown = STDIN if given == "-" else Path(given)
    if not scene.has_linkage:
        tables = [name for name in ("dynamics", "balancing", "vibration") if getattr(scene, name) is not None]
        pieces = _pieces(scene, None)
        dynamics = refuse_as_run_would(scene, None, chosen(scene, None))
        print(f"{shown}: ok")
        print(f"no mechanism; {', '.join(tables)}")
        print(pieces)
        _print_outcomes(scene, None, dynamics)
        return 0
    # The whole analysis, not only the structure: a position the mechanism cannot reach, or a reading of
    # [measured] that names no segment of its plan, is refused here as the run would refuse it.
    analysis = analyse(scene)
    mechanism = analysis.mechanism
    n, p5, w = mechanism.degrees_of_freedom
    try:
        pieces = _pieces(scene, analysis)  # an [output] include the scene cannot give is refused before "ok"
        dynamics = refuse_as_run_would(scene, analysis, chosen(scene, analysis))
    except GraphplanError as error:
        note_warnings(error, analysis)  # as the run, whose refusal this is, tells them
        raise
    print(f"{shown}: ok")
    print(f"structure: {mechanism.structure}")
    print(f"W = 3n − 2p5 − p4 = 3·{n} − 2·{p5} − 0 = {w}")  # Chebyshev's formula as the note writes it; p4 = 0
    turns = analysis.positions.stroke_turns(mechanism.driver.sense)
    if turns is not None:
        working, idle = turns
        print(f"strokes: working φw = {math.degrees(working):.2f}°, idle φi = {math.degrees(idle):.2f}°, "
              f"K = φw/φi = {working / idle:.4f}")
    elif analysis.positions.working_link_turns:
        print(f"strokes: none: {_turning_round(analysis)}")
    print(pieces)
    _print_warnings(analysis)
    _print_outcomes(scene, analysis, dynamics)
    return 0


def _turning_round(analysis: Analysis) -> str:
    """How a working link that turns round goes round, which is all there is to say of its strokes."""
    working = analysis.scene.positions.working
    turns = analysis.positions.working_link_turns
    times = {1: "once", 2: "twice"}.get(abs(turns), f"{abs(turns)} times")
    # The sense it turns in, which its diagrams count against where it is not the working sense the scene gives.
    sense = working.sense if turns > 0 else {"ccw": "cw", "cw": "ccw"}[working.sense]
    against = "" if turns > 0 else f", against positions.working's {working.sense}"
    return (f"link {working.link} turns round {times} a turn of the crank ({sense}{against}) and never turns back, "
            "so it has no extreme positions and no K")


def _print_outcomes(scene: Scene, analysis: Analysis | None, dynamics: MachineDynamics | None) -> None:
    """The warnings ``run`` gives of its outcomes (a machine that stalls, a speed near resonance), which
    ``check`` gave none of: the dynamics integrated as the run integrates them (``dynamics``, where the checks
    before worked them out)."""
    from .deliverables import chosen, outcome_warnings, scale_warnings
    from .machine_dynamics import MachineDynamics

    pieces = chosen(scene, analysis)
    if dynamics is None and "dynamics" in pieces:
        dynamics = MachineDynamics(analysis if analysis is not None else scene)
    for told in outcome_warnings(scene, pieces, dynamics) + scale_warnings(analysis, pieces):
        print(f"warning: {told}")


def _pieces(scene: Scene, analysis: Analysis | None) -> str:
    """What ``run`` would write, and each piece it would leave out for want of data, with what it needs."""
    from .deliverables import PIECES, chosen, missing

    pieces = chosen(scene, analysis)  # an [output] include the scene cannot give is refused here
    # A scene without a mechanism leaves out all the mechanism's pieces; the tables of their own need no word.
    looked_for = [piece for piece in PIECES if analysis is not None and piece not in ("balancing", "vibration")]
    wanting = [f"{piece} ({reason})" for piece in looked_for
               if piece not in pieces and (reason := missing(scene, analysis, piece)) is not None]
    return f"run writes: {', '.join(pieces)}" + (f"\nleft out: {'; '.join(wanting)}" if wanting else "")


def _print_warnings(analysis: Analysis) -> None:
    from .run import position_warnings

    for line in position_warnings(analysis):
        print(f"warning: {line}")


def _run(arguments: argparse.Namespace) -> int:
    from .run import run

    progress = Progress()
    given: str = arguments.scene
    scene = _load(given, "run")
    # --out=~/report reaches us with its ~ (the shell expands none after an =): a folder named ~ was written here.
    default = Path("output") / (STDIN_FOLDER if given == "-" else Path(given).stem)
    out = arguments.out.expanduser() if arguments.out is not None else default
    done = run(scene, out, arguments.only, arguments.formats or ("svg",), arguments.figures, arguments.locale,
               arguments.sheet, say=progress.say)
    print(f"{done.scene.title}")
    if done.analysis is not None:
        print(f"structure: {done.analysis.mechanism.structure}")
    for line in done.warnings:
        print(f"warning: {line}")
    for file in done.files:
        print(f"wrote {file}")
    return 0


def _new(kind: str, out: str | Path | None, locale: str = "en") -> int:
    from .output import write_file
    from .starters import starter

    target = Path(out).expanduser() if out is not None else Path(f"{kind}.toml")
    is_folder = False
    # A folder to put it in, as cp takes one; one that ends in a slash is a folder, made if it is not there yet.
    with contextlib.suppress(OSError):  # a name too long for the disk: write_file tells it
        is_folder = target.is_dir()
    if is_folder or (isinstance(out, str) and out.endswith(("/", os.sep))):
        target = target / f"{kind}.toml"
    write_file(target, starter(kind, locale), replace=False)
    print(f"wrote {target}")
    # Quoted as a shell reads it, so that the command copied runs with a path that has a space.
    shown = shlex.quote(str(target))
    print(f"next: graphplan check {shown}, then graphplan run {shown}")
    return 0


class Progress:
    """A line on stderr for each stage once a run has taken more than a second, so a long run is not silent."""

    def __init__(self, after: float = 1.0) -> None:
        import time

        self._clock = time.perf_counter
        self._start = self._clock()
        self._after = after

    def say(self, stage: str) -> None:
        elapsed = self._clock() - self._start
        if elapsed > self._after:
            print(f"graphplan: {stage} ({elapsed:.1f} s)", file=sys.stderr)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
