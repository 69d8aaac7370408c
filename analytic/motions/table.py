"""A shake table as a speed-limited actuator: what the table does when its servo cannot follow the command.

docs/validation.md#22-what-makes-the-arches-slide-on-the-shake-table. The command is an acceleration
history (a one-cycle sine, a record), integrated to the commanded velocity ``v_c`` and position
``x_c``. The servo is a first-order position loop with velocity feed-forward, its velocity saturated
and, optionally, its acceleration capped::

    v_target = clip(v_c + (x_c - x) / tau, -v_max, v_max)      (tau None: no position loop, v_target = clip(v_c))
    v(t + dt) = v + clip(v_target - v, -a_max dt, a_max dt)

Below both limits the table follows the command exactly (the feed-forward needs no error), so the
sine comes back as the sine. At the speed limit the table's acceleration drops to zero at once and
the table falls behind; with a position loop it then stays at ``v_max`` until the error is recovered
and decelerates harder than the command did: the history is no longer a sine. After the command the
table settles on the commanded end position (an appended stretch of rest command).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from analytic.motions.inputs import GroundMotion, SampledMotion, SinePulse
from foundation.errors import ArchdemInputError

#: The reference study's table: a servo motor of nominal speed 1000 mm/s [m/s].
LAB_TABLE_SPEED = 1.0
#: Settling after the command ends: stop once the table is within these of rest at the commanded end
#: position [m, m/s], or after MAX_SETTLE_S [s].
SETTLE_X, SETTLE_V, MAX_SETTLE_S = 1e-6, 1e-5, 2.0


class TableHistory(NamedTuple):
    """The table's motion at ``t_k = k dt``: acceleration [m/s^2], velocity [m/s], position [m]."""

    accel: np.ndarray
    velocity: np.ndarray
    position: np.ndarray
    dt: float


def _positive(name: str, v: float | None, allow_none: bool = True) -> None:
    if v is None and allow_none:
        return
    if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
        raise ArchdemInputError(f"{name} must be a positive number, got {v!r}")


def servo_table(accel: np.ndarray, dt: float, v_max: float, tau: float | None = None,
                a_max: float | None = None) -> TableHistory:
    """The table's motion when commanded the acceleration history ``accel`` [m/s^2] sampled every ``dt``
    [s] (starting at rest), through a servo whose speed never exceeds ``v_max`` [m/s]; ``tau`` [s] the
    position loop's time constant (None: a velocity command, the lost displacement is not recovered),
    ``a_max`` [m/s^2] the actuator's acceleration cap (None: none). The history runs past the command
    until the table has settled (at most ``MAX_SETTLE_S``). See the module docstring."""
    a_c = np.asarray(accel, dtype=float)
    if a_c.ndim != 1 or len(a_c) < 2 or not np.all(np.isfinite(a_c)):
        raise ArchdemInputError("the commanded acceleration must be a 1-D array of at least 2 finite values")
    _positive("time step dt", dt, allow_none=False)
    _positive("table speed v_max", v_max, allow_none=False)
    _positive("servo time constant tau", tau)
    _positive("table acceleration cap a_max", a_max)
    # commanded velocity and position by the trapezoid rule, the same rule the table's are integrated with
    v_c = np.concatenate([[0.0], np.cumsum(0.5 * (a_c[1:] + a_c[:-1]) * dt)])
    x_c = np.concatenate([[0.0], np.cumsum(0.5 * (v_c[1:] + v_c[:-1]) * dt)])
    n_extra = int(math.ceil(MAX_SETTLE_S / dt))
    v = np.zeros(len(a_c) + n_extra)
    x = np.zeros(len(a_c) + n_extra)
    dv_cap = math.inf if a_max is None else a_max * dt
    end = len(v) - 1
    for k in range(len(v) - 1):
        inside = k + 1 < len(a_c)
        vc, xc_k = (v_c[k + 1], x_c[k]) if inside else (0.0, x_c[-1])
        if not inside and abs(x_c[-1] - x[k]) * (tau is not None) < SETTLE_X and abs(v[k]) < SETTLE_V:
            end = k
            break
        target = vc + ((xc_k - x[k]) / tau if tau is not None else 0.0)
        target = min(v_max, max(-v_max, target))
        v[k + 1] = v[k] + min(dv_cap, max(-dv_cap, target - v[k]))
        x[k + 1] = x[k] + 0.5 * (v[k] + v[k + 1]) * dt
    v, x = v[:end + 1], x[:end + 1]
    a = np.zeros_like(v)
    # central differences: second order where the table follows the command; a jump spreads over 2 samples
    a[1:-1] = (v[2:] - v[:-2]) / (2 * dt)
    if len(v) > 2:  # one-sided, second order too
        a[0] = (-3 * v[0] + 4 * v[1] - v[2]) / (2 * dt)
        a[-1] = (3 * v[-1] - 4 * v[-2] + v[-3]) / (2 * dt)
    else:
        a[:] = (v[-1] - v[0]) / dt
    return TableHistory(a, v, x, float(dt))


def servo_sine(a: float, f: float, v_max: float = LAB_TABLE_SPEED, tau: float | None = None,
               a_max: float | None = None, dt: float = 1.25e-4) -> GroundMotion:
    """The table's acceleration when commanded a one-cycle sine of amplitude ``a`` [m/s^2] and frequency
    ``f`` [Hz] (:class:`SinePulse`), through :func:`servo_table` sampled every ``dt`` [s]. The plain
    :class:`SinePulse` when the servo follows it (peak speed ``a / (pi f) <= v_max``, ``a <= a_max``)."""
    sine = SinePulse(float(a), float(f))
    if abs(a) / (math.pi * f) <= v_max and (a_max is None or abs(a) <= a_max):
        return sine
    n = int(math.ceil(sine.duration / dt)) + 1
    hist = servo_table(sine.acceleration(dt * np.arange(n)), dt, v_max, tau, a_max)
    return SampledMotion(hist.accel, dt, name=f"servo sine {f:g} Hz {a:.4g} m/s^2",
                         source=f"one-cycle sine through a servo: v_max {v_max:g} m/s, tau "
                                f"{'none' if tau is None else f'{tau:g} s'}, a_max "
                                f"{'none' if a_max is None else f'{a_max:g} m/s^2'}")


__all__ = ["LAB_TABLE_SPEED", "TableHistory", "servo_sine", "servo_table"]
