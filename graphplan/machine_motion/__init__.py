"""The machine's motion in time: its equation of motion reduced to the driving shaft, integrated.

The machine is reduced to its driving shaft (the dynamic model of a course in the theory of
machines): a reduced moment of inertia ``Je(φ)`` and the reduced moments of the forces.  Its
equation of motion in the differential form is

    Je(φ)·dω/dt + ½·(dJe/dφ)·ω² = Md(ω) − Mr(φ, ω) − Mb(ω)

with ``Md`` the motor's torque on the shaft, ``Mr`` the reduced moment of the resisting forces
(positive when it resists forward motion; a driving force reduced to the shaft enters with a
minus sign) and ``Mb`` a brake.  As a first-order system in ``(φ, ω)`` it is integrated with
:func:`scipy.integrate.solve_ivp`.

* :class:`Machine` takes ``Je``, ``dJe/dφ`` and ``Mr`` as numbers, callables or periodic samples
  on an equally spaced grid over one turn ``[0, 2π)``, interpolated by a periodic quintic spline
  (:func:`scipy.interpolate.make_interp_spline`); ``Mr`` also as a :class:`PiecewiseMoment`, smooth
  between its jumps, at each of which the integration stops and goes on with the next piece.
* Motors: :class:`ConstantTorque`, :class:`LinearMotor` (``Md = M0·(1 − ω/ω0)``) and
  :class:`KlossMotor` (an induction motor by Kloss' formula), each with a gear ratio
  ``u = ω_motor/ω_shaft`` and the rotor's inertia, reduced to the shaft as ``J·u²``.
* :class:`Brake`: a constant and a speed-proportional braking torque switched on at a time.
* :class:`Clutch`: a friction clutch between the driving half (the motor's rotor and what turns
  with it) and the machine; it slips with a constant torque until the speeds are equal, then
  locks (solve_ivp events find both instants) and slips again if the torque it must pass
  exceeds its capacity.
* :func:`simulate` integrates a start-up from rest (or from a given state), the steady state
  (found when the cycle's mean speed and its coefficient of speed fluctuation δ stop changing)
  and a run-down, and returns the time histories with each cycle's ``ωm``, ``ωmax``, ``ωmin``
  and ``δ``.
* :func:`read_motion` reads the motion's keys of the scene's ``[dynamics]`` table.

The modules, in the order they build on one another: ``moment`` (a moment over the turn that
jumps), ``shaft`` (the machine reduced to its shaft), ``drive`` (motors, brake, clutch, the start), ``cycles`` (the turns of a run and the
steady state), ``integrator`` (each phase's equations, integrated segment by segment),
``method`` (the running speed and the solver chosen by stiffness), ``simulation``
(:func:`simulate`, :func:`engage_clutch`) and ``spec`` (the scene's keys).

Conventions
-----------
SI units, angles in radians, speeds in rad/s (revolutions per minute only in the scene keys
named ``*_rpm``).  The driving shaft turns forward, ``ω ≥ 0``: at rest the resisting forces and
the brake are passive (they hold the machine but cannot turn it backwards).

δ is the textbook one, ``(ωmax − ωmin)/ωm`` with ``ωm = (ωmax + ωmin)/2``, for which the
flywheel relation ``ΔWmax = Je·ωm²·δ`` is exact at constant ``Je``; the time-averaged speed of a
cycle, ``2π/T``, is given as well.
"""

from ..units import RPM
from .cycles import Cycle, SteadyState, find_cycles, find_steady_state
from .drive import MOTOR_KINDS, REST, Brake, Clutch, ConstantTorque, KlossMotor, LinearMotor, Motor, Start
from .integrator import MOST_EVALUATIONS
from .method import STIFFNESS_THRESHOLD, choose_method, is_stiff, running_speed
from .moment import PiecewiseMoment
from .shaft import TWO_PI, Machine, periodic_spline
from .simulation import (
    DEFAULT_RTOL,
    METHODS,
    MOST_CYCLES,
    SMALLEST_RTOL,
    ClutchEngagement,
    MachineMotion,
    Stall,
    engage_clutch,
    simulate,
)
from .spec import MOST_TURNS, MotionSpec, read_motion

__all__ = [
    "DEFAULT_RTOL", "METHODS", "MOST_CYCLES", "MOST_EVALUATIONS", "MOST_TURNS", "MOTOR_KINDS", "REST", "RPM", "SMALLEST_RTOL",
    "STIFFNESS_THRESHOLD", "TWO_PI", "Brake", "Clutch", "ClutchEngagement", "ConstantTorque", "Cycle", "KlossMotor",
    "LinearMotor", "Machine", "MachineMotion", "MotionSpec", "Motor", "PiecewiseMoment", "Stall", "Start",
    "SteadyState", "choose_method", "engage_clutch", "find_cycles", "find_steady_state", "is_stiff", "periodic_spline",
    "read_motion", "running_speed", "simulate",
]
