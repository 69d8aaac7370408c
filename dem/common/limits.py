"""The bounds of a sine pulse the commands accept: beyond them a run answers nothing physical."""
from __future__ import annotations

MIN_SINE_HZ, MAX_SINE_HZ = 0.01, 100.0  # a 100 s cycle; at dt 0.5 ms, 20 steps per cycle
MAX_AMPLITUDE_G = 100.0
