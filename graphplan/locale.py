"""The strings a reader sees, one TOML file per language under ``locales/``."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from functools import cache
from importlib import resources


@cache
def strings(locale: str) -> Mapping[str, str]:
    """All strings of ``locale``; a key missing there falls back to English."""
    english = _read("en")
    if locale == "en":
        return english
    return {**english, **_read(locale)}


def _read(locale: str) -> dict[str, str]:
    text = resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)
