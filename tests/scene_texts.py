"""Scene texts that many tests start from, written once so that a change to the scene format changes them once."""


def central_slider_crank(radius: float, rod: float, omega: float, named_guide: bool = False,
                         locale: str | None = None) -> str:
    """A weightless central slider-crank: the crank OA (link 2, ``radius``) turning at ``omega`` rad/s about O, the
    rod AB (link 3, ``rod``) and the slider B (link 4) on a guide through O along x, given as the frame's line
    ``axis`` where ``named_guide`` (as a friction test names it).  The caller adds the loads, positions and friction
    after it."""
    locale_line = f'locale = "{locale}"\n' if locale is not None else ""
    axis_line = 'lines = { axis = { through = "O", angle = 0.0 } }\n' if named_guide else ""
    guide = '"axis"' if named_guide else '{ through = "O", angle = 0.0 }'
    return f"""
[scene]
gravity = 0.0
{locale_line}[frame]
points = {{ O = [0.0, 0.0] }}
{axis_line}[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {radius}
omega = {omega}
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = {rod}
guide = {guide}
assembly = "forward"
"""


def second_cylinder(radius: float, rod: float, from_opposite: bool, guide_deg: float = 0.0,
                    assembly: str = "forward", opposite: str = "E") -> str:
    """A second rod (link 5, ``rod``) and piston C (link 6) for :func:`central_slider_crank`'s crank of ``radius``:
    from its pin A, or, ``from_opposite``, from its point ``opposite`` half a turn from A (named either way), to C on
    a guide through O at ``guide_deg``.  The caller adds the loads and positions after it."""
    return f"""
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["{opposite if from_opposite else 'A'}", "C"]
length = {rod}
guide = {{ through = "O", angle = {guide_deg} }}
assembly = "{assembly}"
[points]
{opposite} = {{ link = 2, from = "O", toward = "A", at = {-radius} }}
"""


def slider_crank_with_masses(title: str, radius: float, rod: float, rpm: float, centres: tuple[float, float],
                             masses: tuple[float, float, float], inertias: tuple[float, float],
                             locale: str | None = None) -> str:
    """A central slider-crank under gravity with its links' masses: the crank OA (link 2, ``radius``, its centre S2
    ``centres[0]`` from O) at ``rpm``, the rod AB (link 3, ``rod``, S3 ``centres[1]`` from A) and the piston B (link
    4); ``masses`` are links 2, 3, 4's, ``inertias`` links 2 and 3's.  The caller adds the loads and positions."""
    locale_line = f'locale = "{locale}"\n' if locale is not None else ""
    return f"""
[scene]
title = "{title}"
{locale_line}gravity = 9.81
[frame]
link = 1
points = {{ O = [0.0, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {radius}
rpm = {rpm}
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = {rod}
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"
[points]
S2 = {{ link = 2, from = "O", toward = "A", at = {centres[0]} }}
S3 = {{ link = 3, from = "A", toward = "B", at = {centres[1]} }}
[links.2]
mass = {masses[0]}
centre = "S2"
inertia = {inertias[0]}
[links.3]
mass = {masses[1]}
centre = "S3"
inertia = {inertias[1]}
[links.4]
mass = {masses[2]}
centre = "B"
"""


def piston_compressor(radius: float = 0.075, rod: float = 0.30, rod_centre: float = 0.10) -> str:
    """The horizontal piston compressor (crank 0.075 m at 600 rpm, rod 0.30 m, links of 8, 3 and 4 kg) whose lengths a
    test may give in other units; the caller adds its gas load and positions."""
    return slider_crank_with_masses("Piston compressor", radius, rod, 600.0, (0.0, rod_centre), (8.0, 3.0, 4.0),
                                    (0.05, 0.03))


def engine(locale: str | None = None) -> str:
    """The single-cylinder engine (crank 0.05 m at 1500 rpm, rod 0.19 m) whose gas force drives the piston by its
    indicator diagram, expansion and compression; the caller adds its positions, consumer and dynamics."""
    return slider_crank_with_masses("Engine", 0.05, 0.19, 1500.0, (0.006, 0.055), (4.5, 1.1, 0.9), (0.012, 0.0048),
                                    locale) + """
[[loads]]       # expansion: the gas pushes the piston toward the crank as it moves there
kind = "force"
link = 4
point = "B"
angle = 180.0
stroke = { link = 4, sense = "backward" }
diagram = [[0.0, 9000.0], [0.1, 7000.0], [0.3, 4000.0], [0.6, 2000.0], [1.0, 800.0]]

[[loads]]       # compression: the gas still pushes toward the crank as the piston moves away
kind = "force"
link = 4
point = "B"
angle = 180.0
stroke = { link = 4, sense = "forward" }
diagram = [[0.0, 200.0], [0.5, 500.0], [0.8, 1200.0], [1.0, 2500.0]]
"""


def four_bar_through_a_toggle() -> str:
    """A four-bar (crank OA 0.2 m at 10 rad/s, coupler AB 0.5, rocker BC 0.7, OC 1.0) whose coupler and rocker lie in
    one line at φ = 180°, where no plan can be drawn; the caller adds its positions."""
    return """
[scene]
title = "Four-bar through a toggle"
[frame]
points = { O = [0.0, 0.0], C = [1.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.2
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.5, 0.7]
assembly = "left"
"""


def offset_slotted_lever(offset: float) -> str:
    """A slotted lever about C = (0.06, −0.04) m driven by a crank OA = 0.15 m at 10 rad/s, its slide ``offset`` m to
    the left of C, so that the block reaches it only while |CA| > |offset|; the caller adds its positions."""
    return f"""
[scene]
title = "Slotted lever with an offset slide"
[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.06, -0.04] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.15
omega = 10.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = {offset}
"""


def slider_crank_with_a_resisting_force(title: str, guide_angle: float = 0.0, force_angle: float = 180.0,
                                        link: int = 4, point: str = "B") -> str:
    """A slider-crank (crank OA 0.1 m at 10 rad/s, rod AB 0.35 m, a slider of 2 kg on a guide through O at
    ``guide_angle``) with a resisting force of 100 N at ``point`` of ``link`` along ``force_angle``, for the tests of a
    load with no motion to resist; the caller adds any other loads and the positions."""
    return f"""
[scene]
title = "{title}"
[frame]
link = 1
points = {{ O = [0.0, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.35
guide = {{ through = [0.0, 0.0], angle = {guide_angle} }}
assembly = "forward"
[links.4]
mass = 2.0
centre = "B"
[[loads]]
kind = "force"
link = {link}
point = "{point}"
value = 100.0
angle = {force_angle}
resisting = true
"""


def wedge_lift(angle: float, load: float, velocity: float, count: int, title: str = "Wedge lift") -> str:
    """A wedge lift: the wedge (link 2, its point A) driven along the floor's line through G at ``velocity`` m/s
    over 0.1 m, under a block 3 on its incline rising at ``angle`` degrees, pinned at B to a rod 4 that slides in the
    frame's vertical post through P and carries ``load`` N down; ``count`` positions, position 2's plans.  The caller
    adds the friction and anything else after it."""
    return f"""
[scene]
title = "{title}"
gravity = 0.0
[frame]
points = {{ G = [0.0, 0.0], P = [0.3, 0.0] }}
lines = {{ post = {{ through = "P", angle = 90.0 }} }}
[driver]
kind = "slider"
link = 2
joint = "A"
guide = {{ through = "G", angle = 0.0 }}
travel = [0.0, 0.1]
velocity = {velocity}
[[groups]]
kind = "PRP"
links = [3, 4]
joints = ["B"]
guides = [{{ link = 2, through = "A", angle = {angle} }}, "post"]
offsets = [0.0, 0.0]
[[loads]]
kind = "force"
link = 4
point = "B"
value = {load}
angle = 270.0
[positions]
count = {count}
plans = [2]
"""


def watt_ii(*, every_velocity_plan: bool = False, sheet: str | None = None) -> str:
    """A Watt II six-bar: two four-bars in series, O-A-B-C and, from D on the ternary rocker CBD, D-E-F; its
    output link 6 works turning ccw.  ``every_velocity_plan`` asks for the velocity plans of every position, and
    ``sheet`` for the course-project sheets in that format."""
    drawing = f'[drawing]\nsheet = "{sheet}"\n' if sheet is not None else ""
    every = 'velocity_plans = "all"\n' if every_velocity_plan else ""
    return f"""
[scene]
title = "Watt II six-bar linkage"
[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.35, 0.0], F = [0.60, 0.25] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.10
omega = 12.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
assembly = "left"
[points]
D = {{ link = 4, from = "C", toward = "B", at = 0.12, offset = -0.10 }}
[[groups]]
kind = "RRR"
links = [5, 6]
joints = ["D", "E", "F"]
lengths = [0.30, 0.20]
assembly = "right"
[positions]
count = 12
start = "extreme"
working = {{ link = 6, sense = "ccw" }}
plans = [3, 9]
{every}{drawing}"""


def oscillating_cylinder(offset: float) -> str:
    """An inverted slider-crank (RPR): a crank drives the piston rod 3 in the cylinder 4 that rocks about C, the rod's
    axis ``offset`` m from A; E is a point of the rod, laid off from A toward C."""
    return """
[scene]
title = "Oscillating-cylinder mechanism"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.30, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.08
rpm = 120
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = OFFSET
[points]
E = { link = 3, from = "A", toward = "C", at = 0.12, offset = 0.03 }
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "ccw" }
plans = [4, 10]
""".replace("OFFSET", repr(offset))


def crank_press(dynamics: str, force: float = 20000.0, share: float = 0.3, header: str = "",
                positions: str = "") -> str:
    """A crank press (crank OA 0.1 m at 60 rpm, rod AB 0.4 m, a slider of 5 kg on a guide through O) whose
    ``force`` N resists the slider over the last ``share`` of its working stroke, 0.2 m long; ``dynamics`` is its
    [dynamics] table's body, ``header`` more lines of [scene], ``positions`` more lines of [positions]."""
    return f"""
[scene]
title = "Crank press flywheel"
gravity = 9.81
{header}
[frame]
link = 1
points = {{ O = [0.0, 0.0] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
rpm = 60.0
epsilon = 0.0

[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.4
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"

[links.2]
inertia = 0.5

[links.4]
mass = 5.0
centre = "B"

[[loads]]
kind = "force"
link = 4
point = "B"
value = {force}
angle = 180.0
resisting = true
during = {{ from = {1 - share}, to = 1.0 }}

[positions]
count = 12
start = "extreme"
working = {{ link = 4, sense = "forward" }}
{positions}
[dynamics]
{dynamics}"""


# The flywheel starter's press known by its power cycle (driving constant; 367.7 W for a third of the turn and 3677 W
# for two thirds, n = 100 rpm, δ = 0.05), the published example test_textbook_dynamics checks: the [dynamics] table's
# own lines, which the caller follows with its motor, flywheel shaft or another key of the table.
POWER_CYCLE_PRESS = """[dynamics]
rpm = 100
delta = 0.05
resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]
driving = "constant"
inertia = 0.0
"""


def journal_friction(radii: dict[str, float], f: float = 0.1) -> str:
    """A ``[[friction]]`` table for each journal of ``radii`` (joint: its radius, m) at the coefficient ``f``, in
    that order, to add to a scene: the friction circles a course project gives a linkage's pairs."""
    return "".join(f'\n[[friction]]\njoint = "{joint}"\nf = {f}\nradius = {radius}\n'
                   for joint, radius in radii.items())


def crank_rocker_working_its_quicker_stroke(locale: str = "en") -> str:
    """The crank-rocker starter with its working stroke the quicker one (K < 1), as the starter first had it: the
    force sheets and polygons that tests of particular layouts were written for (its sliver at position 5, its lever
    a step smaller on A3, its weightless crank's polygon on one line at the coarsest μF)."""
    from graphplan.starters import starter

    text = starter("crank-rocker", locale)
    working = next(line for line in text.splitlines() if line.startswith("working "))
    return text.replace(working, 'working     = { link = 4, sense = "ccw" }')
