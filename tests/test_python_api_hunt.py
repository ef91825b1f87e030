"""The Python interface called as a student's notebook calls it, wrongly: each misuse is told in a line that names the
argument and what is wrong, never passed on as a traceback from deep inside nor taken silently."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import graphplan

RATCHET = "fixtures/ratchet_crank_rocker.toml"
SHAPER = "fixtures/shaper_six_bar.toml"


@pytest.fixture(scope="module")
def ratchet():
    return graphplan.load(RATCHET)


@pytest.mark.parametrize("wrong", [RATCHET, Path(RATCHET), None, {}])
def test_build_given_no_scene_says_it_takes_one(wrong):
    """build(path) raised AttributeError: 'str' object has no attribute 'driver', from inside the mechanism."""
    with pytest.raises(TypeError, match=r"^build takes a scene, as graphplan\.load\(path\) reads it \(got "):
        graphplan.build(wrong)


def test_the_notebook_s_plan_given_no_scene_says_it_takes_one():
    """graphplan.notebook.plan(path, 5) raised AttributeError: 'str' object has no attribute 'positions'."""
    from graphplan.notebook import plan

    with pytest.raises(TypeError, match=r"^plan takes a scene, as graphplan\.load\(path\) reads it \(got 'fix"):
        plan(RATCHET, 5)


def test_a_mechanism_prints_in_a_line_and_solve_given_one_says_where_its_scene_is(ratchet):
    """A mechanism's repr printed its whole scene (3 000 characters), and so did solve's error given one."""
    mechanism = graphplan.build(ratchet)
    assert repr(mechanism) == "<Mechanism of 'Crank-rocker of a ratchet feed': driver link 2, groups II(3,4)>"
    with pytest.raises(TypeError) as raised:
        graphplan.solve(mechanism, driver=[0.1])
    assert str(raised.value) == ("solve takes a scene, as graphplan.load(path) reads it (got <Mechanism of "
                                 "'Crank-rocker of a ratchet feed': driver link 2, groups II(3,4)>); its scene is "
                                 "mechanism.scene")
    with pytest.raises(TypeError, match=r"\(got <Analysis of .*>\); its scene is analysis\.scene$"):
        graphplan.build(ratchet.analyse())


def test_a_point_typed_in_cyrillic_is_told_apart_from_the_latin_one(ratchet):
    """point('В') with a Cyrillic В was told «no point 'В'; points are O, C, A, S2, B, …»: the B it meant stood in
    the list, looking the same."""
    motion = ratchet.solve(driver=[0.1])
    with pytest.raises(KeyError, match=r"no point 'В'.*the Cyrillic 'В' \(U\+0412\) where 'B' has the Latin 'B'"):
        motion.point("В")


def test_a_sliding_pair_is_named_by_its_slider_s_number_and_an_unknown_one_lists_the_pairs():
    """slide('6') on the shaper, whose link 6 does slide, was told «link 6 slides in no pair»."""
    motion = graphplan.load(SHAPER).solve(driver=[0.1])
    assert [(slide.slider, slide.guide) for slide in motion.slides] == [(3, 4), (6, 1)]
    with pytest.raises(TypeError, match=r"^a sliding pair is named by its slider's number, an integer: slide\(6\), "
                                        r"not slide\('6'\)$"):
        motion.slide("6")
    with pytest.raises(KeyError, match=r"link 9 slides in no pair; the sliding pairs are link 3 on link 4, "
                                       r"link 6 on link 1"):
        motion.slide(9)
    assert motion.slide(6).guide == 1


def test_a_single_precision_number_in_a_scene_s_tables_is_the_number_its_digits_say():
    """np.float32(0.26), from a sweep in single precision, became a rod of 0.25999999046325684 m, where the file's
    0.26 is the double nearest 0.26."""
    import tomllib

    tables = tomllib.loads(Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8"))
    for rod in np.linspace(0.2, 0.3, 11, dtype=np.float32):
        tables["groups"][0]["length"] = rod
        assert graphplan.load(tables).groups[0].length == float(f"{rod:.2f}")
    tables["groups"][0]["length"] = np.float16(0.25)
    assert graphplan.load(tables).groups[0].length == 0.25
    tables["driver"]["length"] = np.array([0.05], dtype=np.float32)[0]
    tables["frame"]["points"] = {"O": np.array([0.0, 0.1], dtype=np.float32)}
    scene = graphplan.load(tables)
    assert (scene.driver.length, scene.frame_points["O"]) == (0.05, 0.1j)


# --- scene.write and drawing.save -------------------------------------------------------------------------------


@pytest.mark.parametrize(("keyword", "value", "told"), [
    ("only", 5, r"^only is a list of names: only=\['note'\] \(got 5\)$"),
    ("formats", None, r"^formats is a list of names: formats=\['png'\] \(got None\)$"),
    ("figures", "no", r"^figures is True or False \(got 'no'\)$"),
])
def test_write_refuses_an_option_of_the_wrong_kind_before_it_writes(ratchet, tmp_path, keyword, value, told):
    """only=5 and formats=None raised «'int' object is not iterable» from inside the run; figures='no', a string and
    so true, drew the report figures."""
    with pytest.raises(TypeError, match=told):
        ratchet.write(tmp_path / "run", **{"only": ["note"], keyword: value})
    assert not (tmp_path / "run").exists()


def test_names_given_as_bytes_are_a_list_of_names_too(ratchet, tmp_path):
    """only=b'note' was taken byte by byte: «only[0]: must be a string, not an integer (got 110)»."""
    with pytest.raises(TypeError, match=r"^only is a list of names: only=\['note'\], not only=b'note'$"):
        ratchet.write(tmp_path / "run", only=b"note")


@pytest.mark.parametrize("folder", [None, {}, 5])
def test_write_given_no_folder_says_it_takes_one(ratchet, folder):
    """write(None) raised pathlib's «expected str, bytes or os.PathLike object, not NoneType»."""
    with pytest.raises(TypeError, match=r"^write takes the folder to write, a path such as 'ratchet' \(got "):
        ratchet.write(folder)


def test_a_path_from_the_home_folder_is_the_home_folder_s(ratchet, tmp_path, monkeypatch):
    """A notebook has no shell to expand ~: write('~/ratchet') wrote a folder named ~ in the working folder, and
    save('~/plan.svg') raised FileNotFoundError."""
    scene_text = Path(RATCHET).read_bytes()
    home, working = tmp_path / "home", tmp_path / "work"
    home.mkdir()
    working.mkdir()
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.chdir(working)
    done = ratchet.write("~/ratchet", only=["note"])
    assert done.folder == home / "ratchet" and (home / "ratchet" / "note.md").is_file()
    assert ratchet.plan(5).drawing.save("~/plan.svg") == home / "plan.svg"
    (home / "copy.toml").write_bytes(scene_text)
    assert graphplan.load("~/copy.toml").title == ratchet.title
    assert list(working.iterdir()) == []


def test_save_says_it_takes_a_file_s_path_and_not_a_folder(ratchet, tmp_path):
    """save(None) raised pathlib's TypeError; save(folder) was told that the folder's name had no suffix, and a
    folder named plan.svg raised IsADirectoryError."""
    drawing = ratchet.plan(5).drawing
    with pytest.raises(TypeError, match=r"^save takes the path of the file to write, such as 'plan\.svg' "
                                        r"\(got None\)$"):
        drawing.save(None)
    (tmp_path / "plan.svg").mkdir()
    for folder in (tmp_path, tmp_path / "plan.svg"):
        with pytest.raises(IsADirectoryError, match=rf"^{folder}: is a folder; save the drawing as a file in it, such "
                                                    rf"as {folder / 'drawing.svg'}$"):
            drawing.save(folder)
    assert [path.name for path in tmp_path.iterdir()] == ["plan.svg"]


# --- load and load_text -----------------------------------------------------------------------------------------


def test_load_text_s_source_is_a_name():
    """source=None raised pathlib's «expected str, bytes or os.PathLike object, not NoneType» from the title's
    default; a path names the scene as its text."""
    text = Path(RATCHET).read_text(encoding="utf-8")
    with pytest.raises(TypeError, match=r"^source names the scene in its errors, a string such as 'ratchet\.toml' "
                                        r"\(got None\)$"):
        graphplan.load_text(text, source=None)
    assert graphplan.load_text(text, source=Path("drafts/lever.toml")).source == "drafts/lever.toml"


def test_load_of_an_empty_path_does_not_read_the_working_folder():
    """load('') was told «.: cannot be read: Is a directory», a folder the caller never named."""
    with pytest.raises(graphplan.SceneError, match=r"^load takes the path of a scene file, such as "
                                                   r"'ratchet\.toml' \(got an empty path ''\)$"):
        graphplan.load("")


# --- the driver's values in the wrong unit ------------------------------------------------------------------------


def test_whole_degrees_given_for_a_crank_s_radians_are_warned_of(ratchet):
    """np.arange(0, 360, 30) went to the crank as radians, 52 turns of it, without a word: the motion came out, at
    angles the student never meant."""
    told_so = (r"^driver: the values are whole numbers up to 330, read as radians \(330 rad is 52\.5 turns\): for "
               r"degrees give np\.radians\(values\)$")
    with pytest.warns(UserWarning, match=told_so) as told:
        ratchet.solve(driver=np.arange(0, 360, 30))
    # Told at the notebook's line, not at graphplan's own through which scene.solve() calls graphplan.solve().
    assert [Path(warning.filename).name for warning in told] == [Path(__file__).name]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ratchet.solve(driver=np.radians(np.arange(0, 360, 30)))
        ratchet.solve(driver=[0, 1, 2, 3, 4, 5, 6])  # whole radians within a turn
        ratchet.solve(driver=[0.5, 0.5 + 2 * np.pi * 3])  # turns on, not whole


def test_degrees_a_rocking_crank_cannot_reach_as_radians_are_told_as_such():
    """[20, 65] for a lever swinging 20°…65° was told «cannot be assembled at φ = 124.226°», an angle the student
    never gave (65 rad), with no word of the unit."""
    scene = graphplan.load("fixtures/double_rocker_swing.toml")
    with pytest.raises(graphplan.AssemblyError, match=r"at φ = 124\.226° \(driver\[1\]\) .*; the values are whole "
                                                      r"numbers up to 65, read as radians \(65 rad is 10\.3 turns\): "
                                                      r"for degrees give np\.radians\(values\)$"):
        scene.solve(driver=[20, 65])
    assert 65 / (2 * np.pi) == pytest.approx(10.345, abs=1e-3)
    assert np.degrees(65) % 360 == pytest.approx(124.226, abs=1e-3)


def test_a_slider_s_millimetres_it_cannot_reach_as_metres_are_told_as_such():
    """[0, 50, 100] for a rod travelling 0…200 mm was told «cannot be assembled at s = 50 m», no word of its travel
    in metres."""
    scene = graphplan.load("fixtures/slider_driven.toml")
    with pytest.raises(graphplan.AssemblyError, match=r"at s = 50 m \(driver\[1\]\) .*; the scene's travel is s = 0 "
                                                      r"… 0\.2 m and the values are in metres: given in millimetres\? "
                                                      r"divide them by 1000$"):
        scene.solve(driver=[0, 50, 100])
    # Beyond the travel, not a thousand times it: the travel is told, not millimetres.
    with pytest.raises(graphplan.AssemblyError, match=r"; the scene's travel is s = 0 … 0\.2 m and the values are in "
                                                      r"metres$"):
        scene.solve(driver=[0.1, 0.5])


def test_a_driver_value_past_float_s_range_is_refused_as_the_others_are(ratchet):
    """A Python integer of 400 digits raised OverflowError from numpy's cast instead of the driver's refusal."""
    with pytest.raises(graphplan.SceneError, match=r"^driver: must be an array of numbers .* \(got \[1000"):
        ratchet.solve(driver=[10 ** 400])


def test_positions_picked_by_a_mask_or_by_none_are_taken_or_told_what_at_positions_takes(ratchet):
    """at_positions([]) was refused as «a list of integers (got [])», which it is, where np.array([], int) gave the
    motion at no position; a mask (motion.driver < 1, numpy's own
    way of picking) was refused without a word of how to turn it into indices."""
    motion = ratchet.solve(driver=[0.5, 1.5, 2.5])
    none = motion.at_positions([])  # as numpy's indexing picks none
    assert none.count == 0 and none.point("B").r.shape == (0, 2) and none.link(4).omega.shape == (0,)
    with pytest.raises(TypeError, match=r"a list of integers \(got array\(\[ True, False, False\]\)\); a mask picks "
                                        r"them as np\.flatnonzero\(mask\)$"):
        motion.at_positions(motion.driver < 1)
    assert motion.at_positions(np.flatnonzero(motion.driver < 1)).driver.tolist() == [0.5]


# --- what a notebook prints --------------------------------------------------------------------------------------


def test_a_scene_and_its_dynamics_print_in_a_line_that_names_them():
    """A scene's repr ran to 3 000 characters; the dynamics' model, flywheel and integrated motion, which the README
    points to, to 28 500, 5 700 and 34 000 on the flywheel starter (every array)."""
    from graphplan.starters import starter

    scene = graphplan.load_text(starter("flywheel"), source="press.toml")
    dynamics = scene.machine_dynamics()
    model, flywheel, motion = dynamics.model, dynamics.flywheel, dynamics.motion
    shown = [repr(item) for item in (scene, graphplan.load(RATCHET), model, flywheel, motion)]
    assert all(len(line) < 200 and "\n" not in line for line in shown), shown
    assert shown[0] == f"<Scene {scene.title!r} from press.toml: [dynamics]>"
    assert shown[1] == ("<Scene 'Crank-rocker of a ratchet feed' from fixtures/ratchet_crank_rocker.toml: a mechanism "
                        "at 12 positions>")
    assert f"Je {model.inertia.min():.4g} … {model.inertia.max():.4g} kg·m²" in shown[2]
    assert f"{len(model.driver)} samples" in shown[2]
    assert f"JF = {flywheel.inertia:.5g} kg·m²" in shown[3] and f"δ = {flywheel.delta:.4g}" in shown[3]
    assert f"{len(motion.t)} steps over {motion.t[-1]:.4g} s" in shown[4]
    assert f"ω {motion.omega.min():.4g} … {motion.omega.max():.4g} rad/s" in shown[4]


def test_a_driver_with_masked_values_is_refused_rather_than_solved_at_what_the_mask_hides(ratchet):
    """np.ma.masked_invalid(...) keeps its hidden values: the motion came out at them, as if the mask were not
    there."""
    angles = np.ma.masked_array([0.1, 0.2, 0.3], mask=[False, True, False])
    with pytest.raises(graphplan.SceneError, match=r"^driver: has masked values \(driver\[1\]\), which the solve "
                                                   r"cannot leave out: give driver\.compressed\(\)"):
        ratchet.solve(driver=angles)
    assert ratchet.solve(driver=angles.compressed()).driver.tolist() == [0.1, 0.3]
    assert ratchet.solve(driver=np.ma.masked_array([0.1, 0.2])).count == 2  # a mask that hides nothing


def test_a_scene_mistyped_in_its_units_is_warned_of_in_python_as_on_the_command_line():
    """A crank's speed typed in rpm (ω = 1450) gave plans a hundred times too fast in a notebook with no word: the
    command line warned of it, scene.analyse() and scene.plan(n) kept the warning in analysis.warnings alone."""
    import tomllib

    tables = tomllib.loads(Path(RATCHET).read_text(encoding="utf-8"))
    tables["driver"]["omega"] = -1450.0
    slipped = graphplan.load(tables)
    told_so = r"^speed-in-rpm: driver\.omega = -1450 rad/s"
    for call in (slipped.analyse, lambda: slipped.plan(5)):
        with pytest.warns(UserWarning, match=told_so) as told:
            call()
        assert Path(told[0].filename).name == Path(__file__).name  # at the notebook's line, not graphplan's
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        graphplan.load(RATCHET).analyse()
        graphplan.load(RATCHET).plan(5)


@pytest.mark.parametrize(("kind", "locale", "error", "told"), [
    ("slider_crank", "en", ValueError, "did you mean 'slider-crank'?"),
    ("Shaper", "en", ValueError, "did you mean 'shaper'?"),
    ("shaper", "RU", ValueError, "no locale 'RU'; there are en, ru, zh; did you mean 'ru'?"),
    (3, "en", TypeError, r"a starter's kind is one of crank-rocker, .* \(got 3\)"),
    ("shaper", None, TypeError, r"a starter's locale is one of en, ru, zh \(got None\)")])
def test_a_starter_asked_for_wrongly_is_told_the_kind_or_locale_meant(kind, locale, error, told):
    """graphplan.starter("slider_crank") was told only the kinds there are; starter(3) raised a ValueError."""
    with pytest.raises(error, match=told):
        graphplan.starter(kind, locale)
    assert graphplan.load_text(graphplan.starter("slider-crank")).title
