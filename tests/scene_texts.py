"""Scene texts that many tests start from, written once so that a change to the scene format changes them once."""


def central_slider_crank(radius: float, rod: float, omega: float) -> str:
    """A weightless central slider-crank: the crank OA (link 2, ``radius``) turning at ``omega`` rad/s about O, the
    rod AB (link 3, ``rod``) and the slider B (link 4) on a guide through O along x.  The caller adds the loads,
    positions and friction after it."""
    return f"""
[scene]
gravity = 0.0
[frame]
points = {{ O = [0.0, 0.0] }}
[driver]
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
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"
"""
