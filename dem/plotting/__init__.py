"""Figures of the simulator's results (matplotlib's object-oriented API; no backend is chosen here)."""
