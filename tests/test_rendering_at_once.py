"""A run's PNG and PDF rendered at once (export.rendered_all): the PNG in threads, one a core, the PDF one by one.

The files must be those rendered one by one, byte for byte, whatever thread renders each; a failed file stops the
rest, and so does a Ctrl-C, which leaves no folder behind, as it does anywhere else in a run.
"""

from __future__ import annotations

import shutil
import signal
import threading
import time

import pytest
from console import without_progress

from graphplan.cli import main
from graphplan.render import export
from graphplan.render.export import Rendering, rendered_all, svg_to_pdf, svg_to_png

pytest.importorskip("cairosvg")

FIXTURE = "fixtures/ratchet_crank_rocker.toml"


def _page(width_mm: float, label: str, colour: str = "black") -> str:
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width_mm}mm" height="40mm" viewBox="0 0 {width_mm} 40">'
            f'<rect x="2" y="2" width="{width_mm - 4}" height="36" fill="none" stroke="{colour}"/>'
            f'<text x="5" y="20" font-size="6">{label}</text></svg>')


PAGES = {f"page_{k}.{kind}": _page(60 + 10 * k, f"Положение {k} 位置", colour)
         for k, colour in enumerate(["black", "red", "blue", "green", "purple"]) for kind in ("png", "pdf")}


def test_the_files_rendered_at_once_are_those_rendered_one_by_one(monkeypatch):
    monkeypatch.setattr(export, "_cores", lambda: 3)
    renderings = {name: Rendering(svg, name[-3:], 120.0 if name.startswith("page_2") and name.endswith("png") else None)
               for name, svg in PAGES.items()}
    found = rendered_all(renderings)
    assert list(found) == list(renderings)
    for name, svg in PAGES.items():
        alone = svg_to_pdf(svg) if name.endswith("pdf") else svg_to_png(svg, 120.0 if name == "page_2.png" else 150.0)
        assert found[name] == alone, name
    assert len(set(found.values())) == len(found)


def test_the_png_are_rendered_in_threads_and_the_pdf_in_the_callers(monkeypatch):
    where: dict[str, str] = {}
    render_png, render_pdf = export.svg_to_png, export.svg_to_pdf

    def png_noted(svg, dpi=export.DEFAULT_DPI):
        where[svg + "png"] = threading.current_thread().name
        return render_png(svg, dpi)

    def pdf_noted(svg):
        where[svg + "pdf"] = threading.current_thread().name
        return render_pdf(svg)

    monkeypatch.setattr(export, "svg_to_png", png_noted)
    monkeypatch.setattr(export, "svg_to_pdf", pdf_noted)
    monkeypatch.setattr(export, "_cores", lambda: 2)
    rendered_all({name: Rendering(svg, name[-3:]) for name, svg in PAGES.items()})
    threads = {key[-3:]: set() for key in where}
    for key, name in where.items():
        threads[key[-3:]].add(name)
    assert threads["pdf"] == {threading.current_thread().name}
    assert threads["png"] and all(name.startswith("graphplan-render") for name in threads["png"])
    # One core: no thread is started for them.
    where.clear()
    monkeypatch.setattr(export, "_cores", lambda: 1)
    rendered_all({name: Rendering(svg, name[-3:]) for name, svg in PAGES.items() if name.endswith("png")})
    assert set(where.values()) == {threading.current_thread().name}


def test_no_more_than_four_threads_render_however_many_cores(monkeypatch):
    threads = set()
    render_png = export.svg_to_png

    def png_noted(svg, dpi=export.DEFAULT_DPI):
        threads.add(threading.current_thread().name)
        return render_png(svg, dpi)

    monkeypatch.setattr(export, "svg_to_png", png_noted)
    monkeypatch.setattr(export, "_cores", lambda: 16)
    rendered_all({f"{k}.png": Rendering(_page(60 + 5 * k, f"{k}"), "png") for k in range(12)})
    assert 2 <= len(threads) <= 4


def test_a_file_that_fails_stops_the_files_not_begun(monkeypatch):
    begun = []
    gate = threading.Event()

    def failing_first(svg, dpi=export.DEFAULT_DPI):
        begun.append(svg)
        if "failing" in svg:
            gate.set()
            raise ValueError("cairo could not draw it")
        gate.wait(5)   # the others wait until the failure is raised: the pool then has many not begun
        time.sleep(0.2)   # and take as long as a small drawing would, while the caller learns of the failure
        return b"png"

    monkeypatch.setattr(export, "svg_to_png", failing_first)
    monkeypatch.setattr(export, "_cores", lambda: 2)
    renderings = {f"{k}.png": Rendering(("failing" if k == 0 else "") + "x" * (1000 - k), "png") for k in range(40)}
    with pytest.raises(ValueError, match="cairo could not draw it"):
        rendered_all(renderings)
    assert 1 <= len(begun) <= 4


def test_ctrl_c_while_the_threads_render_the_pngs_leaves_no_folder(tmp_path, capsys, monkeypatch):
    """The signal goes to the main thread, which waits for the renderers: the run says it was interrupted, renders
    no file it had not begun and leaves no folder."""
    render_png = export.svg_to_png
    rendered = []

    def interrupted_at_the_third(svg, dpi=export.DEFAULT_DPI):
        rendered.append(svg)
        if len(rendered) == 3:
            # As a Ctrl-C from the terminal while a thread renders: the process's signal, which the main thread,
            # waiting on the renderers, takes (raise_signal would send it to this thread, and the main thread would
            # see it only once the file it waits for was rendered).
            signal.pthread_kill(threading.main_thread().ident, signal.SIGINT)
        return render_png(svg, dpi)

    monkeypatch.setattr(export, "svg_to_png", interrupted_at_the_third)
    monkeypatch.setattr(export, "_cores", lambda: 2)
    handler_before = signal.getsignal(signal.SIGINT)
    assert handler_before in (signal.default_int_handler, signal.SIG_IGN), "a test before left its Ctrl-C handler"
    options = ["--only", "positions,velocity,acceleration,diagrams,forces,lever", "--sheet", "none"]
    assert main(["run", FIXTURE, "--out", str(tmp_path / "drawings"), *options]) == 0
    drawings = len(list((tmp_path / "drawings").glob("*.svg")))
    assert drawings >= 6
    shutil.rmtree(tmp_path / "drawings")
    capsys.readouterr()
    folder = tmp_path / "project"
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        status = main(["run", FIXTURE, "--out", str(folder), "--format", "png", *options])
    finally:
        signal.signal(signal.SIGINT, handler_before)
    assert status == 130
    assert without_progress(capsys.readouterr().err) == "graphplan: interrupted\n"
    assert list(tmp_path.iterdir()) == []
    # The third, and the one the other thread may have begun meanwhile; none of the rest.
    assert 3 <= len(rendered) <= 4 < drawings
