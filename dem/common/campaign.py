"""What every campaign step gets (:class:`CampaignContext`) and the small file helpers they share."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable


@dataclass
class CampaignContext:
    """What every step gets: output folder, options, and the log of finished steps."""

    out: Path
    specimens: list  # list[specimens.catalogue.Specimen]
    config: str = "glued"
    engine: str = "pybullet"
    quick: bool = True
    workers: int | None = None
    scheduler: str | None = None  # a Dask scheduler address: every sweep of the campaign runs there
    log: Callable[[str], None] = print
    results: dict = field(default_factory=dict)
    contact: float | str = 1.0  # effective contact of every joint, or "calibrated" (per specimen)
    joints: dict | str | None = None  # None: rigid; "table-5.1": the study's per specimen; or compliant-law settings

    def law_of(self, spec) -> dict:
        """The contact-law settings of ``spec``'s joints in every simulator step ({} = rigid)."""
        if not self.joints:
            return {}
        if self.joints == "table-5.1":
            from dem.core.contact import study_joints

            return study_joints(spec.id)
        return dict(self.joints)

    def joints_text(self) -> str:
        """The joints of the simulator steps, in words for their summaries."""
        if not self.joints:
            return "Rigid joints."
        if self.joints == "table-5.1":
            return "Compliant joints: each specimen's k_n and beta_R of the study's Table 5.1."
        j = self.joints
        damping = (f"beta_R {j['damping_beta']:g} s" if j.get("damping_beta") else
                   f"xi {j['damping_xi']:g} at omega_r" if j.get("damping_xi") else "no damping")
        stiffness = f"k_n {j['kn']:.3g} Pa/m" if j.get("kn") else f"k_n = E / block length, E {j['youngs']:.3g} Pa"
        return f"Compliant joints: {stiffness}, {damping}."

    def contact_of(self, spec) -> float:
        """The effective contact of ``spec``'s joints in this campaign."""
        if self.contact == "calibrated":
            from analytic.calibration import load_calibration

            return load_calibration().contact(spec.arch)
        from specimens.blocks import check_contact

        return check_contact(self.contact)


def write_csv(path: Path, rows: list[dict]) -> None:
    import csv

    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def pct(a: float, b: float) -> float:
    return 100.0 * (a - b) / b


def write_json_atomic(path: Path, obj: dict) -> None:
    from specimens.io import atomic_path, to_json

    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(to_json(obj, indent=2))


def studies_dir(ctx: CampaignContext) -> Path:
    p = ctx.out / "studies"
    p.mkdir(exist_ok=True)
    return p
