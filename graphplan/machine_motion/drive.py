"""What drives and holds the shaft: the motors with their characteristics, a brake, a clutch, the state at the start."""

from __future__ import annotations

import math
from dataclasses import dataclass

MOTOR_KINDS = ("constant", "linear", "kloss")


def require_positive(owner: str, name: str, value: float) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise ValueError(f"{owner}.{name}: must be a finite number > 0 (got {value!r})")


def require_non_negative(owner: str, name: str, value: float) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
        raise ValueError(f"{owner}.{name}: must be a finite number >= 0 (got {value!r})")


class _Motor:
    """What every motor shares: the gear to the driving shaft and the rotor's inertia."""

    gear_ratio: float
    rotor_inertia: float

    def _check_drive(self) -> None:
        require_positive(type(self).__name__, "gear_ratio", self.gear_ratio)
        require_non_negative(type(self).__name__, "rotor_inertia", self.rotor_inertia)

    def characteristic(self, motor_speed: float) -> float:  # pragma: no cover - every motor has one
        """The torque on the motor's own shaft at its own speed, N·m."""
        raise NotImplementedError

    @property
    def no_load_speed(self) -> float | None:
        """The motor's speed at zero torque, rad/s; None for a constant torque."""
        return None

    def shaft_torque(self, shaft_speed: float) -> float:
        """The motor's torque reduced to the driving shaft, N·m: ``u·M(u·ω)`` (an ideal gear)."""
        u = self.gear_ratio
        return u * self.characteristic(u * shaft_speed)

    @property
    def reduced_inertia(self) -> float:
        """The rotor's inertia reduced to the driving shaft, ``J·u²``, kg·m²."""
        return self.rotor_inertia * self.gear_ratio ** 2

    @property
    def shaft_no_load_speed(self) -> float | None:
        """The driving shaft's speed at which the motor gives no torque, rad/s."""
        speed = self.no_load_speed
        return None if speed is None else speed / self.gear_ratio


@dataclass(frozen=True)
class ConstantTorque(_Motor):
    """A driving torque independent of speed, N·m on the motor's shaft."""

    torque: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.torque, (int, float)) and math.isfinite(self.torque)):
            raise ValueError(f"ConstantTorque.torque: must be a finite number (got {self.torque!r})")
        self._check_drive()

    def characteristic(self, motor_speed: float) -> float:
        return float(self.torque)


@dataclass(frozen=True)
class LinearMotor(_Motor):
    """A straight characteristic ``M = M0·(1 − ω/ω0)``: stall torque M0, no-load speed ω0 (rad/s)."""

    stall_torque: float
    no_load: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        require_positive("LinearMotor", "stall_torque", self.stall_torque)
        require_positive("LinearMotor", "no_load", self.no_load)
        self._check_drive()

    @classmethod
    def through(cls, first: tuple[float, float], second: tuple[float, float], **drive: float) -> LinearMotor:
        """The straight line through two points ``(speed rad/s, torque N·m)`` of the characteristic."""
        (w1, m1), (w2, m2) = first, second
        if w1 == w2:
            raise ValueError(f"LinearMotor.through: the two points need different speeds (got {w1!r} twice)")
        slope = (m2 - m1) / (w2 - w1)
        if not slope < 0:
            raise ValueError(f"LinearMotor.through: the torque must fall as the speed rises (slope {slope!r} N·m·s)")
        stall = m1 - slope * w1
        return cls(stall_torque=stall, no_load=-stall / slope, **drive)

    @property
    def no_load_speed(self) -> float:
        return self.no_load

    def characteristic(self, motor_speed: float) -> float:
        return self.stall_torque * (1.0 - motor_speed / self.no_load)


@dataclass(frozen=True)
class KlossMotor(_Motor):
    """An induction motor by Kloss' formula ``M = 2·Mmax/(s/sk + sk/s)``.

    Parameters
    ----------
    power
        Rated power, W.
    synchronous_speed
        ω_s, rad/s (``2π·n_s/60``).
    rated_slip
        s_n, the slip at the rated point.
    overload
        λ = Mmax/Mrated > 1.
    """

    power: float
    synchronous_speed: float
    rated_slip: float
    overload: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        require_positive("KlossMotor", "power", self.power)
        require_positive("KlossMotor", "synchronous_speed", self.synchronous_speed)
        if not (isinstance(self.rated_slip, (int, float)) and 0 < self.rated_slip < 1):
            raise ValueError(f"KlossMotor.rated_slip: must be between 0 and 1 (got {self.rated_slip!r})")
        if not (isinstance(self.overload, (int, float)) and math.isfinite(self.overload) and self.overload > 1):
            raise ValueError(f"KlossMotor.overload: must be > 1, it is Mmax/Mrated (got {self.overload!r})")
        self._check_drive()

    @classmethod
    def from_rated_speed(cls, power: float, rated_speed: float, rated_slip: float, overload: float,
                         **drive: float) -> KlossMotor:
        """From the rated (not synchronous) speed, rad/s: ``ω_s = ω_n/(1 − s_n)``."""
        require_positive("KlossMotor", "rated_speed", rated_speed)
        if not (isinstance(rated_slip, (int, float)) and 0 < rated_slip < 1):
            raise ValueError(f"KlossMotor.rated_slip: must be between 0 and 1 (got {rated_slip!r})")
        return cls(power, rated_speed / (1.0 - rated_slip), rated_slip, overload, **drive)

    @property
    def rated_speed(self) -> float:
        """ω_n = ω_s·(1 − s_n), rad/s."""
        return self.synchronous_speed * (1.0 - self.rated_slip)

    @property
    def rated_torque(self) -> float:
        """M_n = P/ω_n, N·m."""
        return self.power / self.rated_speed

    @property
    def max_torque(self) -> float:
        """Mmax = λ·M_n, N·m."""
        return self.overload * self.rated_torque

    @property
    def critical_slip(self) -> float:
        """s_k = s_n·(λ + √(λ² − 1)): the root of Kloss' formula through the rated point on the stable branch."""
        lam = self.overload
        return self.rated_slip * (lam + math.sqrt(lam * lam - 1.0))

    @property
    def no_load_speed(self) -> float:
        return self.synchronous_speed

    def characteristic(self, motor_speed: float) -> float:
        # 2·Mmax/(s/sk + sk/s) written so that it is finite at s = 0 (and negative above ω_s).
        s = 1.0 - motor_speed / self.synchronous_speed
        sk = self.critical_slip
        return 2.0 * self.max_torque * s * sk / (s * s + sk * sk)


Motor = ConstantTorque | LinearMotor | KlossMotor


@dataclass(frozen=True)
class Brake:
    """A braking torque on the driving shaft from time ``at`` on: ``torque + damping·ω``."""

    torque: float = 0.0
    damping: float = 0.0
    at: float = 0.0

    def __post_init__(self) -> None:
        require_non_negative("Brake", "torque", self.torque)
        require_non_negative("Brake", "damping", self.damping)
        if not (isinstance(self.at, (int, float)) and math.isfinite(self.at)):
            raise ValueError(f"Brake.at: must be a finite time (got {self.at!r})")
        if self.torque == 0 and self.damping == 0:
            raise ValueError("Brake: needs torque > 0 or damping > 0")


@dataclass(frozen=True)
class Clutch:
    """A friction clutch between the driving half and the machine's driving shaft.

    Parameters
    ----------
    torque
        The torque it passes while slipping (its capacity), N·m.
    engage_at
        When it is engaged, s; before that the machine is not driven.
    inertia
        The driving half's inertia besides the motor's rotor, reduced to the driving shaft, kg·m².
    """

    torque: float
    engage_at: float = 0.0
    inertia: float = 0.0

    def __post_init__(self) -> None:
        require_positive("Clutch", "torque", self.torque)
        require_non_negative("Clutch", "inertia", self.inertia)
        if not (isinstance(self.engage_at, (int, float)) and math.isfinite(self.engage_at)):
            raise ValueError(f"Clutch.engage_at: must be a finite time (got {self.engage_at!r})")


@dataclass(frozen=True)
class Start:
    """The state at the start: the shaft's angle (rad) and speed (rad/s), and with a clutch the
    driving half's speed reduced to the shaft (default: that of the shaft)."""

    omega: float = 0.0
    angle: float = 0.0
    driving_omega: float | None = None
    time: float = 0.0

    def __post_init__(self) -> None:
        require_non_negative("Start", "omega", self.omega)
        if self.driving_omega is not None:
            require_non_negative("Start", "driving_omega", self.driving_omega)
        for name in ("angle", "time"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value)):
                raise ValueError(f"Start.{name}: must be a finite number (got {value!r})")


REST = Start()
