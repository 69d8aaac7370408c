"""The shake table's mode map: per specimen and frequency of a one-cycle sine, the first collapse within a
speed-limited table's reach, its failure mode, the joint that slips first and the half cycle it slips in
(docs/validation.md#22).

``ModeMapSpec`` -> ``run`` (a resumable sweep, one threshold search a case) -> ``ModeMapResult`` (a row
per case, its schema declared once); ``read`` tables what a study file holds without running.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Any, ClassVar, Sequence

from analytic.motions.table import LAB_TABLE_SPEED
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.mode_map.case import SLIP_MM, mode_case
from dem.studies.sweep import StudyResult, case_key, load_study, run_study
from foundation.errors import ArchdemInputError
from specimens.catalogue import SPECIMEN_IDS, get_specimen
from specimens.constants import REFERENCE_MU_BASE

#: The map's frequencies [Hz]: the band of the laboratory's one-cycle sines.
MAP_FREQS = (2.0, 4.0, 6.0, 8.0, 10.0)
#: The scan's top over the table's reach: a command the table cannot follow, up to this ratio, is scanned.
SCAN_OVER = 1.5


def _positive(name: str, value: Any, allow_none: bool = False) -> float | None:
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise ArchdemInputError(f"mode map: {name} must be a positive number, got {value!r}")
    return float(value)


@dataclass(frozen=True)
class ModeMapSpec:
    """What to map: catalogue ``specimens`` (ids) by sine ``freqs`` [Hz], glued on the dynamics defaults.

    The table: ``table_speed`` [m/s] its speed limit (None: the ideal sine), ``tau`` [s] its position
    loop (None: a velocity command); the scan of the commanded amplitude reaches ``scan_over`` x the reach
    ``pi f reach_speed``. ``mu_base`` the feet's friction, ``contact`` the joints' contact fraction (or
    ``"calibrated"``), ``restitution``; a joint slips when both its ends moved ``slip_mm`` [mm] along it.
    The defaults are the fitted table of docs/validation.md#22."""

    specimens: tuple[str, ...] = SPECIMEN_IDS
    freqs: tuple[float, ...] = MAP_FREQS
    table_speed: float | None = LAB_TABLE_SPEED
    tau: float | None = None
    mu_base: float = REFERENCE_MU_BASE
    contact: float | str = 1.0
    restitution: float = 0.0
    reach_speed: float = LAB_TABLE_SPEED
    scan_over: float = SCAN_OVER
    slip_mm: float = SLIP_MM

    def __post_init__(self) -> None:
        ids, freqs = tuple(self.specimens), tuple(self.freqs)
        if not ids or not freqs:
            raise ArchdemInputError("mode map: give at least one specimen and one frequency")
        for sid in ids:
            get_specimen(sid)  # an unknown id is refused with the catalogue's ids
        freqs = tuple(_positive("a frequency [Hz]", f) for f in freqs)
        for what, seq in (("specimen", ids), ("frequency", freqs)):
            if len(set(seq)) != len(seq):
                raise ArchdemInputError(f"mode map: a {what} named twice in {list(seq)}")
        if not (self.contact == "calibrated" or (isinstance(self.contact, (int, float)) and not isinstance(self.contact, bool)
                                                 and 0 < self.contact <= 1)):
            raise ArchdemInputError(f"mode map: contact must be a fraction in (0, 1] or 'calibrated', got {self.contact!r}")
        if not (isinstance(self.restitution, (int, float)) and 0 <= self.restitution <= 1):
            raise ArchdemInputError(f"mode map: restitution must lie in [0, 1], got {self.restitution!r}")
        speed = _positive("the table speed [m/s]", self.table_speed, allow_none=True)
        object.__setattr__(self, "specimens", ids)
        object.__setattr__(self, "freqs", freqs)
        object.__setattr__(self, "table_speed", speed)
        # a position loop belongs to a speed-limited servo: the ideal sine has none
        object.__setattr__(self, "tau", None if speed is None else _positive("tau [s]", self.tau, allow_none=True))
        for name in ("mu_base", "reach_speed", "scan_over", "slip_mm"):
            object.__setattr__(self, name, _positive(name, getattr(self, name)))
        object.__setattr__(self, "restitution", float(self.restitution))
        object.__setattr__(self, "contact", self.contact if isinstance(self.contact, str) else float(self.contact))

    def case(self, sid: str, freq: float) -> dict:
        """The sweep case of one cell (:func:`dem.experiments.mode_map.case.mode_case`); its fields are
        those the study files have always stored, so that a study resumes across versions."""
        return {"id": sid, "freq": float(freq), "table_speed": self.table_speed, "tau": self.tau,
                "mu_base": self.mu_base, "contact": self.contact, "restitution": self.restitution,
                "scan_over": self.scan_over, "reach_speed": self.reach_speed, "slip_mm": self.slip_mm}

    def cases(self) -> list[dict]:
        """Every cell's case, specimen by specimen, frequencies in order."""
        return [self.case(s, f) for s in self.specimens for f in self.freqs]

    def title(self) -> str:
        """The map's settings in one line (the figure's title)."""
        speed = "ideal sine" if self.table_speed is None else f"table speed {self.table_speed:g} m/s" + (
            f", position loop {self.tau * 1e3:g} ms" if self.tau else ", velocity command")
        return (f"First collapse of a one-cycle sine, commanded up to {self.scan_over:g} x the table's reach "
                f"(glued, {DYNAMICS_ENGINE}; {speed}, mu_base {self.mu_base:g}, contact {self.contact}, "
                f"e {self.restitution:g})")


@dataclass(frozen=True)
class ModeMapResult(Result):
    """The map's rows, one per case (``label`` names the study it belongs to), in ``SCHEMA``'s columns: a
    case not run reads mode "not run", a case that raised "failed"; ``amplitude_g`` empty when the arch
    stands up to the scan's top (mode "none"). ``title``: the settings, for the figure."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("label", "str"), Column("id", "str"), Column("freq", "float", "Hz"),
        Column("amplitude_g", "float", "g"),  # the first collapse (commanded amplitude)
        Column("within_reach", "bool"),  # the collapse within the table's reach, where it runs the sine
        Column("mode", "str"),  # rocking, mixed, sliding; none, failed, not run
        Column("phase", "str"),  # the collapse before or after the first rebound
        Column("joint", "str"),  # the joint that slips first
        Column("t_slip_s", "float", "s"), Column("slip_half", "str"),
        Column("slid", "str"),  # the joints sliding at the end of the collapsing run
        Column("lambda", "float"),  # the static onset [g]
        Column("scan_top_g", "float", "g"),
        Column("bands", "str"),  # the scan's outcome bands: S(urvives)/C(ollapses) from an amplitude [g]
        Column("n_sims", "int"), Column("wall_s", "float", "s"),
        Column("table_speed", "float", "m/s"), Column("tau", "float", "s"), Column("mu_base", "float"),
        Column("contact", "str"), Column("restitution", "float"),
    ))

    cells: tuple[dict, ...]
    title: str = ""

    def rows(self) -> list[dict]:
        return [dict(c) for c in self.cells]

    @classmethod
    def from_study(cls, study: StudyResult, cases: Sequence[dict], labels: Sequence[str] | None = None,
                   title: str = "") -> "ModeMapResult":
        """One typed row per case asked (``labels`` each, default "map"), from what ``study`` holds."""
        stored = study.by_key
        cells = []
        for lab, case in zip(labels or ["map"] * len(cases), cases):
            rec = stored.get(case_key(case))
            got = {"mode": "not run"} if rec is None else (rec.results if rec.ok else {"mode": "failed"})
            raw = {**case, **{k: got[k] for k in cls.SCHEMA.names if k in got}, "label": lab}
            cells.append({c.name: _typed(raw.get(c.name), c.kind) for c in cls.SCHEMA.columns})
        return cls(tuple(cells), title)

    def lines(self) -> list[str]:
        """One printed line a row."""
        out = []
        for r in self.cells:
            amp = r["mode"] if r["amplitude_g"] is None else f"{r['amplitude_g']:.3f} g"
            out.append(f"{r['label']:<40} {r['id']:<11} {r['freq']:>4g} Hz  {amp:>9} {r['mode']:<8} {r['phase']:<21} "
                       f"first slip {r['joint'] or '-'} {r['slip_half']}  (slid {r['slid'] or '-'}; "
                       f"scan to {r['scan_top_g'] or 0:.2f} g)")
        return out

    def findings(self) -> list[str]:
        """What the map says, in sentences computed from its rows."""
        n = len(self.cells)
        fell = [r for r in self.cells if r["amplitude_g"] is not None]
        count = {m: sum(r["mode"] == m for r in self.cells) for m in ("rocking", "mixed", "sliding", "none")}
        rest = n - sum(count.values())
        out = [f"{len(fell)} of {n} searches find a collapse: {count['rocking']} rocking, {count['mixed']} mixed, "
               f"{count['sliding']} sliding; {count['none']} stand up to the scan's top"
               + (f"; {rest} failed or not run." if rest else ".")]

        def cells(rows: list[dict]) -> str:
            return ", ".join(f"{r['id']} at {r['freq']:g} Hz" for r in rows) or "none"

        above = [r for r in fell if r["within_reach"] is False]
        out.append(f"Collapses only the saturated table gives (above its reach): {cells(above)}.")
        out.append(f"Collapses before the first rebound: {cells([r for r in fell if r['phase'] == 'before-first-rebound'])}; "
                   f"the first slip in the first half cycle: {cells([r for r in fell if r['slip_half'] == 'first'])}.")
        return out


def _typed(v: Any, kind: str) -> Any:
    """A stored value as its column's kind: a missing value (None, "", NaN) None, text "" when missing."""
    if kind == "str":
        return "" if v is None else str(v)
    if v is None or v == "" or (isinstance(v, float) and math.isnan(v)):
        return None
    return {"float": float, "int": int, "bool": bool}[kind](v)


def run(spec: ModeMapSpec, path: str | os.PathLike, workers: int | None = None, scheduler: str | None = None,
        resume: bool = False, progress: bool = True) -> ModeMapResult:
    """Run the map's searches into the study file ``path`` (one case each, on ``workers`` processes or a
    Dask ``scheduler``; ``resume`` runs only the cases it does not hold) and table them."""
    cases = spec.cases()
    study = run_study(cases, mode_case, path, workers=workers, scheduler=scheduler, resume=resume, progress=progress)
    return ModeMapResult.from_study(study, cases, title=spec.title())


def read(spec: ModeMapSpec, path: str | os.PathLike) -> ModeMapResult:
    """The map of what the study file ``path`` holds, without running (a case it lacks reads "not run")."""
    cases = spec.cases()
    return ModeMapResult.from_study(load_study(path, cases), cases, title=spec.title())
