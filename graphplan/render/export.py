"""PNG and PDF of a drawing, rendered from its SVG text by cairosvg.

cairosvg (and through it cairo) is imported inside the functions, so that a
run that writes only SVG never loads it; it is an optional dependency.

Fonts: cairosvg takes only the first family of a ``font-family`` list and
cairo asks fontconfig for it, without falling back glyph by glyph.  The SVG
backend therefore names DejaVu Sans first (Latin, Greek, Cyrillic) and Noto
Sans CJK first for a text with Chinese in it; both must be installed (on
Debian and Ubuntu: ``fonts-dejavu-core`` and ``fonts-noto-cjk``), or cairo
draws another font's glyphs or empty boxes.

Determinism: cairo writes no date into a PNG.  Into a PDF it writes the
creation date; :func:`svg_to_pdf` sets that entry (and the modification date) to an empty string, which
cairo (1.16 and later) takes as "no date" and leaves out, so the same SVG
gives the same PDF bytes with the same cairo.  The ``/Producer`` entry still
names cairo's version.
"""

from __future__ import annotations

import contextlib
import functools
import importlib
import os
import re
import signal
import threading
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

# Resolution of a PNG when none is asked for: enough for a sheet's 2.5 mm lettering on a screen.
DEFAULT_DPI = 150.0
# Millimetres in a unit an SVG document may give its size in (the drawings give mm, matplotlib pt).
_MM_PER = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72.0, "pc": 25.4 / 6.0, "px": 25.4 / 96.0, "": 25.4 / 96.0}
_ROOT = re.compile(r"<svg\b[^>]*>", re.DOTALL)


# The package each format needs that no SVG does (by the name it is imported as): its name and how to install it.
CAIRO = "cairosvg"
_CAIRO = ("cairosvg", "pip install cairosvg; it draws with the cairo library: Debian apt install libcairo2")
_PACKAGES = {
    CAIRO: _CAIRO,
    "cairocffi": _CAIRO,
    "ezdxf": ("ezdxf", "pip install ezdxf"),
    "docx": ("python-docx", "pip install python-docx"),
}


def tool_for(kind: str, module: str):
    """``module``, which writing a file of format ``kind`` (``png``, ``dxf``) needs, imported; an
    :class:`~graphplan.errors.OutputError` that names the format, the package and how to install it where it cannot
    be: a missing package, or cairo's library that cairocffi loads as it is imported (an OSError), came out as a
    traceback after the whole analysis."""
    try:
        return importlib.import_module(module)
    except (ImportError, OSError) as error:
        from ..errors import OutputError

        package, install = _PACKAGES[module.split(".")[0]]
        raise OutputError(f"{kind}: writing {kind} needs {package}, which cannot be loaded ({error}); install it "
                          f"({install}) or leave {kind} out of the formats asked for") from error


def svg_size_mm(svg_text: str) -> tuple[float, float]:
    """The width and height of an SVG document (its root's ``width`` and ``height``), in mm."""
    root = _ROOT.search(svg_text)
    sizes = []
    for name in ("width", "height"):
        found = re.search(rf'\s{name}="([\d.]+)\s*(mm|cm|in|pt|pc|px|)"', root.group(0)) if root else None
        if found is None:
            raise ValueError(f"the SVG document gives no {name} in a unit of length")
        sizes.append(float(found.group(1)) * _MM_PER[found.group(2)])
    return sizes[0], sizes[1]


def svg_to_png(svg_text: str, dpi: float = DEFAULT_DPI) -> bytes:
    """The PNG of an SVG document whose size is in physical units (mm, pt), at ``dpi`` pixels per inch."""
    if not dpi > 0:
        raise ValueError(f"dpi must be > 0 (got {dpi!r})")
    cairosvg = tool_for("png", CAIRO)

    with _interruption_held():
        png = cairosvg.svg2png(bytestring=svg_text.encode("utf-8"), dpi=dpi)
    return _with_resolution(png, dpi)


@contextlib.contextmanager
def _interruption_held() -> Iterator[None]:
    """Ctrl-C held back while cairo writes, and raised as ``KeyboardInterrupt`` once it has written.

    cairo writes a PNG or PDF through a Python callback, which an exception cannot leave: a Ctrl-C there
    printed cffi's traceback and came out as cairo's write error (OSError), not as an interruption. Only the
    main thread receives signals, and a handler the caller installed is theirs to keep.
    """
    callers_own = signal.getsignal(signal.SIGINT) is not signal.default_int_handler
    if threading.current_thread() is not threading.main_thread() or callers_own:
        yield
        return
    held = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: held.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if held:
        raise KeyboardInterrupt


def _with_resolution(png: bytes, dpi: float) -> bytes:
    """``png`` with a pHYs chunk saying its ``dpi``, so that a sheet prints and imports at its own size.

    cairo writes none (viewers then assume 72 or 96 dpi, and an A4 sheet at 150 dpi prints twice its
    size); the chunk goes right after IHDR, whose length is fixed, so the image data is not re-encoded.
    """
    import struct
    import zlib

    header_end = 8 + 4 + 4 + 13 + 4  # signature, then IHDR's length, type, data and CRC
    per_metre = round(dpi / 0.0254)
    body = b"pHYs" + struct.pack(">IIB", per_metre, per_metre, 1)
    chunk = struct.pack(">I", 9) + body + struct.pack(">I", zlib.crc32(body))
    return png[:header_end] + chunk + png[header_end:]


@dataclass(frozen=True)
class Rendering:
    """A PNG (at ``dpi``; None: :data:`DEFAULT_DPI`) or a PDF still to be rendered from an SVG document."""

    svg: str
    kind: str
    dpi: float | None = None

    def rendered(self) -> bytes:
        if self.kind == "png":
            return svg_to_png(self.svg) if self.dpi is None else svg_to_png(self.svg, self.dpi)
        return svg_to_pdf(self.svg)


# A third of a PNG's time holds Python's lock, which caps what threads can gain near 3×; and each thread holds its
# sheet's pixels while it renders (70 MB an A1 sheet).
_MOST_THREADS = 4


def rendered_all(renderings: Mapping[str, Rendering]) -> dict[str, bytes]:
    """Each file rendered, by its name: the PNG in threads, one a core up to four; the PDF one by one.

    A sheet's PNG takes about a second, two thirds of it in cairo's compression, which lets other threads run
    meanwhile: an A1 run's 41 PNG took 11.7 s one by one, 7.3 s in two threads on two cores. An A3 run's 57 PDF took
    3.5 s one by one and 4.5–5.2 s in two threads: nine tenths of a PDF's time is cairosvg's own Python (cairo
    only records the drawing), which threads take in turns and contend for (``bench/png_export.py``).

    Threads, not processes: a process started afresh imports the script that started it again, and a user's script
    without a ``__main__`` guard would run itself over; a forked one may deadlock on a lock that another thread (a
    notebook kernel's) held.
    """
    found = {name: rendering.rendered() for name, rendering in renderings.items() if rendering.kind != "png"}
    images = {name: rendering for name, rendering in renderings.items() if rendering.kind == "png"}
    workers = min(_cores(), len(images), _MOST_THREADS)
    if workers < 2:
        found.update((name, rendering.rendered()) for name, rendering in images.items())
    else:
        found.update(_in_threads(images, workers))
    return {name: found[name] for name in renderings}


def _in_threads(images: Mapping[str, Rendering], workers: int) -> dict[str, bytes]:
    # Imported here: 7 ms, which a run of SVG alone does not pay.
    from concurrent.futures import ThreadPoolExecutor

    # The largest first, so that no thread is left rendering a sheet while the others idle.
    largest_first = sorted(images, key=lambda name: len(images[name].svg), reverse=True)
    pool = ThreadPoolExecutor(workers, thread_name_prefix="graphplan-render")
    try:
        futures = {name: pool.submit(images[name].rendered) for name in largest_first}
        return {name: futures[name].result() for name in largest_first}
    finally:
        # On Ctrl-C or a failed file, the files not yet begun are not rendered for nothing.
        pool.shutdown(cancel_futures=True)


def _cores() -> int:
    """The cores this process may run on (a container's or a job's share, not the machine's count)."""
    if hasattr(os, "process_cpu_count"):
        return os.process_cpu_count() or 1
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def svg_to_pdf(svg_text: str) -> bytes:
    """A one-page PDF of an SVG document, the page the SVG's size, without a creation date."""
    with _interruption_held():
        return _undated_pdf_surface().convert(svg_text.encode("utf-8"))


@functools.cache
def _undated_pdf_surface():
    """cairosvg's PDF surface with cairo's creation date left out of the document."""
    cairocffi = tool_for("pdf", "cairocffi")
    PDFSurface = tool_for("pdf", "cairosvg.surface").PDFSurface

    class UndatedPDFSurface(PDFSurface):
        def _create_surface(self, width, height):
            surface, width, height = super()._create_surface(width, height)
            # An empty date is no ISO 8601 date: cairo drops the /CreationDate (and /ModDate) it would write.
            surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, "")
            surface.set_metadata(cairocffi.PDF_METADATA_MOD_DATE, "")
            return surface, width, height

    return UndatedPDFSurface
