"""Engine inputs that are the same on every machine.

Near a threshold an engine's outcome is chaotic: a difference in the last bit of one vertex
or of the gravity of one step can move a tilt lambda by several per cent. Such differences
come from the machine, not from the model: numpy picks SIMD kernels (AVX-512 or not) and
glibc picks FMA variants of ``sin``/``cos``/``atan`` at run time, and BLAS/LAPACK kernels
(``eigh``, ``@``) differ by CPU (measured: docs/engines.md#7-reproducibility-and-input-rounding).

Every number an engine receives therefore goes through these functions: lengths and
accelerations are rounded to a fixed grid, masses and moments to 10 significant digits, the
principal frames get a canonical sign and a rounded quaternion. Upstream differences of a
few units in the last place then land in the same grid cell except with a probability of
about 1e-7 per number (grid / ulp), while the rounding itself (1 nm, 1e-7 m/s^2) is far
below anything physical. After the rounding only IEEE-exact operations (+ - * / sqrt, rint)
are used.
"""
from __future__ import annotations

import math

import numpy as np

LENGTH_GRID = 1e-9  # [m] vertices, positions
ACCEL_GRID = 1e-7  # [m/s^2] gravity / ground acceleration of every step
QUAT_GRID = 1e-9  # quaternion components (orientation error <= ~1e-9 rad)
SIGNIFICANT = 10  # digits kept of masses and moments of inertia


def on_grid(x, grid: float = LENGTH_GRID) -> np.ndarray:
    """``x`` rounded to the nearest multiple of ``grid`` (float array of the same shape)."""
    return np.rint(np.asarray(x, dtype=float) / grid) * grid


def significant(x, digits: int = SIGNIFICANT):
    """``x`` (a number or an array) rounded to ``digits`` significant digits (decimal
    formatting is correctly rounded, so this is machine-independent)."""
    if np.ndim(x) == 0:
        return float(f"{float(x):.{digits}g}")
    return np.array([float(f"{float(v):.{digits}g}") for v in np.ravel(x)]).reshape(np.shape(x))


def accel(vec) -> np.ndarray:
    """A gravity or ground-acceleration value of one step [m/s^2] on ACCEL_GRID."""
    return on_grid(vec, ACCEL_GRID)


def principal_frame(inertia: np.ndarray) -> tuple[np.ndarray, np.ndarray, tuple[float, float, float, float]]:
    """``(R, I, q)``: principal axes (columns of the proper rotation ``R``), principal moments
    ``I`` (10 digits) and the quaternion ``q`` (x, y, z, w) of ``R``, all machine-independent.

    A diagonal inertia (axes already principal, e.g. a rectangular block) keeps the identity,
    whatever the multiplicity of its moments. Otherwise the eigenvectors get a canonical sign
    (largest component positive, then a right-handed third axis), the quaternion is rounded
    and normalised with scalar arithmetic and ``R`` is rebuilt from it.
    """
    J = np.asarray(inertia, dtype=float)
    if not np.any(J - np.diag(np.diag(J))):
        return np.eye(3), significant(np.diag(J)), (0.0, 0.0, 0.0, 1.0)
    w, v = np.linalg.eigh(J)
    v = v.copy()
    for k in range(3):
        if v[np.argmax(np.abs(v[:, k])), k] < 0:
            v[:, k] = -v[:, k]
    if np.linalg.det(v) < 0:
        v[:, 2] = -v[:, 2]
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.spatial.transform import Rotation

    q = [float(c) for c in on_grid(Rotation.from_matrix(v).as_quat(), QUAT_GRID)]
    if q[3] < 0:  # q and -q are the same rotation: one of them
        q = [-c for c in q]
    n = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    x, y, z, s = (c / n for c in q)
    R = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * s), 2 * (x * z + y * s)],
        [2 * (x * y + z * s), 1 - 2 * (x * x + z * z), 2 * (y * z - x * s)],
        [2 * (x * z - y * s), 2 * (y * z + x * s), 1 - 2 * (x * x + y * y)],
    ])
    return R, significant(w), (x, y, z, s)
