"""Units a scene may give that are not SI, as factors to SI."""

from __future__ import annotations

import math

#: rad/s in one revolution per minute.
RPM = math.pi / 30.0
