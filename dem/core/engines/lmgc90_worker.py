"""The child process that holds one LMGC90 simulation (``python -m dem.core.engines.lmgc90_worker``).

LMGC90 keeps its state in Fortran module variables: one simulation per process, and a fatal error
stops the whole process. :class:`dem.core.engines.lmgc90_engine.LMGC90Engine` therefore runs every
simulation in one of these workers and talks to it over its standard input and output with pickled
tuples (``build``, ``gravity``, ``step`` send nothing back; ``sync``, ``state`` and ``contacts`` answer
``("ok", data)`` or ``("error", message)``). Only numpy and the binding's compiled module are
imported here; the frame is LMGC90's (z up), the engine maps it to archdem's.

Quirks of compas_lmgc90 0.1.11 handled here: its Python ``Solver`` imports the COMPAS stack, so the
compiled module is driven directly; the gravity is fixed at (0, 0, -9.81) by ``set_materials`` and
has no setter, so it is written into the bulk-behaviour module's exported gravity components, which
LMGC90 reads at every step; its ``set_see_tables`` writes one see-table row (one law for every pair,
every contactor coloured ``REDxx``), so the see table is written here through LMGC90's own procedures
that the extension exports (``tact_behaviour``'s see list, ``RBDY3``'s contactor colour): joints
``REDxx``-``REDxx`` with the joint law, the base's contactors ``GRND_`` with the base law; the binding
returns positions and inertia frames only, so velocities are the difference of the last two steps' poses.
"""
from __future__ import annotations

import ctypes
import os
import pickle
import sys

import numpy as np


JOINT_LAW, BASE_LAW = "iqsc0", "iqsc1"  # contact-law nicknames (5 characters)
BODY_COLOR, BASE_COLOR = "REDxx", "GRND_"  # contactor colours: the binding's for every body, and the base's


def _c5(s: str) -> ctypes.c_char_p:
    return ctypes.c_char_p(s.encode())


def _see_table(lib, alert: float) -> None:
    """The see table (instead of the binding's ``set_see_tables``): block-block pairs with the joint law,
    block-base pairs (either as candidate) with the base law. Fortran procedures: arguments by reference,
    the lengths of the character arguments appended."""
    def proc(name: str):
        return getattr(lib, f"__tact_behaviour_MOD_{name}")

    proc("close_tact_behav_ll")()
    proc("open_see_ll")()
    a, ga = ctypes.c_double(alert), ctypes.c_double(0.0)
    for cd, law, an in ((BODY_COLOR, JOINT_LAW, BODY_COLOR), (BODY_COLOR, BASE_LAW, BASE_COLOR),
                        (BASE_COLOR, BASE_LAW, BODY_COLOR)):
        proc("add_to_see_ll")(_c5("RBDY3"), _c5("POLYR"), _c5(cd), _c5(law), _c5("RBDY3"), _c5("POLYR"), _c5(an),
                              ctypes.byref(a), ctypes.byref(ga), *([ctypes.c_size_t(5)] * 7))
    proc("close_see_ll")()


class Simulation:
    """One LMGC90 simulation built from a ``build`` message (see :func:`build_message` in the engine)."""

    def __init__(self, spec: dict) -> None:
        from compas_lmgc90 import _lmgc90

        self.dt = float(spec["dt"])
        lm = self.lm = _lmgc90.LMGC90Solver()
        lm.initialize(self.dt, float(spec["theta"]), False)
        lm.add_one_tact_behav(JOINT_LAW, spec["law"], [float(x) for x in spec["joint_params"]])
        lm.add_one_tact_behav(BASE_LAW, spec["law"], [float(x) for x in spec["base_params"]])
        densities = np.array(sorted({float(b["density"]) for b in spec["bodies"]}))
        lm.set_materials(densities)
        material = {d: f"s{k + 1:04d}" for k, d in enumerate(densities)}  # the binding's material names
        self.lib = lib = ctypes.CDLL(_lmgc90.__file__)
        _see_table(lib, float(spec["alert"]))
        bodies = spec["bodies"]
        lm.set_nb_bodies(len(bodies))
        for i, b in enumerate(bodies):
            v, f, c = np.asarray(b["vertices"], float), np.asarray(b["triangles"], int), np.asarray(b["centroid"], float)
            fixed = bool(b["support"])
            drv = list(range(1, 7)) if fixed else []  # a support: every velocity dof held at zero
            lm.set_one_polyr(material[float(b["density"])], c.tolist(), (f + 1).ravel().tolist(),
                             (v - c).ravel().tolist(), len(drv), 0)
            for d in drv:
                lm.set_drvdof(i + 1, d, [0.0] * 6, True, False)
            if fixed:
                getattr(lib, "__rbdy3_MOD_set_color_rbdy3")(ctypes.byref(ctypes.c_int(i + 1)), ctypes.byref(ctypes.c_int(1)),
                                                            _c5(BASE_COLOR), ctypes.c_size_t(5))
        lm.close_before_computing()
        init = lm.get_initial_state()
        self.n = len(bodies)
        self.coor = np.array(init.init_bodies, float).reshape(self.n, 3)
        self.frame = np.array(init.init_body_frames, float).reshape(self.n, 3, 3)
        self.prev = (self.coor.copy(), self.frame.copy())
        self.last = None
        self.grav = [ctypes.c_double.in_dll(lib, f"__bulk_behaviour_MOD_grav{k}") for k in (1, 2, 3)]

    def set_gravity(self, g) -> None:
        for c, x in zip(self.grav, g):
            c.value = float(x)

    def step(self, n: int) -> None:
        for _ in range(n):
            self.prev = (self.coor, self.frame)
            r = self.lm.compute_one_step()
            self.coor = np.array(r.bodies, float).reshape(self.n, 3)
            self.frame = np.array(r.body_frames, float).reshape(self.n, 3, 3)
            self.last = r

    def state(self) -> dict:
        """Centres, inertia frames (as the binding flattens them) and the previous step's, for velocities."""
        return {"coor": self.coor, "frame": self.frame, "prev_coor": self.prev[0], "prev_frame": self.prev[1]}

    def contacts(self) -> dict:
        r = self.last
        if r is None or len(r.interaction_coords) == 0:
            z = np.zeros((0, 3))
            return {"bodies": np.zeros((0, 2), int), "coor": z, "normal": z, "rloc": z, "force": z}
        return {"bodies": np.array(r.interaction_bodies, int).reshape(-1, 2),
                "coor": np.array(r.interaction_coords, float).reshape(-1, 3),
                "normal": np.array(r.interaction_normals, float).reshape(-1, 3),
                "rloc": np.array(r.interaction_rloc, float).reshape(-1, 3),
                "force": np.array(r.interaction_force_global, float).reshape(-1, 3)}

    def close(self) -> None:
        self.lm.finalize()


QUERIES = ("sync", "state", "contacts")  # the commands answered


def main() -> None:
    # the protocol keeps the pipe of fd 1; LMGC90's own prints go to stderr
    out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)
    inp = sys.stdin.buffer
    sim, error = None, None
    while True:
        try:
            msg = pickle.load(inp)
        except EOFError:
            break
        cmd = msg[0]
        if cmd == "close":
            break
        try:
            if error is not None and cmd in QUERIES:
                pickle.dump(("error", error), out)
                out.flush()
                continue
            if error is not None:
                continue
            if cmd == "build":
                sim = Simulation(msg[1])
            elif cmd == "gravity":
                sim.set_gravity(msg[1])
            elif cmd == "step":
                sim.step(int(msg[1]))
            elif cmd in QUERIES:
                pickle.dump(("ok", None if cmd == "sync" else getattr(sim, cmd)()), out)
                out.flush()
            else:
                raise ValueError(f"unknown command {cmd!r}")
        except Exception as e:  # answered now to a query, otherwise at the next one; the parent raises it
            error = f"{type(e).__name__}: {e}"
            if cmd in QUERIES:
                pickle.dump(("error", error), out)
                out.flush()
    if sim is not None:
        sim.close()
    out.close()


if __name__ == "__main__":
    main()
