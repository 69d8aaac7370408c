"""The assessment step: the Noh Gumbad vaults against their site, unreinforced and with FRP strips
(docs/physics/assessment.md#7-the-noh-gumbad-example)."""
from __future__ import annotations

from pathlib import Path

from analytic.codes.assessment import NOH_GUMBAD_FRP, assess_monument, monument_site
from analytic.codes.frp import Strips
from dem.common.campaign import CampaignContext, write_csv
from specimens.constants import G
from specimens.monuments import NOH_GUMBAD


def step_assess(ctx: CampaignContext, d: Path) -> dict:
    """The code's kinematic checks of the monument's three configurations, with and without strips."""
    site = monument_site()
    rows = assess_monument(NOH_GUMBAD, site, Strips(*NOH_GUMBAD_FRP))
    table = [{"configuration": r["configuration"], "frp": r["frp"], "lambda": r["lambda"], "e_star": r["e_star"],
              "M_star_kg": r["M_star"], "a0_star_g": r["a0_star"] / G, "d0_star_mm": r["d0_star"] * 1e3,
              "du_star_mm": r["du_star"] * 1e3, "safety_index_linear": r["safety_index_linear"],
              "safety_index_displacement": r["safety_index_displacement"], "verified": r["verified"],
              "hinges_rad": " ".join(f"{h['angle_rad']:.3f}" for h in r["hinges"])} for r in rows]
    write_csv(d / "assess.csv", table)
    findings = []
    for name in NOH_GUMBAD.configurations:
        bare, frp = (next(r for r in table if r["configuration"] == name and r["frp"] == f) for f in (False, True))
        findings.append(f"Noh Gumbad, {name}: lambda {bare['lambda']:.3f} -> {frp['lambda']:.3f} with FRP; governing "
                        f"safety index {min(bare['safety_index_linear'], bare['safety_index_displacement']):.2f} -> "
                        f"{min(frp['safety_index_linear'], frp['safety_index_displacement']):.2f} "
                        f"(site PGA {site.pga / G:.3f} g).")
    return {
        "summary": f"{NOH_GUMBAD.source}. Site: EN 1998-1 type 1, ground A, PGA {site.pga:.3g} m/s^2; linear (q = 2) and "
                   f"displacement (SLV) checks at FC 1.35; FRP strips {NOH_GUMBAD_FRP[0] / 1e6:g} MPa, "
                   f"{NOH_GUMBAD_FRP[1] * 1e3:g} mm, {NOH_GUMBAD_FRP[2] * 1e3:g} mm on the extrados.",
        "tables": [{"name": "assess", "title": "Noh Gumbad: code-based assessment", "csv": "assess/assess.csv"}],
        "findings": findings,
    }
