"""The note gives the sense of the crank's angular acceleration as it gives ω's: a student reading "ε2 5 rad/s²" and
"in the sense of ε2" was never told which way that is (counter-clockwise against a clockwise ω: the crank slows)."""

from pathlib import Path

import pytest

from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.scene import loads

RATCHET = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
SENSES = {"en": ("counter-clockwise", "clockwise"), "ru": ("против часовой стрелки", "по часовой стрелке"),
          "zh": ("逆时针", "顺时针")}


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("epsilon", [5.0, -5.0])
def test_the_initial_data_and_the_crank_pins_acceleration_say_which_way_epsilon_turns(locale, epsilon):
    text = RATCHET.replace("epsilon = 0.0", f"epsilon = {epsilon}").replace('locale  = "ru"', f'locale = "{locale}"')
    analysis = analyse(loads(text))
    assert analysis.scene.locale == locale and analysis.mechanism.driver.epsilon == epsilon
    note = note_markdown(analysis)
    # Counter-clockwise positive, as the scene format counts ω and ε.
    sense = SENSES[locale][0 if epsilon > 0 else 1]
    row = next(line for line in note.splitlines() if line.startswith("| ε2 |"))
    assert row.startswith("| ε2 | 5 ") and row.rstrip(" |").endswith(sense), row   # its size, and its sense in words
    # The crank pin's tangential acceleration "in the sense of ε2 (…)": its line reads ε2·lOA.
    pin = [line for line in note.splitlines() if "ε2·lOA" in line]
    assert pin and all(f"({sense})" in line or f"（{sense}）" in line for line in pin)
