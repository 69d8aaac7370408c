"""What every campaign step gets (:class:`CampaignContext`) and the small file helpers they share."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from dem.common.joints import contact_fraction, joint_law, joint_law_text
from dem.common.tables import Schema
from dem.common.tables import write_csv as write_table
from dem.core.settings import DYNAMICS_ENGINE, Settings, dynamics_settings
from foundation.io import atomic_path, to_json


@dataclass
class CampaignContext:
    """What every step gets: output folder, options, and the log of finished steps."""

    out: Path
    specimens: list  # list[specimens.catalogue.Specimen]
    config: str = "glued"
    engine: str = "pybullet"  # the tilt, lab, map and piers steps
    dynamics_engine: str = DYNAMICS_ENGINE  # the shake, record and fragility steps (docs/decisions/011-dynamics-engine.md)
    quick: bool = True
    workers: int | None = None
    scheduler: str | None = None  # a Dask scheduler address: every sweep of the campaign runs there
    log: Callable[[str], None] = print
    results: dict = field(default_factory=dict)
    contact: float | str = 1.0  # contact fraction of every joint, or "calibrated" (dem.common.joints)
    joints: dict | str | None = None  # joint law: None rigid, "table-5.1" or compliant-law settings (dem.common.joints)

    def law_of(self, spec) -> dict:
        """The contact-law settings of ``spec``'s joints in every simulator step ({} = rigid)."""
        return joint_law(self.joints, spec.id)

    def dynamics_of(self, spec) -> Settings:
        """The settings of ``spec``'s shakes in the dynamic steps: their engine and its step, its joints."""
        return dynamics_settings(engine=self.dynamics_engine, **self.law_of(spec))

    def joints_text(self) -> str:
        """The joints of the simulator steps, in words for their summaries."""
        return joint_law_text(self.joints)

    def contact_of(self, spec) -> float:
        """The contact fraction of ``spec``'s joints in this campaign."""
        return contact_fraction(self.contact, spec.arch)


def write_csv(path: Path, rows: list[dict], schema: Schema | None = None) -> None:
    """A step's table, with its schema (given, or inferred from the values) beside it: the report and
    ``campaign.h5`` read it back typed (:mod:`dem.common.tables`)."""
    write_table(path, rows, schema)


def pct(a: float, b: float) -> float:
    return 100.0 * (a - b) / b


def write_json_atomic(path: Path, obj: dict) -> None:
    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(to_json(obj, indent=2))


def studies_dir(ctx: CampaignContext) -> Path:
    p = ctx.out / "studies"
    p.mkdir(exist_ok=True)
    return p
